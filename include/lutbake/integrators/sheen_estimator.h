// One-sample Monte Carlo estimators of the sheen albedo (models/sheen.h),
// sheen colour 1, F = 1:
//
//   E(mu_o) = integral over the upper hemisphere of D(h) W(mu_o, mu_i) d(omega_i),
//   W = V mu_i (SheenCosineVisibility).
//
// kCharlieLobe: h drawn from D(h) cos(theta_h) (SampleCharlieHalfVector; pdf
// with respect to solid angle of h, u in [0,1)^2), i = 2 (o.h) h - o. With
// d(omega_i) = 4 (o.h) d(omega_h),
//   E = integral of D W 4 (o.h) d(omega_h) over {h : mu_i > 0},
// so the weight is
//   w = 4 (o.h) W(mu_o, mu_i) / cos(theta_h),  0 when mu_i <= 0 or o.h <= 0:
//   charlie:   w = (o.h) / (cos(theta_h) mu_o (1 + Lambda(mu_o) + Lambda(mu_i))),
//   ashikhmin: w = ((o.h) / cos(theta_h)) mu_i / (mu_i + mu_o (1 - mu_i)).
// kUniform: i uniform on the hemisphere, pdf 1 / (2 pi) with respect to solid
// angle of i (mu_i = u0, phi = 2 pi u1), h = normalize(o + i):
//   w = 2 pi D(h) W(mu_o, mu_i),  D from the cosines and cos(phi / 2)
//   (CharlieDFromDirections, no cancellation).
// Both are unbiased: E[w] = E(mu_o).
//
// Cosine-weighted light sampling (pdf mu_i / pi) is not offered: its weight
// pi D W / mu_i grows as 1 / mu_i at the horizon, where Charlie's W tends to
// 1 / (4 mu_o (1 + Lambda(mu_o) + Lambda(0))) > 0, so its second moment
// int (D W / mu_i)^2 mu_i dmu_i diverges logarithmically: infinite variance.
//
// A proven bound of the weights. With m = mu_o + mu_i, (o.h) / cos(theta_h) =
// (1 + o.i) / m <= (1 + mu_o mu_i + s_o s_i) / m; W increases with mu_i (Lambda
// decreases; ashikhmin's derivative is mu_o / (4 (mu_i + mu_o (1 - mu_i))^2));
// D <= K dhatmax(mu_i), the value at phi = 0, which decreases with mu_i. On
// a cell [a, b] of mu_i every factor is bounded by its value at the cell's
// worse end; the largest cell bound over a partition of [0, 1] (64 uniform
// cells, the first refined 60 times geometrically) is SheenMaxWeight (times
// 1 + 1e-12 for rounding). It is finite for mu_o > 0; ashikhmin's lobe weight
// at mu_o = 0 is unbounded (1 / mu_i) and returns +inf. A sampler that
// bounds its error as lutbake's does (tables/bake.h) adds
// kUnseenEventCount * SheenMaxWeight / N for events no sample has seen.
//
// E_avg = 2 int_0^1 E(mu) mu dmu is sampled with three numbers: mu_o = u2
// uniform in (0, 1), weight 2 mu_o w(mu_o, u0, u1) (pdf 1 in mu_o). Drawing
// mu_o with density 2 mu_o instead would make the weight E's own size, and
// Charlie's E ~ C / mu_o would give that an infinite second moment; with the
// uniform draw 2 mu_o E stays bounded. (Per-sample weights still are not:
// 2 mu_o SheenMaxWeight grows like 1 / mu_o below mu_o ~ 1 / Lambda(0).)
#pragma once

#include <string_view>

#include "lutbake/models/sheen.h"

namespace lutbake {

enum class SheenStrategy { kCharlieLobe, kUniform };

// "charlie-lobe", "uniform".
std::string_view ToString(SheenStrategy strategy);

// The estimator of E at one mu_o (what every sample of a texel shares is
// computed once). Throws std::domain_error for Charlie at mu_o = 0 (E is
// infinite there) and std::invalid_argument outside alpha in (0, 1],
// mu_o in [0, 1].
class SheenAlbedoEstimator {
 public:
  SheenAlbedoEstimator(SheenVisibility visibility, double alpha, SheenStrategy strategy,
                       double mu_o);
  // The weight w of the sample u in [0,1)^2; E[w] = E(mu_o).
  double Weight(double u0, double u1) const;
  // A proven upper bound of Weight (see above).
  double MaxWeight() const;

 private:
  // W in units of 1 / 4: 4 W(mu_o, mu_i).
  double FourW(double mu_i) const;

  SheenVisibility visibility_;
  double alpha_;
  SheenStrategy strategy_;
  double mu_o_, s_o_;
  double onePlusLambda_o_ = 1.0;  // charlie
};

// SheenAlbedoEstimator(...).MaxWeight().
double SheenMaxWeight(SheenVisibility visibility, double alpha, SheenStrategy strategy,
                      double mu_o);

}  // namespace lutbake
