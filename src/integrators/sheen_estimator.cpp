#include "lutbake/integrators/sheen_estimator.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lutbake {

std::string_view ToString(SheenStrategy strategy) {
  switch (strategy) {
    case SheenStrategy::kCharlieLobe: return "charlie-lobe";
    case SheenStrategy::kUniform: return "uniform";
  }
  return "?";
}

SheenAlbedoEstimator::SheenAlbedoEstimator(SheenVisibility visibility, double alpha,
                                           SheenStrategy strategy, double mu_o)
    : visibility_(visibility), alpha_(alpha), strategy_(strategy), mu_o_(mu_o) {
  if (!(alpha > 0.0 && alpha <= 1.0))
    throw std::invalid_argument("sheen estimator: alpha must lie in (0, 1]");
  if (!(mu_o >= 0.0 && mu_o <= 1.0))
    throw std::invalid_argument("sheen estimator: mu_o must lie in [0, 1]");
  if (UsesCharlieLambda(visibility) && mu_o == 0.0)
    throw std::domain_error(
        "sheen estimator: E is infinite at mu_o = 0 with the Charlie visibility");
  s_o_ = SafeSqrt((1.0 - mu_o) * (1.0 + mu_o));
  if (UsesCharlieLambda(visibility)) onePlusLambda_o_ = 1.0 + CharlieLambda(mu_o, alpha);
}

double SheenAlbedoEstimator::FourW(double mu_i) const {
  if (UsesCharlieLambda(visibility_))
    return 1.0 / (mu_o_ * (onePlusLambda_o_ + SheenLightLambda(visibility_, mu_i, alpha_)));
  const double denom = mu_i + mu_o_ * (1.0 - mu_i);
  return denom > 0.0 ? mu_i / denom : 0.0;
}

double SheenAlbedoEstimator::Weight(double u0, double u1) const {
  if (strategy_ == SheenStrategy::kCharlieLobe) {
    const Vec3 h = SampleCharlieHalfVector(alpha_, u0, u1);
    const double oh = s_o_ * h.x + mu_o_ * h.z;
    // h.z = 0 only at u0 = 1 exactly, outside [0, 1).
    if (!(oh > 0.0) || !(h.z > 0.0)) return 0.0;
    const double mu_i = 2.0 * oh * h.z - mu_o_;
    if (!(mu_i > 0.0)) return 0.0;
    return oh / h.z * FourW(std::min(mu_i, 1.0));
  }
  const double mu_i = u0;
  if (!(mu_i > 0.0)) return 0.0;
  const double d = CharlieDFromDirections(alpha_, mu_o_, mu_i, std::cos(kPi * u1));
  return 0.5 * kPi * d * FourW(mu_i);  // 2 pi D W = (pi / 2) D (4 W)
}

double SheenAlbedoEstimator::MaxWeight() const {
  const bool lobe = strategy_ == SheenStrategy::kCharlieLobe;
  if (lobe && mu_o_ == 0.0) return std::numeric_limits<double>::infinity();
  const double K = CharlieNormalization(alpha_);
  const auto s = [](double mu) { return SafeSqrt((1.0 - mu) * (1.0 + mu)); };
  // D / K at phi = 0 for the light at mu: its largest value at that mu_i.
  const auto dhatMax = [&](double mu) {
    const double sum = s_o_ + s(mu), m = mu_o_ + mu;
    if (!(sum > 0.0)) return m > 0.0 ? 0.0 : 1.0;
    return std::exp(-0.5 / alpha_ * std::log1p(m * m / (sum * sum)));
  };
  const auto cell = [&](double a, double b) {
    if (lobe) return (1.0 + mu_o_ * b + s_o_ * s(a)) / (mu_o_ + a) * FourW(b);
    return 0.5 * kPi * K * dhatMax(a) * FourW(b);
  };
  constexpr int kUniform = 64, kGeometric = 60;
  double worst = 0.0;
  for (int k = 1; k < kUniform; ++k)
    worst = std::max(worst, cell(static_cast<double>(k) / kUniform,
                                 k + 1 == kUniform ? 1.0 : static_cast<double>(k + 1) / kUniform));
  double b = 1.0 / kUniform;
  for (int k = 0; k < kGeometric; ++k) {
    worst = std::max(worst, cell(0.5 * b, b));
    b *= 0.5;
  }
  worst = std::max(worst, cell(0.0, b));
  return worst * (1.0 + 1e-12);
}

double SheenMaxWeight(SheenVisibility visibility, double alpha, SheenStrategy strategy,
                      double mu_o) {
  return SheenAlbedoEstimator(visibility, alpha, strategy, mu_o).MaxWeight();
}

}  // namespace lutbake
