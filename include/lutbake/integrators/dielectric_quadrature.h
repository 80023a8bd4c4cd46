// The directional albedo of a rough dielectric interface (models/dielectric.h),
// reflection only or reflection plus transmission, and its cosine-weighted
// average, with error bounds:
//
//   E(mu_o) = E_{h ~ D_o}[w(h)],  w the facet weight of dielectric.h in [0, 1],
//   E_avg   = 2 int_0^1 E(mu) mu dmu.
//
// Change of variables. With o = (s_o, 0, mu_o), h at polar angle theta (T =
// tan(theta)) and azimuth phi, sc = s_o cos(phi), and xi the NDF's own CDF
// in theta (D cos(theta) d(omega_h) = d(xi) d(phi) / (2 pi)),
//   D_o(h) d(omega_h) = (o.h)_+ D d(omega_h) / (mu_o + L_o)
//                     = (sc T + mu_o)_+ / (mu_o + L_o) d(xi) d(phi) / (2 pi),
// L_o = mu_o Lambda(mu_o), and by the symmetry phi -> -phi
//   E = (1/pi) int_0^pi d(phi) int d(xi) (sc T + mu_o)_+ / (mu_o + L_o) w(h).
// The inner variable is x = T / alpha on [0, 1] and w = alpha / T beyond
// for GGX (d(xi) = 2 x / (1 + x^2)^2 dx in both), t = T / alpha for
// Beckmann (d(xi) = 2 t exp(-t^2) dt, cut at t = 7: the rest is below
// e^-49 (mu_o + 8 s_o alpha) / (mu_o + L_o), added to the bound).
//
// The kinks of the inner integrand (per azimuth, in closed form):
//  - the facet turns away from o, o.h = 0:  T_c = mu_o / (-sc) for sc < 0
//    (the end of the range);
//  - the mirror direction crosses the horizon, mu_r = 0:
//    T_r = (sc + sqrt(sc^2 + mu_o^2)) / mu_o (= mu_o / (sqrt(..) - sc) for sc < 0);
//  - total internal reflection begins (eta < 1), o.h = c_crit = sqrt(1 - eta^2):
//    (sc^2 - c_crit^2) T^2 + 2 sc mu_o T + mu_o^2 - c_crit^2 = 0, with
//    discriminant c_crit^2 (sc^2 + mu_o^2 - c_crit^2); F has a square-root
//    branch point there (on the refracting side);
//  - the refracted direction crosses the horizon (eta < 1 only: for eta > 1
//    every refracted ray has mu_t < -mu_o / eta): h ~ o + eta i with i on
//    the horizon, which for an azimuth phi of h gives tan(theta) = rho / mu_o,
//    rho = s_o cos(phi) +- sqrt(eta^2 - s_o^2 sin^2(phi)).
// The panels end at every kink and are graded toward it (ratio 2) down to
// the scale of the nearest singularity off the real axis: at the horizons,
// G2 / mu_o's pole and mu Lambda's branch points at |mu_i| ~ min(alpha,
// mu_o) / 2; at o.h = 0, F's branch point at c = +-i sqrt(eta^2 - 1). At
// the critical cosine 1 - F = sqrt(c - c_crit) g(c), g analytic: the panel
// on the refracting side is mapped by v = v_root +- length u^2, which makes
// the integrand analytic in u (that panel reaches the next kink, or half
// way to it). GGX's core/tail split (T = alpha) moves onto a kink within a
// factor 2 of it, so that no kink sits just beside an ungraded panel end;
// the tail variable has singularities at w = +-i alpha (1 + T^2 = 0): no
// tail panel is longer than max(its start, alpha). Panels are at most 0.5
// long in x, w, t and phi, split into equal pieces.
//
// The outer integral (phi in [0, pi]) is analytic except where the inner
// structure changes: at phi = pi/2, where T_c and T_r go to infinity as
// mu_o -> 0 (nearest singularity at distance asinh(mu_o / s_o)), and where
// a kink appears, disappears or crosses another (eta < 1: the onsets of
// total internal reflection and of the refracted horizon). The latter are
// found by scanning the sequence of kinks on 1024 azimuths (64 missed pairs
// of kinks that appear and vanish within pi/64, an error of 3e-8) and bisecting
// where it changes; the panels are graded toward each, down to sqrt(1e-3
// tolerance) in phi.
//
// The bound. Level k uses n(k) = 5, 7, 10, 14, 19, 25 Gauss nodes per outer and
// inner panel. The value is level k's, the bound 2 |V_k - V_{k-1}| + 1e-10 +
// 0.2 tolerance + the Beckmann cut (the factor 2: the plain difference was
// reached to 0.96 of itself on the validation grid, GGX eta = 1/1.33, mu_o =
// 0.3, r = 1; the 0.2 tolerance: one random point at grazing view, eta =
// 0.56, reached 1.13 x the doubled difference); levels are added until
// bound <= tolerance max(1, value)
// (`converged`) or the finest is done. Like the house quadratures' it is an
// estimate validated against the adaptive reference below and an independent
// brute-force rule in the tests, not a theorem.
//
// Measured (tolerance 1e-8) against the adaptive reference at 1e-10..1e-11:
// 144 grid points (GGX and Beckmann, correlated, glass; eta in {1/2.42,
// 1/1.5, 1/1.33, 1.33, 1.5, 2.42}, mu_o in {0.05, 0.3, 0.7, 1}, r in {0.3,
// 0.6, 1}): real error at most 1.6e-9, all within the bound; 107 random
// points (both NDFs and Smith forms and lobes, mu_o 0.02..1, r 0.3..1, eta
// 0.4..2.5): at most 1.1e-9 and 0.37 of the bound. Cost on 16 x 16 texel
// centres (GGX correlated glass): eta = 1.5 ~9,600 facet weights a point
// (6,000 at r ~ 1 to 23,000 at r = 1/32), 0.3 to 2 ms on this shared
// machine; eta = 1/1.5 ~370,000 (10 to 100 ms), 3 of 256 texels ending at
// a bound of up to 1.4e-8 (not `converged`). The outer azimuth grading at
// the detected kinks dominates for eta < 1.
//
// Domain: alpha in [0, 1] (alpha = 0: the exact smooth values, `exact`),
// mu_o in [0, 1] (0 the grazing limit), eta in [1/16, 16]; else
// std::invalid_argument.
#pragma once

#include <cstdint>

#include "lutbake/models/dielectric.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

struct DielectricIntegral {
  double value = 0.0;
  double bound = 0.0;        // |value - exact| <= bound (an estimate; see above)
  uint64_t evaluations = 0;  // facet weights evaluated, all levels
  bool exact = false;        // value is exact (alpha = 0)
  bool converged = false;    // bound <= tolerance max(1, value)
};

DielectricIntegral IntegrateDielectricAlbedo(NdfKind ndf, SmithForm smith, DielectricLobes lobes,
                                             double alpha, double mu_o, double eta,
                                             double tolerance);

// E_avg: Gauss panels in mu graded toward 0 from min(alpha, 0.01) (ratio 2)
// and, for eta < 1, toward mu = c_crit from both sides (below it the normal
// facet reflects totally), E at each node at the same level; bound
// 2 |V_k - V_{k-1}| + 1e-10 + 0.2 tolerance + the node values' Beckmann cuts.
DielectricIntegral IntegrateDielectricAverage(NdfKind ndf, SmithForm smith, DielectricLobes lobes,
                                              double alpha, double eta, double tolerance);

// The independent reference: nested adaptive Gauss-Kronrod (gauss_kronrod.h)
// over the light direction i = (mu_i, phi_i), of f(o, i) |mu_i|
// (DielectricBsdfCosine), split at mu_i = 0, at the lobes' peaks (the
// mirror and the smooth refraction direction) and at the edges of the
// refracted support (o.i < -1/eta for eta > 1, -eta for eta < 1; and h.z > 0,
// mu_i <= -mu_o / eta or >= -mu_o / eta). Bound: 16 x the sum of |K15 - G7|
// of both levels. Meant for alpha >= ~0.01 (the lobe's peak, of width alpha,
// must be found by bisection), mu_o > 0 and |eta - 1| >= ~0.1: at eta = 1
// the transmitted lobe is a Dirac at i = -o (every facet passes o straight
// through), which no rule over i can integrate; near 1 it is that narrow.
DielectricIntegral IntegrateDielectricAlbedoAdaptive(NdfKind ndf, SmithForm smith,
                                                     DielectricLobes lobes, double alpha,
                                                     double mu_o, double eta, double tolerance);

}  // namespace lutbake
