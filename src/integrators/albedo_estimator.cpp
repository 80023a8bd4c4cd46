#include "lutbake/integrators/albedo_estimator.h"

namespace lutbake {

std::string_view ToString(SampleStrategy strategy) {
  switch (strategy) {
    case SampleStrategy::kVisibleNormal: return "vndf";
    case SampleStrategy::kNdf: return "ndf";
    case SampleStrategy::kCosine: return "cosine";
    case SampleStrategy::kUniform: return "uniform";
  }
  return "?";
}

namespace {

// The light-sampling baselines: i from (u1, u2), then h = normalize(o + i).
AlbedoSample SampleLight(const AlbedoEstimator &e, const Vec3 &o, double L_o, double u1,
                         double u2) {
  const bool cosine = e.strategy == SampleStrategy::kCosine;
  // Uniform: mu_i = u1. Cosine: mu_i = sqrt(u1) (density 2 mu_i in mu_i).
  const double mu_i = cosine ? std::sqrt(u1) : u1;
  const double sinTheta = SafeSqrt((1.0 - mu_i) * (1.0 + mu_i));
  const double phi = 2.0 * kPi * u2;
  const Vec3 i{sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu_i};
  const Vec3 sum{o.x + i.x, o.y + i.y, o.z + i.z};
  // o + i = 0 only for i = -o, which is below the horizon unless both lie
  // on it; that single direction has measure zero.
  const double length2 = Dot(sum, sum);
  if (!(length2 > 0.0) || mu_i <= 0.0) return {};
  const Vec3 h = Normalize(sum);
  const double oh = Dot(o, h);
  const double g2OverMuO = SmithG2OverMuO(e.smith, o.z, mu_i, L_o, e.ndf.MuLambda(mu_i));
  const double d = e.ndf.D(h);
  const double w = cosine ? 0.25 * kPi * d * g2OverMuO / mu_i : 0.5 * kPi * d * g2OverMuO;
  const SchlickWeights fc = Schlick(oh);
  return {w, fc.fc, fc.complement, oh};
}

}  // namespace

AlbedoSample AlbedoEstimator::Sample(const Vec3 &o, double L_o, double u1, double u2) const {
  const double mu_o = o.z;
  if (strategy == SampleStrategy::kVisibleNormal) {
    const Vec3 h = ndf.SampleVisibleNormal(o, u1, u2);
    const double oh = Dot(o, h);
    const double mu_i = 2.0 * oh * h.z - mu_o;
    if (mu_i <= 0.0 || oh <= 0.0) return {};
    const double w = SmithG2OverG1o(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i));
    const SchlickWeights fc = Schlick(oh);
    return {w, fc.fc, fc.complement, oh};
  }
  if (strategy == SampleStrategy::kCosine || strategy == SampleStrategy::kUniform)
    return SampleLight(*this, o, L_o, u1, u2);
  const Vec3 h = ndf.SampleNormal(u1, u2);
  const double oh = Dot(o, h);
  // h.z = 0 only at the measure-zero end of the NDF sampler's range.
  if (oh <= 0.0 || h.z <= 0.0) return {};
  const double mu_i = 2.0 * oh * h.z - mu_o;
  if (mu_i <= 0.0) return {};
  const double w = SmithG2OverMuO(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i)) * oh / h.z;
  const SchlickWeights fc = Schlick(oh);
  return {w, fc.fc, fc.complement, oh};
}

}  // namespace lutbake
