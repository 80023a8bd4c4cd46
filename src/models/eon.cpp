#include "lutbake/models/eon.h"

#include <cmath>

namespace lutbake {

namespace {

constexpr double kC1 = 0.5 - 2.0 / (3.0 * kPi);
constexpr double kC2 = 2.0 / 3.0 - 28.0 / (15.0 * kPi);
// The clamps of the reference implementation: they keep f_ms finite as
// 1 - E_F,avg -> 0 (r -> 0).
constexpr double kEps = 1e-7;

double AF(double r) { return 1.0 / (1.0 + kC1 * r); }

double MultipleScatteringFactor(EonVariant variant, double r, double mu) {
  const double E = variant == EonVariant::kApprox ? FonAlbedoApprox(r, mu) : FonAlbedo(r, mu);
  return std::max(kEps, 1.0 - E);
}

}  // namespace

std::string_view ToString(EonVariant variant) {
  switch (variant) {
    case EonVariant::kExact: return "exact";
    case EonVariant::kApprox: return "approx";
    case EonVariant::kFon: return "fon";
  }
  return "exact";
}

double FonAlbedo(double r, double mu) {
  mu = Clamp(mu, 0.0, 1.0);
  const double S = SafeSqrt(1.0 - mu * mu);
  const double G =
      S * (std::acos(mu) - S * mu) + (2.0 / 3.0) * (S * mu * (1.0 + S + S * S) / (1.0 + S) - S);
  return AF(r) * (1.0 + r * G * kInvPi);
}

double FonAlbedoApprox(double r, double mu) {
  const double m = 1.0 - mu;
  const double g1 = 0.0571085289, g2 = 0.491881867, g3 = -0.332181442, g4 = 0.0714429953;
  const double GoverPi = m * (g1 + m * (g2 + m * (g3 + m * g4)));
  return (1.0 + r * GoverPi) * AF(r);
}

double FonAverageAlbedo(double r) { return AF(r) * (1.0 + kC2 * r); }

double EonBrdf(EonVariant variant, double r, const Vec3 &o, const Vec3 &i) {
  if (i.z <= 0.0 || o.z < 0.0) return 0.0;
  const double s = Dot(o, i) - i.z * o.z;
  const double sOverT = s > 0.0 ? s / std::max(i.z, o.z) : s;
  const double single = kInvPi * AF(r) * (1.0 + r * sOverT);
  if (variant == EonVariant::kFon) return single;
  const double multiple = kInvPi * MultipleScatteringFactor(variant, r, o.z) *
                          MultipleScatteringFactor(variant, r, i.z) /
                          std::max(kEps, 1.0 - FonAverageAlbedo(r));
  return single + multiple;
}

double EonCosineRing(EonVariant variant, double r, double theta_o, double theta_i) {
  const double mu_o = std::cos(theta_o), mu_i = std::cos(theta_i);
  const double S = std::sin(theta_i) * std::sin(theta_o);
  const double t = std::max(mu_i, mu_o);
  // S (1 / t - 1) = S (1 - t) / t; finite unless both are at grazing.
  const double single = 2.0 * AF(r) * (mu_i + r * S * (1.0 - t) * (mu_i / t) * kInvPi);
  if (variant == EonVariant::kFon) return single;
  const double multiple = 2.0 * mu_i * MultipleScatteringFactor(variant, r, mu_o) *
                          MultipleScatteringFactor(variant, r, mu_i) /
                          std::max(kEps, 1.0 - FonAverageAlbedo(r));
  return single + multiple;
}

}  // namespace lutbake
