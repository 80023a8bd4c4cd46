// Lambert's diffuse BRDF, f = rho / pi, with reflectance rho = 1: the one
// classic model whose white furnace is exactly 1 at every view cosine,
//   albedo(mu_o) = int (1 / pi) mu_i d(omega_i) = (1 / pi) pi = 1.
#pragma once

#include "lutbake/core/math.h"

namespace lutbake {

inline constexpr double kLambertBrdf = kInvPi;

}  // namespace lutbake
