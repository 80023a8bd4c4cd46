#include "lutbake/models/ggx.h"

namespace lutbake::ggx {

double D(double alpha, const Vec3 &h) {
  if (h.z <= 0.0) return 0.0;
  const double alpha2 = alpha * alpha;
  const double sin2 = h.x * h.x + h.y * h.y;
  const double denom = alpha2 * h.z * h.z + sin2;
  return alpha2 / (kPi * denom * denom);
}

double MuLambda(double alpha, double mu) {
  const double sin2 = std::max(0.0, (1.0 - mu) * (1.0 + mu));
  const double a2s2 = alpha * alpha * sin2;
  const double root = std::sqrt(mu * mu + a2s2);
  // root + mu = 0 only when alpha = 0 and mu = 0: a mirror seen exactly at
  // grazing, where Lambda has no limit; callers never sample alpha = 0.
  return root + mu > 0.0 ? a2s2 / (2.0 * (root + mu)) : 0.0;
}

Vec3 SampleVisibleNormal(double alpha, const Vec3 &o, double u1, double u2) {
  const Vec3 os = Normalize({alpha * o.x, alpha * o.y, o.z});
  const double phi = 2.0 * kPi * u1;
  const double z = (1.0 - u2) * (1.0 + os.z) - os.z;
  const double sinTheta = SafeSqrt((1.0 - z) * (1.0 + z));
  const Vec3 hs = {sinTheta * std::cos(phi) + os.x, sinTheta * std::sin(phi) + os.y, z + os.z};
  const Vec3 h = {alpha * hs.x, alpha * hs.y, std::max(0.0, hs.z)};
  const double len2 = Dot(h, h);
  // len2 = 0 only when c = -o_s exactly, a set of measure zero; return the
  // normal rather than NaN.
  if (!(len2 > 0.0)) return {0.0, 0.0, 1.0};
  const double inv = 1.0 / std::sqrt(len2);
  return {h.x * inv, h.y * inv, h.z * inv};
}

void NormalFromCdf(double alpha, double xi, double *cosTheta_h, double *sinTheta_h) {
  // cos^2 = (1 - xi) / ((1 - xi) + alpha^2 xi), sin^2 = alpha^2 xi / (same).
  const double oneMinusXi = 1.0 - xi;
  const double denom = oneMinusXi + alpha * alpha * xi;
  if (!(denom > 0.0)) {
    *cosTheta_h = 1.0;
    *sinTheta_h = 0.0;
    return;
  }
  *cosTheta_h = std::sqrt(oneMinusXi / denom);
  *sinTheta_h = alpha * std::sqrt(xi / denom);
}

double CdfFromTheta(double alpha, double theta_h) {
  const double s = std::sin(theta_h), c = std::cos(theta_h);
  const double denom = alpha * alpha * c * c + s * s;
  return denom > 0.0 ? s * s / denom : 0.0;
}

}  // namespace lutbake::ggx
