// The Blinn-Phong lobe: cos^n of the half-vector angle, as a BRDF (no
// 1 / mu_i): f(o, i) = c (n.h)^n, h = normalize(o + i), with c one of
//   none:   c = 1
//   n+2:    c = (n + 2) / (2 pi)   (the normalisation of the NDF cos^n(theta_h),
//           applied to the BRDF as if it were one)
//   n+8:    c = (n + 8) / (8 pi)   (Akenine-Moller's approximation of the exact one)
//   exact:  c such that the albedo at normal incidence is 1.
//
// The exact factor in closed form. At mu_o = 1, h is halfway between n and
// i, theta_i = 2 theta_h, and with x = cos(theta_h) (cos(theta_i) = 2 x^2 - 1,
// sin(theta_i) d(theta_i) = -4 x dx, x from 1/sqrt(2) to 1)
//   albedo / c = 2 pi int x^n (2 x^2 - 1) 4 x dx
//              = 8 pi [2 x^(n+4) / (n+4) - x^(n+2) / (n+2)]_{1/sqrt(2)}^1
//              = 8 pi (n + 2^(-n/2)) / ((n + 2) (n + 4)),
// so c_exact = (n + 2) (n + 4) / (8 pi (n + 2^(-n/2))); 1 / pi at n = 0
// (Lambert), and (n + 6 + 8 / n) / (8 pi) + O(2^(-n/2)) for large n, which
// is where (n + 8) / (8 pi) comes from.
//
// The furnace integrates over h: d(omega_i) = 4 (o.h) d(omega_h), and with u
// = cos(theta_h), azimuth p of h about n (p = 0 toward o), A = mu_o u,
// B = s_o sqrt(1 - u^2): o.h = A + B cos(p), mu_i = 2 u (o.h) - mu_o, so
//   albedo = c int u^n P(u) du,
//   P(u)   = int_0^2pi 4 (o.h) max(0, mu_i) dp.
// The light is above the horizon for cos(p) > (mu_o - 2 u A) / (2 u B), i.e.
// |p| < p_max, and then o.h > 0 too; the integrand is a polynomial in
// cos(p), so with q = p_max
//   P(u) = 8 [2 u (A^2 q + 2 A B sin q + B^2 (q / 2 + sin(2q) / 4)) - mu_o (A q + B sin q)].
// q = pi (the whole circle) for u >= u_full = mu_o / sqrt((1 - s_o)^2 + mu_o^2)
// and q = 0 for u <= u_none = mu_o / sqrt((1 + s_o)^2 + mu_o^2): the half
// vectors of o with the horizon directions away from and toward o. P is
// analytic in u between these two.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

enum class BlinnPhongNormalisation { kNone, kNPlus2, kNPlus8, kExact };

std::string_view ToString(BlinnPhongNormalisation normalisation);

double BlinnPhongNormalisationFactor(BlinnPhongNormalisation normalisation, double exponent);

// f(o, i) for unit o and i (0 with either below the horizon).
double BlinnPhongBrdf(BlinnPhongNormalisation normalisation, double exponent, const Vec3 &o,
                      const Vec3 &i);

// P(u) above, for view cosine mu_o and cos(theta_h) = u in (0, 1].
double BlinnPhongRingIntegral(double mu_o, double u);

// u_none and u_full above; at mu_o = 0, u_none = 0 and u_full = 1.
struct BlinnPhongBreaks {
  double none, full;
};
BlinnPhongBreaks BlinnPhongHorizonBreaks(double mu_o);

}  // namespace lutbake
