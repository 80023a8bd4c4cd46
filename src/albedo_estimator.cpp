#include "lutbake/albedo_estimator.h"

namespace lutbake {

std::string_view ToString(SampleStrategy strategy) {
  return strategy == SampleStrategy::kVisibleNormal ? "vndf" : "ndf";
}

AlbedoSample AlbedoEstimator::Sample(const Vec3 &o, double L_o, double u1, double u2) const {
  const double mu_o = o.z;
  if (strategy == SampleStrategy::kVisibleNormal) {
    const Vec3 h = ndf.SampleVisibleNormal(o, u1, u2);
    const double oh = Dot(o, h);
    const double mu_i = 2.0 * oh * h.z - mu_o;
    if (mu_i <= 0.0 || oh <= 0.0) return {};
    const double w = SmithG2OverG1o(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i));
    return {w, Pow5(1.0 - oh)};
  }
  const Vec3 h = ndf.SampleNormal(u1, u2);
  const double oh = Dot(o, h);
  // h.z = 0 only at the measure-zero end of the NDF sampler's range.
  if (oh <= 0.0 || h.z <= 0.0) return {};
  const double mu_i = 2.0 * oh * h.z - mu_o;
  if (mu_i <= 0.0) return {};
  const double w = SmithG2OverMuO(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i)) * oh / h.z;
  return {w, Pow5(1.0 - oh)};
}

}  // namespace lutbake
