// One-sample estimators of the directional albedo E(mu_o) and of the
// split-sum pair (A, B), Fresnel = 1:
//
//   E = integral over the hemisphere of f(o, i) cos(theta_i) d(omega_i),
//   f = D(h) G2(o, i) / (4 mu_o mu_i),  h = normalize(o + i),
//   B = same with the weight Fc = (1 - o.h)^5, A = E - B (with 1 - Fc).
//
// Changing variables from i to h, d(omega_i) = 4 (o.h) d(omega_h):
//   E = integral of D(h) G2 (o.h) / mu_o d(omega_h) over {h : mu_i > 0}.
//
// Visible-normal sampling, pdf D_o(h) = G1(o) (o.h) D(h) / mu_o:
//   weight = G2 / G1(o)                       (in [0, 1]; needs neither D nor the pdf)
// NDF sampling, pdf D(h) cos(theta_h):
//   weight = G2 (o.h) / (mu_o cos(theta_h))   (computed with G2 / mu_o, finite at mu_o = 0)
// In both, the light is the mirror direction i = 2 (o.h) h - o, and the
// weight is 0 when i falls below the horizon.
//
// Sampling the light direction i itself (the naive baselines of
// `lutbake report`), with f cos(theta_i) = D G2 / (4 mu_o):
// uniform hemisphere, pdf 1 / (2 pi):
//   weight = (pi / 2) D(h) G2 / mu_o
// cosine-weighted, pdf mu_i / pi:
//   weight = (pi / 4) D(h) (G2 / mu_o) / mu_i
// Both are unbiased but their weights are unbounded where D peaks (small
// alpha): they show what importance sampling buys.
#pragma once

#include <string_view>

#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

enum class SampleStrategy { kVisibleNormal, kNdf, kCosine, kUniform };

std::string_view ToString(SampleStrategy strategy);

struct AlbedoSample {
  double weight = 0.0;             // contribution to E
  double schlickWeight = 0.0;      // Fc = (1 - o.h)^5, so that B gets weight * Fc
  double schlickComplement = 0.0;  // 1 - Fc without cancellation: A gets weight * this
  double cosThetaD = 0.0;          // o.h, for other Fresnel weights (f82: (o.h) (1 - o.h)^6)
};

struct AlbedoEstimator {
  Ndf ndf;
  SmithForm smith = SmithForm::kCorrelated;
  SampleStrategy strategy = SampleStrategy::kVisibleNormal;

  // o: the view direction (ViewDirection(mu_o)); L_o = ndf.MuLambda(mu_o),
  // passed in because it depends only on the texel. u in (0,1)^2.
  AlbedoSample Sample(const Vec3 &o, double L_o, double u1, double u2) const;
};

}  // namespace lutbake
