// The directional albedo of the sheen lobe (models/sheen.h) and its cosine-
// weighted average, with error bounds:
//
//   E(mu_o) = integral over the upper hemisphere of D(h) V(o, i) mu_i d(omega_i),
//   E_avg   = 2 int_0^1 E(mu) mu dmu.
//
// Domain: alpha in [0, 1], mu_o in [0, 1]. As alpha -> 0 the Charlie lobe
// D = (2 + q) sin(theta_h)^q / (2 pi) (q = 1 / alpha) collapses onto the
// horizon of h: only half vectors with cos(theta_h) <~ sqrt(alpha) keep any
// weight, and a light above the horizon needs cos(theta_h) >= mu_o / 2
// (theta_h <= (theta_o + pi/2) / 2, sin^2(theta_h) <= 1 - mu_o^2 / 4), so
// E(mu_o > 0) <= 2 pi W_max (2 + q) / (2 pi) (1 - mu_o^2 / 4)^(q / 2) -> 0
// (W <= W_max, a constant for fixed mu_o): alpha = 0 gives E = 0 exactly for
// mu_o > 0. At mu_o = 0 the limit diverges instead (E ~ 0.4 alpha^(-1/2) for
// ashikhmin), and the Charlie visibility's 1 / mu_o makes E ~ C / mu_o
// infinite at mu_o = 0 for every alpha: those points throw
// std::domain_error. Everything else returns a finite value and a bound,
// down to alpha = 1e-24 and mu_o = 1e-300; a value beyond the range of
// double throws std::domain_error.
//
// Bounds are absolute; the target is tolerance * max(1, value) (E exceeds 1
// where the lobe meets a grazing view: charlie for mu_o below ~0.05 at
// alpha <= 0.03 and below ~5e-6 at larger alpha; ashikhmin below ~0.09 at
// alpha ~ 0.01 to 0.03, nowhere for alpha >= 0.3).
//
// The default's bound is the difference of two Gauss orders on the same
// panels (summed over panels, plus a floor and the parts provably
// negligible), not a theorem; it is validated: against tests/data/sheen (416
// points, an independent numpy computation to ~1e-14) every value is within
// its bound at tolerance 1e-8 and 1e-10 (real error: median 2.5e-4 of the
// bound, at most 0.16 of it; 0.36 of the closed-form upper bound where the
// value is that bound's zero);
// against this file's adaptive reference at 1e-11 on 576 table-like points
// (worst 0.16 of the bound) and 400 random ones down to alpha = 1e-6 and mu_o
// = 1e-8 (worst 0.17 at tolerance 1e-6, 0.013 at 1e-8), and 176 extreme ones
// (alpha 1e-24..1, mu_o 1e-300..1: worst 0.05). Cost at tolerance 1e-8 on a
// 32 x 32 table (alpha = r^2): ~7000 evaluations and 36 (ashikhmin) to 45
// (charlie) microseconds a point, one thread.
#pragma once

#include <cstdint>

#include "lutbake/models/sheen.h"

namespace lutbake {

struct SheenIntegral {
  double value = 0.0;
  double bound = 0.0;        // |value - exact| <= bound
  uint64_t evaluations = 0;  // integrand evaluations (D at a node), all levels
  bool exact = false;        // value is the exact integral (alpha = 0)
};

// The default integrator: a Gauss-Legendre product rule over the light
// direction (mu_i, phi) on panels placed from the integrand's known features,
// at two orders; see sheen_quadrature.cpp for the panels and the bound.
// bound <= tolerance * max(1, value) whenever the finest order reaches it.
SheenIntegral IntegrateSheenAlbedo(SheenVisibility visibility, double alpha, double mu_o,
                                   double tolerance);
// E_avg by Gauss panels in mu, E at each node by the rule above.
SheenIntegral IntegrateSheenAlbedoAverage(SheenVisibility visibility, double alpha,
                                          double tolerance);

// The independent reference: the half vector (theta_h, phi_h), with theta_h
// through the lobe's own variable v = -(q/2) log(sin^2(theta_h)) (D cos(theta_h)
// d(omega_h) = (1 + 2 alpha) exp(-(1 + 2 alpha) v) dv d(phi_h) / (2 pi)), the
// Jacobian d(omega_i) = 4 (o.h) d(omega_h) and the light kept above the
// horizon by the inner range; nested adaptive Gauss-Kronrod (gauss_kronrod.h).
// Bound: 16 x the sums of |K15 - G7| of both levels (the outer one and the
// integral of the inner ones). Used by the tests (and meant for `lutbake
// check`) to judge the default.
SheenIntegral IntegrateSheenAlbedoAdaptive(SheenVisibility visibility, double alpha, double mu_o,
                                           double tolerance);
// The sheen's split-sum bias B = int D V (1 - o.h)^5 mu_i d(omega_i) (the
// F90 term of a Schlick-weighted sheen, as Unity HDRP's Charlie FGD stores
// it; F0 A + F90 B with A = E - B), by the same adaptive rule with the
// weight in the inner integrand (0 <= weight <= 1, so the shortcut bound
// above still holds).
SheenIntegral IntegrateSheenSchlickWeightedAdaptive(SheenVisibility visibility, double alpha,
                                                    double mu_o, double tolerance);
SheenIntegral IntegrateSheenAlbedoAverageAdaptive(SheenVisibility visibility, double alpha,
                                                  double tolerance);

}  // namespace lutbake
