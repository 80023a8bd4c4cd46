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

}  // namespace lutbake
