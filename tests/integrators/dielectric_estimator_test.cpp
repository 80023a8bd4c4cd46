// The rough-dielectric Monte Carlo weights: unbiased (their mean agrees
// with the quadrature within 4 standard errors of the mean, from the
// samples' own variance, plus kUnseenEventCount maxWeight / N for what no
// sample may have seen, plus the quadrature's bound), within their proven
// maximum, and the standard sampler (choosing reflection or refraction by
// F) has the same mean.
#include "lutbake/integrators/dielectric_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/tables/settings.h"

namespace lutbake {
namespace {

constexpr auto kGlass = DielectricLobes::kReflectionAndTransmission;

struct Moments {
  double mean = 0.0, stdError = 0.0, largest = 0.0;
};

template <typename F>
Moments Sample(int n, uint64_t seed, const F &weight) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double sum = 0.0, sum2 = 0.0;
  Moments m;
  for (int k = 0; k < n; ++k) {
    const double w = weight(u(rng), u(rng), u(rng));
    sum += w;
    sum2 += w * w;
    m.largest = std::max(m.largest, w);
  }
  m.mean = sum / n;
  m.stdError = std::sqrt(std::max(0.0, sum2 / n - m.mean * m.mean) / n);
  return m;
}

TEST(DielectricEstimator, MeanMatchesQuadrature) {
  constexpr int kSamples = 1 << 19;
  struct Point {
    NdfKind kind;
    SmithForm smith;
    DielectricLobes lobes;
    double alpha, mu_o, eta;
  };
  const Point points[] = {
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.25, 0.5, 1.5},
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.3, 1.0 / 1.5},
      {NdfKind::kGgx, SmithForm::kSeparable, DielectricLobes::kReflection, 0.1, 0.8, 1.0 / 1.33},
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.01, 0.05, 2.42},
      {NdfKind::kBeckmann, SmithForm::kCorrelated, kGlass, 0.3, 0.7, 1.0 / 2.42},
      {NdfKind::kBeckmann, SmithForm::kSeparable, kGlass, 0.8, 0.2, 1.33},
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.3, 0.5, 1.0},
      // The ends of the accepted range and Cycles' last IOR slice (99.503).
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.6, kMaxRelativeIor},
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.6, kMinRelativeIor},
      {NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.36, 0.2, 1.0 / 99.502693},
  };
  for (const Point &p : points) {
    const DielectricAlbedoEstimator e(p.kind, p.smith, p.lobes, p.alpha, p.mu_o, p.eta);
    const Moments m =
        Sample(kSamples, 5, [&](double u0, double u1, double) { return e.Weight(u0, u1); });
    const DielectricIntegral q =
        IntegrateDielectricAlbedo(p.kind, p.smith, p.lobes, p.alpha, p.mu_o, p.eta, 1e-9);
    const double allowed =
        4.0 * m.stdError + kUnseenEventCount * e.MaxWeight() / kSamples + q.bound;
    EXPECT_NEAR(m.mean, q.value, allowed)
        << ToString(p.kind) << " eta " << p.eta << " mu " << p.mu_o << " alpha " << p.alpha;
    EXPECT_LE(m.largest, e.MaxWeight());
    // The standard sampler: reflection or refraction chosen by F.
    const Ndf ndf{p.kind, p.alpha};
    const Vec3 o = ViewDirection(p.mu_o);
    const Moments s = Sample(kSamples, 6, [&](double u0, double u1, double u2) {
      return SampleDielectric(ndf, p.smith, p.lobes, p.eta, o, u0, u1, u2).weight;
    });
    EXPECT_NEAR(s.mean, q.value, 4.0 * s.stdError + kUnseenEventCount / kSamples + q.bound);
    // The expected weight never has more variance than the choice.
    EXPECT_LE(m.stdError, s.stdError * 1.05);
  }
}

TEST(DielectricEstimator, AverageMatchesQuadrature) {
  constexpr int kSamples = 1 << 19;
  for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable}) {
    const DielectricAverageEstimator e(NdfKind::kGgx, smith, kGlass, 0.25, 1.5);
    const Moments m =
        Sample(kSamples, 9, [&](double u0, double u1, double u2) { return e.Weight(u0, u1, u2); });
    const DielectricIntegral q =
        IntegrateDielectricAverage(NdfKind::kGgx, smith, kGlass, 0.25, 1.5, 1e-7);
    EXPECT_NEAR(m.mean, q.value,
                4.0 * m.stdError + kUnseenEventCount * e.MaxWeight() / kSamples + q.bound);
    EXPECT_LE(m.largest, e.MaxWeight());
  }
}

TEST(DielectricEstimator, RefusesBadArguments) {
  EXPECT_THROW(
      DielectricAlbedoEstimator(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.0, 0.5, 1.5),
      std::invalid_argument);
  EXPECT_THROW(
      DielectricAlbedoEstimator(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.0, 1.5),
      std::invalid_argument);
  EXPECT_THROW(DielectricAlbedoEstimator(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.5,
                                         kMaxRelativeIor * 1.01),
               std::invalid_argument);
  EXPECT_THROW(DielectricAlbedoEstimator(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 0.5,
                                         kMinRelativeIor * 0.99),
               std::invalid_argument);
}

}  // namespace
}  // namespace lutbake
