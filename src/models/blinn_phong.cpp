#include "lutbake/models/blinn_phong.h"

#include <cmath>

namespace lutbake {

std::string_view ToString(BlinnPhongNormalisation normalisation) {
  switch (normalisation) {
    case BlinnPhongNormalisation::kNone: return "none";
    case BlinnPhongNormalisation::kNPlus2: return "n+2";
    case BlinnPhongNormalisation::kNPlus8: return "n+8";
    case BlinnPhongNormalisation::kExact: return "exact";
  }
  return "none";
}

double BlinnPhongNormalisationFactor(BlinnPhongNormalisation normalisation, double exponent) {
  const double n = exponent;
  switch (normalisation) {
    case BlinnPhongNormalisation::kNone: return 1.0;
    case BlinnPhongNormalisation::kNPlus2: return (n + 2.0) / (2.0 * kPi);
    case BlinnPhongNormalisation::kNPlus8: return (n + 8.0) / (8.0 * kPi);
    case BlinnPhongNormalisation::kExact:
      // 2^(-n/2) underflows to 0 for huge n, harmlessly: n dominates then.
      return (n + 2.0) * (n + 4.0) / (8.0 * kPi * (n + std::exp2(-0.5 * n)));
  }
  return 1.0;
}

double BlinnPhongBrdf(BlinnPhongNormalisation normalisation, double exponent, const Vec3 &o,
                      const Vec3 &i) {
  if (i.z <= 0.0 || o.z < 0.0) return 0.0;
  const Vec3 h = Normalize({o.x + i.x, o.y + i.y, o.z + i.z});
  return BlinnPhongNormalisationFactor(normalisation, exponent) * std::pow(h.z, exponent);
}

double BlinnPhongRingIntegral(double mu_o, double u) {
  const double s_o = SafeSqrt(1.0 - mu_o * mu_o);
  const double A = mu_o * u, B = s_o * SafeSqrt(1.0 - u * u);
  // mu_i > 0 <=> 2 u (A + B cos p) > mu_o; compared without dividing by B.
  double q;
  if (mu_o <= 2.0 * u * (A - B))
    q = kPi;
  else if (mu_o >= 2.0 * u * (A + B))
    q = 0.0;
  else
    q = std::acos(Clamp((mu_o - 2.0 * u * A) / (2.0 * u * B), -1.0, 1.0));
  if (q == 0.0) return 0.0;
  const double sinQ = std::sin(q), sin2Q = std::sin(2.0 * q);
  const double cos2Integral = 0.5 * q + 0.25 * sin2Q;  // int_0^q cos^2
  return 8.0 * (2.0 * u * (A * A * q + 2.0 * A * B * sinQ + B * B * cos2Integral) -
                mu_o * (A * q + B * sinQ));
}

BlinnPhongBreaks BlinnPhongHorizonBreaks(double mu_o) {
  const double s_o = SafeSqrt(1.0 - mu_o * mu_o);
  // 1 - s_o = mu_o^2 / (1 + s_o), without cancellation at grazing view.
  const double oneMinusS = mu_o * mu_o / (1.0 + s_o);
  return {mu_o / std::sqrt(Sqr(1.0 + s_o) + mu_o * mu_o),
          mu_o > 0.0 ? mu_o / std::sqrt(oneMinusS * oneMinusS + mu_o * mu_o) : 1.0};
}

}  // namespace lutbake
