#include "lutbake/models/oren_nayar.h"

#include <cmath>

namespace lutbake {

namespace {

struct Angles {
  double a, b;
};
Angles MaxMin(double theta_o, double theta_i) {
  return {std::max(theta_o, theta_i), std::min(theta_o, theta_i)};
}

// cos(theta_i) tan(b): tan(b) cos(b) = sin(b) when b = theta_i, else
// tan(theta_o) cos(theta_i) with theta_o < theta_i.
double CosTanB(double theta_o, double theta_i) {
  if (theta_i <= theta_o) return std::sin(theta_i);
  return std::sin(theta_o) * std::cos(theta_i) / std::cos(theta_o);
}

// cos(theta_i) tan((a + b) / 2) = cos(theta_i) (sin a + sin b) / (cos a + cos b);
// cos(theta_i) is cos a or cos b, so the ratio is at most (sin a + sin b).
double CosTanHalfSum(double theta_o, double theta_i) {
  return std::cos(theta_i) * (std::sin(theta_o) + std::sin(theta_i)) /
         (std::cos(theta_o) + std::cos(theta_i));
}

}  // namespace

std::string_view ToString(OrenNayarVariant variant) {
  return variant == OrenNayarVariant::kFull ? "full" : "qualitative";
}

double OrenNayarBrdf(OrenNayarVariant variant, double sigma, const Vec3 &o, const Vec3 &i) {
  if (i.z <= 0.0 || o.z < 0.0) return 0.0;
  const double theta_o = std::acos(Clamp(o.z, -1.0, 1.0));
  const double theta_i = std::acos(Clamp(i.z, -1.0, 1.0));
  const double s_o = std::hypot(o.x, o.y), s_i = std::hypot(i.x, i.y);
  // cos(dphi) of the two projections; undefined (and irrelevant: tan(b) = 0)
  // when either is along the normal.
  const double cosPhi = s_o > 0.0 && s_i > 0.0 ? (o.x * i.x + o.y * i.y) / (s_o * s_i) : 0.0;
  const auto [a, b] = MaxMin(theta_o, theta_i);
  const double s2 = sigma * sigma;
  if (variant == OrenNayarVariant::kQualitative) {
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
    return kInvPi * (A + B * std::max(0.0, cosPhi) * std::sin(a) * std::tan(b));
  }
  const double C1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
  const double K2 = 0.45 * s2 / (s2 + 0.09);
  const double C2 =
      cosPhi >= 0.0 ? K2 * std::sin(a) : K2 * (std::sin(a) - std::pow(2.0 * b / kPi, 3));
  const double C3 = 0.125 * s2 / (s2 + 0.09) * Sqr(4.0 * a * b / (kPi * kPi));
  const double direct =
      C1 + cosPhi * C2 * std::tan(b) + (1.0 - std::abs(cosPhi)) * C3 * std::tan(0.5 * (a + b));
  const double interreflection = 0.17 * s2 / (s2 + 0.13) * (1.0 - cosPhi * Sqr(2.0 * b / kPi));
  return kInvPi * (direct + interreflection);
}

double OrenNayarCosineRing(OrenNayarVariant variant, double sigma, double theta_o, double theta_i) {
  const auto [a, b] = MaxMin(theta_o, theta_i);
  const double s2 = sigma * sigma, cosI = std::cos(theta_i);
  if (variant == OrenNayarVariant::kQualitative) {
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
    return 2.0 * (A * cosI + B * std::sin(a) * CosTanB(theta_o, theta_i) * kInvPi);
  }
  const double C1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
  const double K2 = 0.45 * s2 / (s2 + 0.09);
  const double C3 = 0.125 * s2 / (s2 + 0.09) * Sqr(4.0 * a * b / (kPi * kPi));
  const double direct = C1 * cosI +
                        K2 * std::pow(2.0 * b / kPi, 3) * CosTanB(theta_o, theta_i) * kInvPi +
                        (1.0 - 2.0 * kInvPi) * C3 * CosTanHalfSum(theta_o, theta_i);
  return 2.0 * direct + 0.34 * s2 / (s2 + 0.13) * cosI;
}

}  // namespace lutbake
