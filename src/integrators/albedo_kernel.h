// The innermost loop of the panel quadrature (albedo_quadrature.cpp): the
// split-sum integrand of GGX at a batch of half-vector nodes, summed,
// vectorised with Highway and dispatched at run time to the widest
// instruction set the processor has (AVX-512, AVX2, SSE4, ... or scalar).
//
// The result does not depend on the instruction set: additions,
// multiplications, divisions and square roots are correctly rounded in IEEE
// double at any vector width, nothing is fused (the library is built with
// -ffp-contract=off), and the sum is taken in 8 partial sums (node i into
// sum i mod 8, whatever the width) added in a fixed order at the end. So the
// tables are bit-identical on every processor, thread count and compiler.
#pragma once

#include <cstddef>

#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/models/smith.h"

namespace lutbake::kernel {

// What the nodes of one texel share.
struct GgxSplitSumConstants {
  double alpha = 1.0;
  double mu_o = 1.0;  // = cos(theta_o)
  double L_o = 0.0;   // mu_o Lambda(mu_o)
  SmithForm smith = SmithForm::kCorrelated;
  // A fitted G2 in place of Smith's (albedo_quadrature.h, FittedVisibility),
  // with its parameter: Schlick-GGX's k, or the joint approximation's alpha.
  FittedVisibility fitted = FittedVisibility::kNone;
  double fitParameter = 0.0;
};

// A batch of panels of one kind (core or tail) and one Gauss rule: panel p
// covers [from[p], from[p] + width[p]] in the variable x, at the azimuth of
// sc[p] = s_o cos(phi), with weight scale[p] (outer weight x width). Its node
// i is x = from + width rule_x[i], with weight scale rule_w[i].
struct Panels {
  const double *from, *width, *sc, *scale;
  size_t n;
};

// At x, the half vector is at tan(theta) = T, T = alpha x (core panels) or
// alpha / x (tail = true). With dxi = 2 x / (1 + x^2)^2 dx (the GGX measure
// D cos(theta) d(omega) in either variable), the integrand of E in the
// measure dx is
//   f(x) = 2 x / (1 + x^2)^2  (o.h / cos(theta))  G2 / mu_o,
//   o.h / cos(theta) = sc T + mu_o,  o.h = (sc T + mu_o) / sqrt(1 + T^2),
//   mu_i = (2 T sc + mu_o (1 - T^2)) / (1 + T^2),
// and zero where mu_i <= 0 (the light below the horizon). Returns the sums
// over every node of every panel
//   sums[0] = sum weight f(x) (1 - (1 - o.h)^5)   (A),
//   sums[1] = sum weight f(x) (1 - o.h)^5         (B).
// The nodes must have x > 0. Panel p goes into partial sum p mod 8.
void SumGgxSplitSum(const GgxSplitSumConstants &constants, bool tail, int ruleNodes,
                    const double *ruleX, const double *ruleW, const Panels &panels, double sums[2]);

// The same sums[0] and sums[1], bit for bit, and the F82 term (table f82)
//   sums[2] = sum weight f(x) (o.h) (1 - o.h)^6    (C).
// (A separate entry point, so that E and dfg do not pay for C.)
void SumGgxSplitSumF82(const GgxSplitSumConstants &constants, bool tail, int ruleNodes,
                       const double *ruleX, const double *ruleW, const Panels &panels,
                       double sums[3]);

// The per-azimuth set-up of GGX's inner panels (albedo_quadrature.cpp,
// InnerPanels), for every azimuth of one texel and level at once. What the
// texel shares:
struct GgxAzimuthConstants {
  double alpha = 1.0;
  double mu_o = 1.0;
  double muL_o = 1.0;  // mu_o + L_o
  double d_mu = 0.0;   // the distance of G2 / mu_o's nearest singularity from mu_i = 0
  double negligibleMass = 0.0;
};
// What each azimuth j needs (kind[j]):
enum AzimuthKind : int {
  kAzimuthNone = 0,       // no light above the horizon, or a negligible share
  kAzimuthCore = 1,       // the core graded toward end = t_max (t_max <= 1)
  kAzimuthTail = 2,       // the core, and the tail from end = w_min graded from first
  kAzimuthTailHypot = 3,  // the same, its first panel still to take hypot(w_min, alpha)
                          // into account: first = FirstPanel(min(g2, hypot), lengthForMass)
  kAzimuthTailAll = 4,    // mu_o = 0: the core, and the tail from 0
};
// In: n azimuths (a multiple of 8; padding with T_max = -1 gives kAzimuthNone)
// with sc = s_o cos(phi), T_max, |dmu_i/dT| at T_max and |sc| T_max + mu_o.
// Out: kind, first (the first graded panel), end (t_max or w_min), and for
// kAzimuthTailHypot G2's distance g2 and lengthForMass. Every value is the
// same IEEE double the scalar expressions of InnerPanels give.
void GgxAzimuthSetup(const GgxAzimuthConstants &constants, size_t n, const double *sc,
                     const double *T_max, const double *slope, const double *boundNumerator,
                     int *kind, double *first, double *end, double *g2, double *lengthForMass);

// The cuts of n gradings toward lo at once (albedo_quadrature.cpp,
// PushGraded with hi = 1): range j is [lo[j], 1], its first graded panel
// first[j]. With length = 1 - lo and first raised to length 2^-60 where
// positive, a range with 0 < first < length gets cuts c_1 = first,
// c_k = c_(k-1) + first ratio^(k-1) while c_k < length, at most maxCuts - 1 of
// them, the last dropped when what follows it is under half the piece
// before; cuts[(k - 1) n + j] = c_k for k = 1 ... count[j]. n is a multiple of
// 8; the same doubles as PushGraded's loop.
void GradedCutsTowardLo(size_t n, const double *lo, const double *first, double ratio, int maxCuts,
                        double *cuts, int *count);

}  // namespace lutbake::kernel
