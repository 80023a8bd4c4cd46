#include "lutbake/models/phong.h"

#include <cmath>

namespace lutbake {

std::string_view ToString(PhongNormalisation normalisation) {
  switch (normalisation) {
    case PhongNormalisation::kNone: return "none";
    case PhongNormalisation::kNPlus1: return "n+1";
    case PhongNormalisation::kNPlus2: return "n+2";
  }
  return "none";
}

double PhongNormalisationFactor(PhongNormalisation normalisation, double exponent) {
  switch (normalisation) {
    case PhongNormalisation::kNone: return 1.0;
    case PhongNormalisation::kNPlus1: return (exponent + 1.0) / (2.0 * kPi);
    case PhongNormalisation::kNPlus2: return (exponent + 2.0) / (2.0 * kPi);
  }
  return 1.0;
}

double PhongBrdf(PhongNormalisation normalisation, double exponent, const Vec3 &o, const Vec3 &i) {
  if (i.z <= 0.0 || o.z < 0.0) return 0.0;
  const Vec3 mirror{-o.x, -o.y, o.z};  // 2 (n.o) n - o
  const double cosLobe = Dot(mirror, i);
  if (cosLobe <= 0.0) return 0.0;
  return PhongNormalisationFactor(normalisation, exponent) * std::pow(cosLobe, exponent);
}

double PhongConeIntegral(double mu_o, double u) {
  const double s_o = SafeSqrt(1.0 - mu_o * mu_o);
  const double A = mu_o * u, B = s_o * SafeSqrt(1.0 - u * u);
  if (B <= A) return 2.0 * kPi * A;
  const double bMax = std::acos(Clamp(-A / B, -1.0, 1.0));
  return 2.0 * (A * bMax + B * std::sin(bMax));
}

}  // namespace lutbake
