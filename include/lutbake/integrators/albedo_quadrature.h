// The default integrator of E, A, B and E_avg: Gauss-Legendre product rules
// on panels placed where the integrand's singularities are, computed at two
// orders whose difference is the error bound. Deterministic; ~3400
// integrand evaluations (5 microseconds) per texel for a bound below 1e-8,
// with a real error of ~1e-11.
//
// The integral. With o = (s_o, 0, mu_o) and the half vector h at polar angle
// theta (T = tan(theta)) and azimuth phi,
//   E = (1/pi) int_0^pi dphi int_0^xi_max(phi) dxi (o.h / cos(theta)) G2 / mu_o,
// where xi is the NDF's own CDF in theta (D cos(theta) d(omega) = dxi dphi / 2pi),
// so the peak of width alpha is absorbed into the variable, and
//   o.h / cos(theta) = s_o T cos(phi) + mu_o,
//   mu_i = (2 T s_o cos(phi) + mu_o (1 - T^2)) / (1 + T^2).
// The light stays above the horizon (mu_i > 0) exactly for T below
//   T_max(phi) = (sc + sqrt(sc^2 + mu_o^2)) / mu_o,  sc = s_o cos(phi),
// so the inner integral stops there and the integrand is analytic inside.
// A and B weight it with 1 - (1 - o.h)^5 and (1 - o.h)^5; E = A + B.
//
// The inner variable (GGX). xi = x^2 / (1 + x^2) with x = t = T / alpha on
// the core [0, 1] (xi <= 1/2, two panels) and with x = w = alpha / T on the
// tail [alpha / T_max, 1]; in both dxi = 2 x / (1 + x^2)^2 dx. Where the
// tail ends at the horizon, G2 falls to 0 through a boundary layer: G2 / mu_o
// has a pole at mu_i ~ -alpha mu_o / (2 (mu_o + L_o)) (separable: -alpha/2)
// and mu Lambda branch points at |mu_i| ~ alpha; and 1 + T^2 vanishes at
// w = +-i alpha. The tail's panels are graded geometrically (ratio 2) from
// the nearest of these distances, converted to the variable, so that every
// panel sees its nearest singularity at least its own length away
// (Bernstein parameter rho >= 4.6). A first panel whose share of E is
// provably below 1e-3 of the tolerance (from a closed-form bound of the
// integrand) starts the grading instead, when it is longer; so does the
// azimuth left out when its whole inner integral is that small. Beckmann:
// t = T / alpha, dxi = 2 t exp(-t^2) dt, panels of at most 0.4 / alpha
// (1 + T^2 = 0 at t = +-i / alpha) up to min(t_max, 6.5), graded toward
// t_max the same way.
//
// The outer variable. The inner integral as a function of phi is analytic
// except where T_max is, at cos(phi) = +-i mu_o / s_o: on the line
// Re(phi) = pi/2, nearest at distance a = asinh(mu_o / s_o) (~ mu_o at
// grazing view, where the horizon swings across a width mu_o of azimuth).
// phi = pi/2 -+ a sinh(u) maps that line to Im(u) = +-pi/2 whatever mu_o,
// so uniform panels of width 1.2 in u, u in [0, asinh(pi / (2a))], give the
// same rho on every panel: 2 x 2 panels at mu_o = 0.5, 2 x 6 at mu_o = 1/256.
//
// The bound. Level k uses n_outer(k) x n_inner(k) Gauss nodes per pair of
// panels: (6, 5), (9, 8), (13, 12), (18, 17), (24, 23), except that GGX's
// tail panels, graded toward their singularities, take 7 nodes at level 1
// (measured below: every bound as it was with 8). The value is level
// k's and its bound |V_k - V_{k-1}| + 1e-10 + 3e-3 tolerance: the error of
// the coarser rule, ~rho^4 larger than that of the finer one, a floor for
// the case where the coarser rule's error happens to cross zero, and what
// the negligible first panels and azimuths may hold. Levels are added until
// the bound is at most the tolerance. Beckmann starts at level 1: its
// Lambda has an essential singularity where the light reaches the normal
// (mu_i = 1), inside the domain, and its rule converges more slowly there.
//
// Measured at level 1 (tolerance 1e-8) on 100,932 points (every texel
// centre of 32^2, 128^2 and 256^2 tables and the 580 values of tests/data,
// both Smith forms, GGX): real error at most 1.7e-11, never above 0.08 of
// the bound. With the tail's 7 nodes, against the rule's finest level, on
// A, B and E at those texel centres and 20,000 random points (mu and r down
// to ~1e-6), both Smith forms (308,832 values each): real error at most
// 1.93e-11, at most 0.094 of the bound (0.093 with 8 nodes), in 6.6% fewer
// evaluations; F82's C at 0.058 of its bound, as before. The closed-form
// azimuthal integral of GGX's D (tests) agrees
// to 5e-13 over 2120 points down to mu = r = 1/2048; tests/data's Beckmann
// values to 6.7e-10, within every bound.
#pragma once

#include <cstdint>

#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

// Added to every bound (see above).
inline constexpr double kQuadratureBoundFloor = 1e-10;
// The finest level is this minus one.
inline constexpr int kQuadratureLevels = 5;

struct SplitSumQuadrature {
  double A = 0, B = 0;
  double boundA = 0, boundB = 0, boundE = 0;  // bounds of A, B and E = A + B
  uint64_t evaluations = 0;                   // integrand evaluations, all levels
  int level = 0;                              // the level of the values
  bool converged = false;                     // the bound reached the tolerance
};

// E, A and B at mu_o in [0, 1] (mu_o = 0 is the grazing limit) for alpha in
// (0, 1]. Levels are added until boundE (split = false) or both boundA and
// boundB (split = true) are at most `tolerance`, or the finest level is done.
SplitSumQuadrature IntegrateSplitSumQuadrature(const Ndf &ndf, SmithForm smith, double mu_o,
                                               double tolerance, bool split);

// The fitted G2 that engines bake their split sums with instead of Smith's
// (engine presets, lutbake/presets/preset.h); GGX only:
//   kSchlickGgx        G1(mu) = mu / (mu (1 - k) + k), G2 = G1(mu_o) G1(mu_i),
//                      k = alpha / 2 (Karis 2013; LearnOpenGL, Godot)
//   kSmithJointApprox  G2 = 2 mu_o mu_i / (mu_i (mu_o (1 - a) + a) +
//                      mu_o (mu_i (1 - a) + a)), a = alpha (Unreal's
//                      Vis_SmithJointApprox: Heitz 2014's height-correlated
//                      form with Lambda replaced by a linear fit)
// Both are at most 1 on [0, 1]^2 and have their nearest pole off the domain
// at mu_i = -k / (1 - k) and -a mu_o / (2 mu_o (1 - a) + a), the distances
// the panels are graded by, as for the separable and correlated Smith G.
enum class FittedVisibility { kNone, kSchlickGgx, kSmithJointApprox };
SplitSumQuadrature IntegrateFittedSplitSumQuadrature(double alpha, FittedVisibility visibility,
                                                     double mu_o, double tolerance);

struct F82Quadrature {
  double C = 0, bound = 0;
  uint64_t evaluations = 0;
  int level = 0;
  bool converged = false;
};

// The F82 term of table f82: the integrand of E above weighted by
// (o.h) (1 - o.h)^6 instead of Schlick's (1 - o.h)^5, on the same panels and
// levels (the weight is a polynomial in o.h, which is analytic wherever E's
// integrand is). Bound |C_k - C_{k-1}| + 1e-10 + 3e-3 tolerance, as for B.
// mu_o in [0, 1], alpha in (0, 1].
F82Quadrature IntegrateF82Quadrature(const Ndf &ndf, SmithForm smith, double mu_o,
                                     double tolerance);

struct AverageQuadrature {
  double value = 0, bound = 0;
  uint64_t evaluations = 0;
  int level = 0;
  bool converged = false;
};

// E_avg = 2 int_0^1 E(mu) mu dmu: Gauss panels in mu graded from mu = 0
// (first panel min(alpha, 0.01), ratio 2: E's boundary layer at grazing
// has width ~alpha, mu Lambda(mu) branch points at mu = +-i alpha /
// sqrt(1 - alpha^2), and correlated E = 1 + c mu log(mu) + ... at 0), E at
// each node by the rule above; level k uses n_outer(k) nodes per mu panel
// and E at level k, and the bound is |V_k - V_{k-1}| + 1e-10 + 4e-3 tolerance.
AverageQuadrature IntegrateAverageQuadrature(const Ndf &ndf, SmithForm smith, double tolerance);

}  // namespace lutbake
