// The average Fresnel reflectance F_avg = 2 integral_0^1 F(mu) mu dmu of
// the models of models/fresnel.h, by adaptive Gauss-Kronrod quadrature.
#pragma once

#include "lutbake/models/fresnel.h"

namespace lutbake {

struct FresnelAverageResult {
  double value = 0.0;
  double error = 0.0;  // error bound of the adaptive quadrature
};

// F_avg by adaptive Gauss-Kronrod quadrature to ~1e-15, split at the critical
// angle for eta < 1 where the integrand has a kink.
FresnelAverageResult SchlickFresnelAverage(double f0);
FresnelAverageResult ExactFresnelAverage(double eta, double k);

// F_avg of the F82-tint Fresnel (models/fresnel.h) in closed form, error 0
// (the value is that of a few correctly rounded operations):
//   2 int_0^1 mu Schlick(F0, mu) dmu = F0 + (1 - F0) 2 B(2, 6) = 20/21 F0 + 1/21,
//   2 int_0^1 mu mu (1 - mu)^6 dmu  = 2 B(3, 7) = 2 (2! 6! / 9!) = 1/126,
// B the Beta function, B(p, q) = (p-1)! (q-1)! / (p+q-1)!, so
//   F_avg = 20/21 F0 + 1/21 - a / 126,
//   a = Schlick(F0, 1/7) (1 - tint) 7^7 / 6^6.
// It is the average of the formula as written, unclamped: it lies in
// [-13/756, 1] (-13/756 at F0 = tint = 0, where F itself dips below 0).
FresnelAverageResult F82TintFresnelAverage(double f0, double tint);

}  // namespace lutbake
