// Brute-force azimuthal integrals of a BRDF for the model tests: int over
// the light azimuth of f(o, i) at fixed polar angle, by Gauss-Legendre on
// panels split at given azimuths (the BRDFs' kinks), to compare with the
// closed-form azimuthal integrals the models provide.
#pragma once

#include <cmath>
#include <vector>

#include "lutbake/core/math.h"
#include "lutbake/integrators/gauss_legendre.h"

namespace lutbake::test {

// int_-pi^pi f(o, i(theta_i, phi)) dphi with o = (sin theta_o, 0, cos theta_o):
// twice the integral over [0, pi] (f is even in phi), 64 nodes per panel.
template <typename F>
double AzimuthIntegral(const F &f, double theta_o, double theta_i, std::vector<double> breaks) {
  const Vec3 o{std::sin(theta_o), 0.0, std::cos(theta_o)};
  const GaussLegendreRule &rule = GaussLegendre(64);
  double sum = 0.0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    for (int j = 0; j < rule.n; ++j) {
      const double phi = a + (b - a) * rule.x[j];
      const Vec3 i{std::sin(theta_i) * std::cos(phi), std::sin(theta_i) * std::sin(phi),
                   std::cos(theta_i)};
      sum += (b - a) * rule.w[j] * f(o, i);
    }
  }
  return 2.0 * sum;
}

}  // namespace lutbake::test
