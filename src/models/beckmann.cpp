#include "lutbake/models/beckmann.h"

#include <limits>

namespace lutbake::beckmann {

double D(double alpha, const Vec3 &h) {
  if (h.z <= 0.0) return 0.0;
  const double cos2 = h.z * h.z;
  const double tan2 = (h.x * h.x + h.y * h.y) / cos2;
  // exp() underflows to 0 far from the peak when alpha is tiny: that is the
  // correct value there, not an error.
  return std::exp(-tan2 / (alpha * alpha)) / (kPi * alpha * alpha * cos2 * cos2);
}

double MuLambda(double alpha, double mu) {
  const double s = SafeSqrt((1.0 - mu) * (1.0 + mu));
  if (s == 0.0) return 0.0;  // mu = 1: Lambda = 0.
  const double alphaS = alpha * s;
  if (alphaS == 0.0) return 0.0;  // alpha = 0: a mirror has no shadowing.
  const double a = mu / alphaS;
  return 0.5 * (alphaS * std::exp(-a * a) / kSqrtPi - mu * std::erfc(a));
}

double SampleVisibleSlope(double cosTheta, double sinTheta, double u) {
  // Slopes beyond |x| = 8 carry a probability below erfc(8) ~ 1e-29: the
  // bracket [-8, min(8, cot theta)] loses nothing at double precision.
  constexpr double kSlopeLimit = 8.0;
  double lo = -kSlopeLimit;
  double hi = sinTheta > 0.0 ? std::min(kSlopeLimit, cosTheta / sinTheta) : kSlopeLimit;
  const auto cdf = [&](double x) {
    return cosTheta * 0.5 * kSqrtPi * std::erfc(-x) + 0.5 * sinTheta * std::exp(-x * x);
  };
  const double target = u * cdf(hi);
  double x = std::clamp(0.0, lo, hi);
  for (int iter = 0; iter < 100; ++iter) {
    const double f = cdf(x) - target;
    if (f < 0.0)
      lo = x;
    else
      hi = x;
    const double slope = std::exp(-x * x) * (cosTheta - x * sinTheta);
    double next = slope > 0.0 ? x - f / slope : 0.5 * (lo + hi);
    // Newton may leave the bracket where the density is flat; bisect there.
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-14 * (1.0 + std::abs(x))) return next;
    x = next;
  }
  return x;
}

Vec3 SampleVisibleNormal(double alpha, const Vec3 &o, double u1, double u2) {
  const Vec3 os = Normalize({alpha * o.x, alpha * o.y, o.z});
  const double sinTheta = std::sqrt(os.x * os.x + os.y * os.y);
  const double cosTheta = os.z;
  const double slopeX = SampleVisibleSlope(cosTheta, sinTheta, u1);
  const double slopeY = SampleVisibleSlope(1.0, 0.0, u2);
  // Rotate the slopes from the view's azimuth back to the frame.
  const double cosPhi = sinTheta > 0.0 ? os.x / sinTheta : 1.0;
  const double sinPhi = sinTheta > 0.0 ? os.y / sinTheta : 0.0;
  const double sx = cosPhi * slopeX - sinPhi * slopeY;
  const double sy = sinPhi * slopeX + cosPhi * slopeY;
  return Normalize({-alpha * sx, -alpha * sy, 1.0});
}

void NormalFromCdf(double alpha, double xi, double *cosTheta_h, double *sinTheta_h) {
  const double tan2 = -alpha * alpha * std::log1p(-xi);
  if (!(tan2 < std::numeric_limits<double>::infinity())) {
    *cosTheta_h = 0.0;
    *sinTheta_h = 1.0;
    return;
  }
  const double inv = 1.0 / std::sqrt(1.0 + tan2);
  *cosTheta_h = inv;
  *sinTheta_h = std::sqrt(tan2) * inv;
}

double CdfFromTheta(double alpha, double theta_h) {
  const double t = std::tan(theta_h);
  return -std::expm1(-t * t / (alpha * alpha));
}

}  // namespace lutbake::beckmann
