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
// Beyond that, a branch point of W = sqrt(c^2 - c_crit^2) outside
// a panel but within a panel length of it (the panel beyond a short one, or
// the range's end at T = 0 or T = infinity when the refracting region reaches
// it: the quadratic's roots at T <= 0) maps that panel by v = root +- (s_a +
// (s_b - s_a) u)^2, s = sqrt(|v - root|), so that the square root is linear in
// u; a start within half a panel of such a root is split from the next point
// as two square-root ends are. Where c_crit is small (eta -> 1), the side of
// the root that refracts is graded down to c_crit / 2 (F's other
// singularities, c = -c_crit and 0).
//
// The outer integral (phi in [0, pi]) is analytic except at phi = pi/2,
// where T_c and T_r go to infinity as mu_o -> 0 (nearest singularity at
// distance asinh(mu_o / s_o); for eta < 1 also where the total-reflection
// circle crosses the NDF's peak about the normal, |mu_o - c_crit| / (alpha
// s_o) and alpha mu_o / (4 s_o)), and, for eta < 1, where the sequence of
// kinks changes. Those azimuths are known in closed form (the .cpp derives
// them): the total-reflection circle's tangency to the ray, sc^2 = c_crit^2 -
// mu_o^2 (the refracted horizon's two roots merge there too: sin(phi) = eta /
// s_o is the same azimuth); its second root leaving through T = infinity, sc =
// c_crit; the mirror's horizon crossing it, at cos(theta) = mu_o / (2
// c_crit). Each is a square-root-type point (a kink position analytic in
// sqrt(phi - phi*), or a max(., 0) and a sqrt(max(., 0)) crossing) or a plain
// kink of the form max(delta, 0) analytic: the outer panels on both sides are
// mapped quadratically. Where a Smith layer meets the point (the transmitted
// one at the tangency, the mirror's at the crossing) they are graded toward
// it (ratio 4) down to the layer's own azimuth scale or sqrt(10 tolerance),
// whichever is wider; a break near pi/2 is graded to its distance from pi/2.
// The albedo lays these panels (at most pi/2 long) and, where they do not
// converge, the fine grid (ratio 2, down to sqrt(1e-3 tolerance), at most 0.5
// long), keeping the smaller bound.
//
// GGX's node geometry and facet weights are computed by a Highway kernel
// (integrators/dielectric_kernel.h: the same bits on every instruction set,
// summed in node order); Beckmann's by DielectricFacetWeight.
//
// For eta in [1/4, 4] the albedo's levels take n(k) = 5, 6, 9, 12, 16, 21
// nodes on inner panels graded with ratio 4, not 2 (dielectric_quadrature.cpp).
//
// The bound. Level k uses n(k) = 5, 7, 10, 14, 19, 25 Gauss nodes per outer and
// inner panel. The albedo refines its outer panels one by one: each at
// levels 1 and 2, then the one with the largest level difference a level
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
// Measured (tolerance 1e-8) against the adaptive reference at tolerance /
// 1000, on 700 random points in two sets (GGX 3/4, Beckmann 1/4, both Smith
// forms and lobes, r 0.2..1 (Beckmann 0.35..1), mu_o 0.02..1, eta 0.3..0.95
// and 1.05..3.05, 30% of the eta < 1 points at mu_o = c_crit +- 0.01 and 15% at
// mu_o = eta +- 0.01): error at most 0.17 of the bound, none outside, all
// converged. On 2379 harder points (eta 1/128, 1/99.5, 1/3, 1/1.5, 0.9, 0.99,
// 0.999, 1 -+ 1e-6, 1, 1.001, 1.01, 1.1, 1.5, 3, 99.5, 128; r 0.001..1; mu_o
// 1e-4..1 and c_crit +- 1e-6, +- 1e-3, eta +- 1e-4) against the rule this one
// replaced (a scan of 1024 azimuths for the outer kinks, graded toward each):
// within the sum of both bounds at all but one point, where the old rule is
// outside its own (at 1e-11 both give 0.82894362015; eta = 1 - 1e-6, r =
// 0.6, mu_o = 0.3); 36 of them not converged (146 with the old rule).
// Cost on 6 x 6 texel centres x 11 etas (GGX correlated glass, one thread,
// CPU time on the shared build machine): 0.27 ms a texel (16,100 facet
// weights; 0.09 ms for eta >= 1, 0.5-0.6 ms for eta < 1), against 1.8 ms
// (50,600) for the rule before.
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

// The average's rule before the one below, kept as its independent check
// (tests, validation): E_avg = int_0^(pi/2) E(cos(theta)) sin(2 theta)
// dtheta, a rule in theta = acos(mu) (E is even, so analytic, in theta at the normal, where in mu
// it is not). The panels end on E's kinks, for eta < 1 theta_c = asin(eta) (mu = c_crit) and, for
// alpha >= 0.04, theta_eta = acos(eta) (mu = eta; below, the facets at the horizon that make it
// weigh alpha^2 / pi), graded toward them (ratio 4, from max(alpha / 4, sqrt(10 tolerance))) and
// toward mu = 0 (from max(alpha, 0.1 sqrt(tolerance))), the panels that touch them mapped
// quadratically (the .cpp says why). Each panel takes Fejer's second rule,
// nested: 3, 7, 15, 31, 63, 127 nodes, every albedo kept for the finer
// levels. Every panel at the first two levels, then the panel with the
// largest level difference a level further (split in two past the last)
// until 2 sum_p |V_p,k - V_p,k-1| <= tolerance / 2. Each node's albedo by
// IntegrateDielectricAlbedo at the tolerance its weight allows (0.4
// tolerance / (panels x nodes x its weight), from 0.4 tolerance to 1e-4), with
// its own bound. Bound: 2 sum_p |V_p,k - V_p,k-1| + the nodes' bounds,
// weighted as the rule weights them, + 1e-10 (an estimate, validated
// against the rule this one replaced, Gauss panels in mu at tolerance 1e-9:
// on 17 etas from 1/128 to 128 (1 -+ 1e-6 among them) x 8 roughnesses, GGX
// correlated, both lobes, every difference within 0.59 of the sum of both
// bounds; Beckmann glass, GGX separable glass and Beckmann separable
// reflection on 4 roughnesses within 0.54, measured before mu = eta was left
// out below alpha = 0.04). Facet weights at tolerance 1e-8 on that grid: glass 3.0e8
// against 6.1e8 for the rule before, reflection 2.6e8 against 5.0e8 (bake
// times: docs/speed.md).
DielectricIntegral IntegrateDielectricAverageOverAlbedo(NdfKind ndf, SmithForm smith,
                                                        DielectricLobes lobes, double alpha,
                                                        double eta, double tolerance);

// E_avg over the half vector first (integrators/dielectric_average.cpp):
// with o at c = o.h and azimuth psi about the facet h (h_z = cos(theta),
// h_s = sin(theta)), d(omega_o) = dc d(psi) and
//   E_avg = (2/pi) int d(xi) / h_z int_0^1 c dc [F(c) A_r + (1 - F(c)) A_t],
//   A_r = int_0^pi G2(mu_o, mu_r) d(psi),  A_t = int_0^pi G2(mu_o, |mu_t|) d(psi)
// over the azimuths where those cosines are positive, mu_o = c h_z + u,
// mu_r = c h_z - u, |mu_t| = (W h_z + u) / eta, u = sqrt(1 - c^2) h_s
// cos(psi) (xi the NDF's CDF in theta, in GGX's x = T / alpha and w = alpha
// / T or Beckmann's t = T / alpha, cut at t = 7). F depends on c alone: the
// critical cosine is a coordinate line, and each horizon the closed-form end
// of a psi range. The panels end on the breaks: in psi (as v = tan(psi / 2))
// at the horizons, graded toward them (ratio 4) to where G2 is singular
// (min(alpha / 2, the other cosine there)); in c at c_crit (the refracting
// side mapped quadratically, graded to c_crit / 2), at c = h_s and, for
// glass with eta < 1, c = sqrt(1 - eta^2 h_z^2), where a horizon enters the
// psi range (the panel below mapped quadratically, both sides graded to G2's
// layer, ratio 4, no further than the next break), and at c = 0 (graded to
// half the distance of F's singularities for eta > 1: sqrt(eta^2 - 1) and
// 1 / sqrt(eta^2 + 1)); in theta at tan(theta) = c_crit / eta (eta < 1,
// where c = h_s crosses c_crit: mapped quadratically on both sides), GGX's
// split T = alpha, and toward theta = pi/2 (w = 0, from alpha / 4). Level k
// takes n(k) = 5, 7, 10, 14, 19, 25 Gauss nodes per panel in all three
// variables; every outer panel at levels 0 and 1, then the one with the
// largest level difference a level further (split in two past the last)
// until 2 sum_p |V_p,k - V_p,k-1| <= 0.7 tolerance. Bound: 2 sum_p |V_p,k -
// V_p,k-1| + 0.2 tolerance + 1e-10 (+ the Beckmann cut, e^-49 (1 + 8
// alpha)); `converged` when that is <= tolerance max(1, value). An estimate,
// validated against IntegrateDielectricAverageOverAlbedo (a rule over the
// view of albedos over the half vector): the default glass_Eavg and
// spec_Eavg tables (GGX correlated, 32 roughnesses x 23 etas from 1/3 to 3,
// tolerance 1e-8) differ from that rule's by at most 0.85 of the two
// stored bounds summed, and the tests' hard points (eta 1/128, 0.9999, 1 -+
// 1e-6, 128; r 0.01 to 1; Beckmann and separable) within the summed bounds
// too. Starting levels of 3 and 5 nodes agreed falsely by 1.5e-7 near theta
// = pi/2, and a split of the psi range at pi/2 inside a horizon's layer
// missed 2.5e-8: both are what the layout above avoids. Cost at tolerance
// 1e-8 (bake times: docs/speed.md): 0.2 to 2 million G2 values a texel.
// Where the outer panels keep splitting (more than 24: the differences stop
// shrinking, e.g. eta < 0.15 at r 0.33..1, where the inner panels' layout
// jumps between neighbouring facets by about the inner rule's error) or the
// G2 values pass 4e7, the rule above answers instead when its bound is the
// smaller. alpha = 0: glass 1 exactly, reflection F_avg by the rule above.
// Glass leaving the denser medium (eta < 1) comes from reciprocity: its
// transmitted part T = E_avg,glass - E_avg,reflection obeys T(eta) = eta^2
// T(1 / eta) (the BTDF's reciprocity with a G2 symmetric in its two
// directions, both Smith forms), so
//   E_avg,glass(eta) = E_avg,refl(eta) + eta^2 (E_avg,glass(1/eta) - E_avg,refl(1/eta)),
// the three by the rule above at tolerance / (1 + 2 eta^2), the bound the
// sum of theirs weighted alike (where that does not converge, the direct
// rule as well, the smaller bound kept). On the default grid the rule over
// the half vector costs 2.5 to 3.5 times as much for glass at eta < 1 as
// for reflection there, and 3 to 5 times as much as for glass at 1 / eta.
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
