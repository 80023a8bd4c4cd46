// The energy-preserving Oren-Nayar model (EON) of OpenPBR (Portsmouth, Kutz
// and Hill 2024, "EON: A practical energy-preserving rough diffuse BRDF",
// JCGT 14(1)), at reflectance rho = 1, roughness r in [0, 1] (not an angle).
//
// Single scattering: Fujii's Oren-Nayar (FON), with s = o.i - mu_i mu_o,
//   f_ss = (1 / pi) A_F (1 + r s / t),  t = max(mu_i, mu_o) where s > 0, else 1,
//   A_F  = 1 / (1 + c1 r),  c1 = 1/2 - 2 / (3 pi).
// Its directional albedo is closed-form (the paper's E_FON):
//   E_F(mu)  = A_F + (r A_F / pi) G(mu),  S = sqrt(1 - mu^2),
//   G(mu)    = S (acos(mu) - S mu) + (2/3) ((S / mu) (1 - S^3) - S),
// written here with (S / mu)(1 - S^3) = S mu (1 + S + S^2) / (1 + S), which
// does not cancel at grazing; and its average 2 int E_F mu dmu is
//   E_F,avg  = A_F (1 + c2 r),  c2 = 2/3 - 28 / (15 pi).
// The paper's cheaper fit replaces G / pi by a quartic in 1 - mu:
//   G / pi ~ (1 - mu) (g1 + (1 - mu) (g2 + (1 - mu) (g3 + (1 - mu) g4))),
//   g = 0.0571085289, 0.491881867, -0.332181442, 0.0714429953.
// Multiple scattering (Kulla-Conty form, rho_ms = 1 at rho = 1):
//   f_ms = (1 / pi) max(eps, 1 - E_F(mu_o)) max(eps, 1 - E_F(mu_i)) / max(eps, 1 - E_F,avg),
//   eps = 1e-7, with E_F exact or fitted (the variant).
// With the exact E_F the albedo of f_ss + f_ms is E_F + (1 - E_F) = 1 at
// every mu (away from r -> 0, where the eps clamps act on a lobe that holds
// no energy); with the fit it is off by the fit's error.
//
// The azimuthal integral over dphi (s = sin(theta_i) sin(theta_o) cos(dphi))
// is closed-form: int max(0, cos) = 2, int min(0, cos) = -2, so
//   int_-pi^pi f_ss = 2 A_F (1 + r sin(theta_i) sin(theta_o) (1 / t - 1) / pi),
//   t = max(mu_i, mu_o), and int f_ms = 2 pi f_ms.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

// exact: E_F in closed form (the paper's E_FON_exact); approx: its quartic
// fit (E_FON_approx); fon: the single-scattering FON lobe alone.
enum class EonVariant { kExact, kApprox, kFon };

std::string_view ToString(EonVariant variant);

double FonAlbedo(double r, double mu);        // E_F(mu), closed form
double FonAlbedoApprox(double r, double mu);  // its quartic fit
double FonAverageAlbedo(double r);            // E_F,avg

double EonBrdf(EonVariant variant, double r, const Vec3 &o, const Vec3 &i);

// cos(theta_i) int_-pi^pi f d(dphi) at polar angles theta_o, theta_i.
double EonCosineRing(EonVariant variant, double r, double theta_o, double theta_i);

}  // namespace lutbake
