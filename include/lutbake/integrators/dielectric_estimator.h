// One-sample Monte Carlo estimators of the rough-dielectric albedo
// (models/dielectric.h), reflection only or reflection plus transmission.
//
// E(mu_o) = E_{h ~ D_o}[w(h)] with the visible-normal density
// D_o(h) = G1(o) max(0, o.h) D(h) / mu_o (pdf with respect to solid angle
// of h; Ndf::SampleVisibleNormal, u in [0,1)^2), and the facet weight
//   w(h) = F(c) G2(o, i_r)/G1(o) 1{mu_r > 0} + (1 - F(c)) G2(o, i_t)/G1(o) 1{mu_t < 0}
// (the second term only with transmission), c = o.h. This is the expected
// value over the standard sampler's choice (reflect with probability F,
// refract otherwise; models/dielectric.h SampleDielectric), so it has the
// same mean and no more variance, and needs no third number.
//
// A proven bound of the weights: G2 / G1(o) <= 1 for both Smith forms
// (correlated: mu_i (mu_o + L_o) / (mu_o mu_i + mu_i L_o + mu_o L_i) <= 1
// as mu_o L_i >= 0; separable: G1(i) <= 1), and F + (1 - F) = 1, so
// 0 <= w <= 1: DielectricMaxWeight = 1, for every alpha, mu_o and eta. The
// sampler's unseen-event term (tables/sampled_texel.h) is then
// kUnseenEventCount / N.
//
// E_avg = 2 int_0^1 E(mu) mu dmu is sampled with three numbers: mu_o = u2
// uniform in [0, 1) (pdf 1), weight 2 mu_o w(mu_o, u0, u1), which lies in
// [0, 2): DielectricAverageMaxWeight = 2.
#pragma once

#include "lutbake/models/dielectric.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

inline constexpr double kDielectricMaxWeight = 1.0;
inline constexpr double kDielectricAverageMaxWeight = 2.0;

// The estimator of E at one mu_o (what every sample shares is computed
// once). Throws std::invalid_argument outside alpha in (0, 1], mu_o in
// (0, 1], eta in [1/128, 128].
class DielectricAlbedoEstimator {
 public:
  DielectricAlbedoEstimator(NdfKind ndf, SmithForm smith, DielectricLobes lobes, double alpha,
                            double mu_o, double eta);
  // The weight w of the sample u in [0,1)^2; E[w] = E(mu_o), 0 <= w <= 1.
  double Weight(double u0, double u1) const;
  double MaxWeight() const { return kDielectricMaxWeight; }

 private:
  Ndf ndf_;
  SmithForm smith_;
  DielectricLobes lobes_;
  double eta_;
  Vec3 o_;
  double L_o_;
};

// The E_avg estimator: weight 2 u2 w(u2, u0, u1), E[weight] = E_avg, in [0, 2].
class DielectricAverageEstimator {
 public:
  DielectricAverageEstimator(NdfKind ndf, SmithForm smith, DielectricLobes lobes, double alpha,
                             double eta);
  double Weight(double u0, double u1, double u2) const;
  double MaxWeight() const { return kDielectricAverageMaxWeight; }

 private:
  Ndf ndf_;
  SmithForm smith_;
  DielectricLobes lobes_;
  double eta_;
};

}  // namespace lutbake
