// Deterministic reference integrals of E, A, B and E_avg by nested adaptive
// Gauss-Kronrod quadrature over the half vector. Slow, accurate to ~1e-11:
// the truth that tests hold the Monte Carlo estimators to.
//
// Parameterisation. With o in the xz-plane (sin(theta_o) = s_o, mu_o = c_o)
// and h at (theta, phi),
//   E = (1/pi) integral_0^pi dphi integral d(xi) (o.h / cos(theta)) G2 / mu_o
// where xi is the NDF's own CDF in theta (D cos(theta) d(omega) = d(xi) dphi / 2pi),
// so the peak of width alpha is absorbed into the variable:
//   GGX:      xi = sin^2(psi), tan(theta) = alpha tan(psi), d(xi) = sin(2 psi) d(psi)
//   Beckmann: xi = 1 - exp(-t^2), tan(theta) = alpha t,     d(xi) = 2 t exp(-t^2) dt
// The horizon mu_i = 2 (o.h) cos(theta) - mu_o > 0 reads
//   s_o cos(phi) sin(2 theta) + c_o cos(2 theta) > 0  <=>  theta < theta_max(phi),
//   theta_max(phi) = (atan2(s_o cos(phi), c_o) + pi/2) / 2 = atan2(c_o, -s_o cos(phi)) / 2,
// so the inner integral stops exactly there and the integrand is smooth
// inside (G2 falls to 0 linearly at the boundary). The outer integral is
// split at phi = pi/2, where theta_max jumps when mu_o = 0.
#pragma once

#include <cstdint>

#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

struct ReferenceAlbedo {
  double E = 0, A = 0, B = 0;
  double error = 0;     // error estimate of A plus that of B (so also a bound for E)
  int evaluations = 0;  // integrand evaluations, A and B counted once
  bool converged = false;
};

ReferenceAlbedo IntegrateReferenceAlbedo(const Ndf &ndf, SmithForm smith, double mu_o,
                                         double tolerance = 1e-12);

struct ReferenceF82 {
  double C = 0;
  double error = 0;  // error estimate of C
  int evaluations = 0;
  bool converged = false;
};

// The F82 term C = integral of f (o.h) (1 - o.h)^6 mu_i d omega_i (table
// f82), F = 1 in f: the same integrand as E weighted by (o.h) (1 - o.h)^6,
// integrated on its own (its adaptive refinement follows C's error).
ReferenceF82 IntegrateReferenceF82(const Ndf &ndf, SmithForm smith, double mu_o,
                                   double tolerance = 1e-12);

struct ReferenceAverage {
  double value = 0;
  double error = 0;
  uint64_t evaluations = 0;
  bool converged = false;
};

// E_avg = 2 integral_0^1 E(mu) mu dmu, the E integral nested inside; the mu
// axis is split at mu = alpha and 8 alpha, the width of the grazing boundary layer.
ReferenceAverage IntegrateReferenceAlbedoAverage(const Ndf &ndf, SmithForm smith,
                                                 double tolerance = 1e-11);

}  // namespace lutbake
