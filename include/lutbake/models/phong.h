// The Phong lobe: cos^n of the angle between the light i and the mirror
// direction of the view, r = 2 mu_o n - o, as a BRDF (no 1 / mu_i):
//   f(o, i) = c max(0, r.i)^n,
// with the normalisation c one of
//   none:  c = 1
//   n+1:   c = (n + 1) / (2 pi)  (the lobe integrates to 1 over the sphere
//          without the cosine: int cos^n = 2 pi / (n + 1))
//   n+2:   c = (n + 2) / (2 pi)  (albedo 1 at normal incidence, where
//          int cos^n(theta) cos(theta) d(omega) = 2 pi / (n + 2))
// So at mu_o = 1 the albedo is 2 pi c / (n + 2): 1 for n+2, (n + 1) / (n + 2)
// for n+1.
//
// The furnace integrates in cones about r. With i at angle a from r, u =
// cos(a), and azimuth b about r (b = 0 toward the normal, in the plane of n
// and o), n.i = mu_o u + s_o sqrt(1 - u^2) cos(b), s_o = sqrt(1 - mu_o^2), so
//   albedo = c int_0^1 u^n W(u) du,  W(u) = int_0^2pi max(0, n.i) db,
// and W is closed-form: with A = mu_o u, B = s_o sqrt(1 - u^2), the light is
// above the horizon for cos(b) > -A / B, i.e. |b| < b_max,
//   b_max = pi                 if B <= A (u >= s_o: the whole cone is up),
//         = acos(-A / B)       otherwise,
//   W(u)  = 2 (A b_max + B sin(b_max)).
// W is analytic in u except at u = s_o, where b_max leaves pi.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

enum class PhongNormalisation { kNone, kNPlus1, kNPlus2 };

std::string_view ToString(PhongNormalisation normalisation);

// c of the normalisation for exponent n >= 0.
double PhongNormalisationFactor(PhongNormalisation normalisation, double exponent);

// f(o, i) for unit o and i in the upper hemisphere (0 below it).
double PhongBrdf(PhongNormalisation normalisation, double exponent, const Vec3 &o, const Vec3 &i);

// W(u) above: the integral over the cone of directions at cos(a) = u from the
// mirror direction of view cosine mu_o of max(0, n.i) db.
double PhongConeIntegral(double mu_o, double u);

}  // namespace lutbake
