// Burley's diffuse BRDF (Disney 2012, "Physically-Based Shading at Disney"),
// base colour 1:
//   f_d(v, l) = (1/pi) F(mu_l) F(mu_v),  F(u) = 1 + (F_D90 - 1) (1 - u)^5,
//   F_D90 = 0.5 + 2 r cos^2(theta_d),  cos(theta_d) = l.h,
// h the half vector of v and l, r the perceptual roughness (no NDF, no
// alpha: r enters F_D90 alone). Its directional albedo is table burley_E.
#pragma once

#include <cmath>

#include "lutbake/core/math.h"

namespace lutbake {

// f_d(v, l) as Burley writes it, cos(theta_d) = l.h with h = (v + l) / |v +
// l| (l = -v, where h is undefined, happens only at the grazing horizon:
// measure zero; cos(theta_d) = 0 there).
inline double BurleyDiffuseBrdf(double r, const Vec3 &v, const Vec3 &l) {
  const Vec3 sum{v.x + l.x, v.y + l.y, v.z + l.z};
  const double length2 = Dot(sum, sum);
  const double lh = length2 > 0.0 ? Dot(l, sum) / std::sqrt(length2) : 0.0;
  const double fd90 = 0.5 + 2.0 * r * lh * lh;
  const auto schlick = [fd90](double u) { return 1.0 + (fd90 - 1.0) * std::pow(1.0 - u, 5.0); };
  return schlick(l.z) * schlick(v.z) * kInvPi;
}

}  // namespace lutbake
