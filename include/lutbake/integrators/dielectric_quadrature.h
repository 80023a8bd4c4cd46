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
// long in x and w, 1 in t (exp(-t^2) is entire), split into equal pieces.
//
// The outer integral (phi in [0, pi]) is analytic except where the inner
// structure changes: at phi = pi/2, where T_c and T_r go to infinity as
// mu_o -> 0 (nearest singularity at distance asinh(mu_o / s_o)), and where
// a kink appears, disappears or crosses another (eta < 1: the onsets of
// total internal reflection and of the refracted horizon). The latter are
// found by scanning the sequence of kinks on 1024 azimuths (64 missed pairs
// of kinks that appear and vanish within pi/64, an error of 3e-8) and bisecting
// where it changes. The albedo first lays the outer panels on a coarse grid
// (graded toward pi/2 and each detected kink by ratio 4, down to sqrt(10
// tolerance) at a kink, at most pi/2 long) and, where that does not
// converge, on the fine one (ratio 2, down to sqrt(1e-3 tolerance), at most
// 0.5 long), keeping the smaller bound.
//
// The bound. Level k uses n(k) = 5, 7, 10, 14, 19, 25 Gauss nodes per outer and
// inner panel. The albedo refines its outer panels one by one: each at
// levels 0 and 1, then the one with the largest level difference a level
// further, until 2 sum_p |V_p,k - V_p,k-1| <= 0.5 tolerance (or no panel can
// go further). The value is the sum of the panels' last levels, the bound
// 2 sum_p |V_p,k - V_p,k-1| + 1e-10 + 0.2 tolerance + the Beckmann cut (a
// sum of differences, never smaller than the difference of sums that a
// common level would give; the factor 2: the plain difference was reached
// to 0.96 of itself on the validation grid, GGX eta = 1/1.33, mu_o = 0.3,
// r = 1; the 0.2 tolerance: one random point at grazing view, eta = 0.56,
// reached 1.13 x the doubled difference). The average adds levels to all
// its nodes together: bound 2 |V_k - V_{k-1}| + the same terms. Either is
// `converged` when bound <= tolerance max(1, value). Like the house
// quadratures' it is an estimate validated against the adaptive reference
// below and an independent brute-force rule in the tests, not a theorem.
//
// Measured (tolerance 1e-8) against the adaptive reference at 1e-10: the
// grid of both NDFs, both Smith forms, both lobes, eta in {1/2.42, 1/1.5,
// 1/1.33, 0.9, 1.1, 1.33, 1.5, 2.42}, mu_o in {0.01, 0.05, 0.3, 0.7, 1},
// r in {0.05, 0.1, 0.3, 0.6, 1}, and 300 random points (r 0.05..1, mu_o
// 0.01..1, eta 0.4..2.5): where the reference is within its domain (all
// but Beckmann at r <= 0.1 or mu_o = 0.01, where it is wrong by up to 1:
// it misses the narrow lobe; at r = 0.3, mu_o = 0.01, eta = 2.42 a
// 2 x 10^7-sample estimate agrees with this rule, not with it) real error
// at most 1.4e-9 and 0.27 of the bound (1476 of the 1900 points); at all
// 1900, within 0.23 of the bound of the previous rule (common levels, fine
// grid) at tolerance 1e-8, and on 950 of them (every other) within 0.27 of
// it at tolerance 1e-10.
// Cost on 16 x 16 texel centres (GGX correlated glass): eta = 1.5 ~5,400
// facet weights a point (was 9,600 with global levels), eta = 1/1.5
// ~92,000 (was 376,000); medians 0.18 ms (was 0.34) and 9.5 ms (was 28),
// means 0.7 ms (1.2) and 11 ms (43) on this shared machine, the same 3 of
// 256 texels at eta = 1/1.5 ending at a bound of up to 1.4e-8 (not
// `converged`). The facet weights (Smith's Lambda and G2 included) take
// ~70% of the time, the kink scan ~2%.
//
// Domain: alpha in [0, 1] (alpha = 0: the exact smooth values, `exact`),
// mu_o in [0, 1] (0 the grazing limit), eta in [1/128, 128]; else
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
// and, for eta < 1, toward mu = c_crit and mu = eta from both sides and
// toward mu = 1 (where E(mu) is not analytic; the .cpp says why), the
// albedo at each node by IntegrateDielectricAlbedo to half the tolerance
// with its own bound. The panels are refined one by one as the albedo's
// are (levels 5, 7, 10, 14, 19, 25, + 4 nodes); bound 2 sum_p |V_p,k -
// V_p,k-1| + the nodes' bounds, weighted as the rule weights them, + 1e-10.
// Measured (GGX correlated glass, tolerance 1e-8, this machine): eta = 1/1.5
// at r = 0.3 0.9 s (was 5.8 s with common levels on the fine grid), at r =
// 1 3 s and converged (was 18 s, not converged); eta = 1.5 ~0.05 s.
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
