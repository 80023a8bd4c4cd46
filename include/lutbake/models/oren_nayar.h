// Oren-Nayar rough diffuse reflection (Oren and Nayar 1994), reflectance
// rho = 1, roughness sigma: the standard deviation of the facet slope angle,
// in radians. With theta_o, theta_i the polar angles, dphi the azimuth
// between the light and the view, a = max(theta_i, theta_o), b =
// min(theta_i, theta_o):
//
// qualitative (the common "A + B" form):
//   f = (1 / pi) (A + B max(0, cos dphi) sin(a) tan(b)),
//   A = 1 - 0.5 s2 / (s2 + 0.33),  B = 0.45 s2 / (s2 + 0.09),  s2 = sigma^2.
//
// full (the paper's direct term L1 with C1, C2, C3 and its interreflection
// term L2, at rho = 1):
//   f = (1 / pi) [C1 + cos(dphi) C2 tan(b) + (1 - |cos dphi|) C3 tan((a + b) / 2)]
//     + (0.17 / pi) s2 / (s2 + 0.13) [1 - cos(dphi) (2 b / pi)^2],
//   C1 = 1 - 0.5 s2 / (s2 + 0.33),
//   C2 = 0.45 s2 / (s2 + 0.09) sin(a)                    where cos dphi >= 0,
//      = 0.45 s2 / (s2 + 0.09) (sin(a) - (2 b / pi)^3)    where cos dphi < 0,
//   C3 = 0.125 s2 / (s2 + 0.09) (4 a b / pi^2)^2.
//
// The azimuthal integrals are closed-form (int_-pi^pi max(0, cos) = 2,
// int cos C2 = 2 K2 (2b/pi)^3 ... see below), so the furnace is a 1D
// integral over theta_i:
//   albedo = int_0^pi/2 sin(theta_i) [cos(theta_i) int_-pi^pi f dphi] d(theta_i),
// the bracket being OrenNayarCosineRing:
//   qualitative: 2 cos(theta_i) (A + B sin(a) tan(b) / pi)
//   full:        2 cos(theta_i) [C1 + K2 (2b/pi)^3 tan(b) / pi
//                   + (1 - 2/pi) C3 tan((a + b) / 2)] + 0.34 cos(theta_i) s2 / (s2 + 0.13)
//   with K2 = 0.45 s2 / (s2 + 0.09) (the cos dphi C2 term integrates to
//   2 K2 sin(a) - 2 K2 (sin(a) - (2b/pi)^3)).
// tan(b) and tan((a + b) / 2) grow without bound at grazing, the products
// with cos(theta_i) do not: they are computed as products (tan((a+b)/2) =
// (sin a + sin b) / (cos a + cos b)). The integrand has a kink at theta_i =
// theta_o, where a and b swap.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

enum class OrenNayarVariant { kFull, kQualitative };

std::string_view ToString(OrenNayarVariant variant);

// f(o, i) for unit o and i (0 with either below the horizon); sigma in radians.
double OrenNayarBrdf(OrenNayarVariant variant, double sigma, const Vec3 &o, const Vec3 &i);

// cos(theta_i) int_-pi^pi f d(dphi) at polar angles theta_o, theta_i in [0, pi/2]
// (finite except at theta_o = theta_i = pi/2).
double OrenNayarCosineRing(OrenNayarVariant variant, double sigma, double theta_o, double theta_i);

}  // namespace lutbake
