// The innermost loop of the rough-dielectric panel quadrature
// (dielectric_quadrature.cpp) for GGX: the facet weight of
// DielectricFacetWeight (models/dielectric.h) at a batch of facets,
// vectorised with Highway and dispatched at run time to the widest
// instruction set the processor has (AVX-512, AVX2, SSE4, ... or scalar).
//
// Each lane computes its facet alone with the same correctly rounded
// operations (additions, multiplications, divisions, square roots, min and
// max; nothing fused: -ffp-contract=off), so the weights, and the sums the
// caller forms from them in a fixed order, are the same bits on every
// instruction set and thread count.
#pragma once

#include <cstddef>

#include "lutbake/models/dielectric.h"
#include "lutbake/models/smith.h"

namespace lutbake::kernel {

// What the facets of one texel share (GGX).
struct DielectricConstants {
  double alpha = 1.0;
  double eta = 1.5;
  double mu_o = 1.0;
  double L_o = 0.0;      // mu_o Lambda(mu_o)
  double invNorm = 1.0;  // 1 / (mu_o + L_o)
  SmithForm smith = SmithForm::kCorrelated;
  DielectricLobes lobes = DielectricLobes::kReflectionAndTransmission;
};

// w[k] = the facet weight at the facet with c = o.h = c[k], h.z = hz[k] and
// the mirror's mu_r = muR[k] (the caller's stable forms), for k < n:
//   F(c) G2(o, i_r)/G1(o) [mu_r > 0] + (1 - F(c)) G2(o, i_t)/G1(o) [mu_t < 0]
// (the second term with transmission only), at most 1; 0 where c <= 0.
// F and 1 - F as DielectricFresnel writes them, mu_t = ((c - W) h.z - mu_o)
// / eta with c - W = (1 - eta^2) / (c + W), G2 / G1 and Lambda as smith.h and
// ggx.h write them (the two divisions by the Fresnel denominators' squares
// shared by r and t; -mu_t and both G2 / G1 kept as numerator over
// denominator, so that one division gives the weight, and in
// DielectricTerms the whole term). Agrees with DielectricFacetWeight to a
// few ulps.
void DielectricWeights(const DielectricConstants &constants, const double *c, const double *hz,
                       const double *muR, size_t n, double *w);

// The quadrature's terms at the nodes of one azimuth (sc = s_o cos(phi)):
// node k at the variable v[k] with rule weight x jacobian ruleJac[k] gives
//   terms[k] = ruleJac[k] (measure w),  measure = (c / cos(theta)) d(xi)/dv / (mu_o + L_o),
// in GGX's core variable x = T / alpha (tail = false: T = alpha x, cos(theta)
// = 1 / sqrt(1 + T^2), sin(theta) = T cos(theta), measure numerator (sc T +
// mu_o) 2 x / (1 + x^2)^2) or its tail variable w = alpha / T (tail = true:
// r = sqrt(w^2 + alpha^2), cos(theta) = w / r, sin(theta) = alpha / r,
// numerator 2 c r / (1 + w^2)^2), c = sc sin(theta) + mu_o cos(theta),
// mu_r = 2 c cos(theta) - mu_o and w the facet weight above.
void DielectricTerms(const DielectricConstants &constants, double sc, bool tail, const double *v,
                     const double *ruleJac, size_t n, double *terms);

// What the nodes of one azimuth arc of the average's rule share
// (dielectric_average.cpp, GGX): the two cosines mu_o = a + ka cos(psi) and
// mu_i = (b + kb cos(psi)) invDivisor along it, alpha^2 and the Smith form.
struct ArcConstants {
  double alpha2 = 1.0;
  SmithForm smith = SmithForm::kCorrelated;
  double a = 1.0, ka = 0.0, b = 1.0, kb = 0.0, invDivisor = 1.0;
};

// The arc's terms at nodes v[k] = tan(psi / 2) with rule weights ruleW[k]:
//   q = 1 / (1 + v^2), cos(psi) = (1 - v^2) q,
//   terms[k] = (ruleW[k] q) G2(mu_o, mu_i),
// each cosine clamped to at most 1, 0 unless both are positive. G2 is
// smith.h's for GGX, with L = mu Lambda(mu) = s / d, s = alpha^2 (1 - mu^2),
// d = 2 (sqrt(mu^2 + s) + mu) (ggx.h), multiplied through by d_o d_i:
//   correlated: mu_o mu_i d_o d_i / (mu_o mu_i d_o d_i + mu_i s_o d_i + mu_o s_i d_o),
//   separable:  (mu_o d_o)(mu_i d_i) / ((mu_o d_o + s_o)(mu_i d_i + s_i)),
// with every cosine and length scaled by 1 + v^2 (G2 is homogeneous of
// degree 0 in them; cos(psi) = (1 - v^2) / (1 + v^2)), so that one division
// takes q as well: one division a node, not four.
// The same bits on every instruction set as ArcTermScalar.
void ArcTerms(const ArcConstants &constants, const double *v, const double *ruleW, size_t n,
              double *terms);
double ArcTermScalar(const ArcConstants &constants, double v, double ruleW);

// The same, one facet at a time in plain C++ (the reference the vector
// lanes are tested against, and the weights the kernel's lanes reproduce).
double DielectricWeightScalar(const DielectricConstants &constants, double c, double hz,
                              double muR);

}  // namespace lutbake::kernel
