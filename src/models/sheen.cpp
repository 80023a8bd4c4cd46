#include "lutbake/models/sheen.h"

#include <cmath>

namespace lutbake {

std::string_view ToString(SheenVisibility visibility) {
  switch (visibility) {
    case SheenVisibility::kCharlie: return "charlie";
    case SheenVisibility::kAshikhmin: return "ashikhmin";
    case SheenVisibility::kOspray: return "ospray";
  }
  return "?";
}

bool ParseSheenVisibility(std::string_view text, SheenVisibility *visibility) {
  for (SheenVisibility v :
       {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin, SheenVisibility::kOspray})
    if (text == ToString(v)) {
      *visibility = v;
      return true;
    }
  return false;
}

double CharlieNormalization(double alpha) { return (2.0 + 1.0 / alpha) / (2.0 * kPi); }

double CharlieD(double alpha, double sin2Theta_h) {
  if (!(sin2Theta_h > 0.0)) return 0.0;
  return CharlieNormalization(alpha) * std::exp(0.5 / alpha * std::log(std::min(sin2Theta_h, 1.0)));
}

double CharlieDFromCos(double alpha, double cosTheta_h) {
  const double c = Clamp(cosTheta_h, 0.0, 1.0);
  // log(sin^2): log1p(-c^2) is exact to rounding where sin^2 is near 1; near
  // the normal, where sin^2 is small, (1 - c)(1 + c) is.
  const double sin2 = (1.0 - c) * (1.0 + c);
  if (!(sin2 > 0.0)) return 0.0;
  const double logSin2 = sin2 > 0.5 ? std::log1p(-c * c) : std::log(sin2);
  return CharlieNormalization(alpha) * std::exp(0.5 / alpha * logSin2);
}

double CharlieDFromDirections(double alpha, double mu_o, double mu_i, double cosHalfPhi) {
  const double s_o = SafeSqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double s_i = SafeSqrt((1.0 - mu_i) * (1.0 + mu_i));
  // s_o - s_i = (mu_i - mu_o)(mu_i + mu_o) / (s_o + s_i): no cancellation
  // when both are near 1 (grazing view and light).
  const double ds = s_o + s_i > 0.0 ? (mu_i - mu_o) * (mu_i + mu_o) / (s_o + s_i) : 0.0;
  const double T = ds * ds + 4.0 * s_o * s_i * cosHalfPhi * cosHalfPhi;
  const double m = mu_o + mu_i;
  if (!(T > 0.0)) return 0.0;  // h = n: sin(theta_h) = 0
  return CharlieNormalization(alpha) * std::exp(-0.5 / alpha * std::log1p(m * m / T));
}

namespace {

double Mix(double p, double q, double w) { return p * (1.0 - w) + q * w; }

// The glTF README's l(x, alpha).
struct LambdaFit {
  double a, b, c, d, e;
  explicit LambdaFit(double alpha) {
    const double w = (1.0 - alpha) * (1.0 - alpha);
    a = Mix(21.5473, 25.3245, w);
    b = Mix(3.82987, 3.32435, w);
    c = Mix(0.19823, 0.16801, w);
    d = Mix(-1.97760, -1.27393, w);
    e = Mix(-4.32054, -4.85967, w);
  }
  double L(double x) const { return a / (1.0 + b * std::pow(x, c)) + d * x + e; }
  // log Lambda at x = mu in [0, 1]: l(x) below 1/2, 2 l(1/2) - l(1 - x) above.
  double LogLambda(double x) const { return x < 0.5 ? L(x) : 2.0 * L(0.5) - L(1.0 - x); }
};

}  // namespace

double CharlieLambda(double mu, double alpha) {
  return std::exp(LambdaFit(alpha).LogLambda(Clamp(mu, 0.0, 1.0)));
}

double CharlieLambdaExponent(double alpha) { return LambdaFit(alpha).c; }

bool UsesCharlieLambda(SheenVisibility visibility) {
  return visibility == SheenVisibility::kCharlie || visibility == SheenVisibility::kOspray;
}

double SheenLightLambda(SheenVisibility visibility, double mu_i, double alpha) {
  if (visibility != SheenVisibility::kOspray) return CharlieLambda(mu_i, alpha);
  const double x = Clamp(mu_i, 0.0, 1.0);
  const double t = Sqr(Sqr(Sqr(1.0 - x)));  // (1 - mu_i)^8
  return std::exp((1.0 + 2.0 * t) * LambdaFit(alpha).LogLambda(x));
}

double SheenCosineVisibility(SheenVisibility visibility, double alpha, double mu_o, double mu_i) {
  if (UsesCharlieLambda(visibility))
    return 1.0 / (4.0 * mu_o *
                  (1.0 + CharlieLambda(mu_o, alpha) + SheenLightLambda(visibility, mu_i, alpha)));
  const double denom = mu_i + mu_o * (1.0 - mu_i);
  return denom > 0.0 ? mu_i / (4.0 * denom) : 0.0;
}

Vec3 SampleCharlieHalfVector(double alpha, double u0, double u1) {
  const double e = alpha / (2.0 * alpha + 1.0);
  const double logXi = std::log(u0);  // -inf at u0 = 0: theta_h = 0
  const double sinTheta = std::exp(e * logXi);
  const double cosTheta = std::sqrt(std::max(0.0, -std::expm1(2.0 * e * logXi)));
  const double phi = 2.0 * kPi * u1;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

double CharlieHalfVectorPdf(double alpha, double cosTheta_h) {
  if (!(cosTheta_h > 0.0)) return 0.0;
  return CharlieDFromCos(alpha, cosTheta_h) * std::min(cosTheta_h, 1.0);
}

std::array<double, 2> InvertCharlieHalfVectorSample(double alpha, const Vec3 &h) {
  // u0 = x^(q + 2) = exp((q + 2) / 2 log(sin^2)), the logarithm taken as in
  // CharlieDFromCos from cos(theta_h) = h.z.
  const double c = Clamp(h.z, 0.0, 1.0);
  const double sin2 = (1.0 - c) * (1.0 + c);
  double u0 = 0.0;
  if (sin2 > 0.0) {
    const double logSin2 = sin2 > 0.5 ? std::log1p(-c * c) : std::log(sin2);
    u0 = std::exp(0.5 * (2.0 + 1.0 / alpha) * logSin2);
  }
  double u1 = std::atan2(h.y, h.x) / (2.0 * kPi);
  if (u1 < 0.0) u1 += 1.0;
  if (u1 >= 1.0) u1 = 0.0;
  return {u0, u1};
}

}  // namespace lutbake
