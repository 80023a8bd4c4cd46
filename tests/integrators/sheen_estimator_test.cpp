// The sheen Monte Carlo weights: unbiased (their mean agrees with the
// quadrature within the sample mean's own 99% error), bounded by
// SheenMaxWeight, and refused where E is infinite.
#include "lutbake/integrators/sheen_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/bake.h"

namespace lutbake {
namespace {

TEST(SheenEstimator, Names) {
  EXPECT_EQ(ToString(SheenStrategy::kCharlieLobe), "charlie-lobe");
  EXPECT_EQ(ToString(SheenStrategy::kUniform), "uniform");
}

// 2^20 samples per point and strategy from std::mt19937_64 (seed 5). The
// allowed difference is 2.576 s (two-sided 99% normal quantile times the
// standard error of the mean, from the samples' own variance) plus
// kUnseenEventCount maxWeight / N for what no sample may have seen, plus the
// quadrature's bound.
TEST(SheenEstimator, MeanMatchesQuadrature) {
  constexpr int kSamples = 1 << 20;
  struct Point {
    SheenVisibility v;
    double alpha, mu_o;
  };
  const Point points[] = {
      {SheenVisibility::kCharlie, 0.25, 0.5},  {SheenVisibility::kCharlie, 1.0, 0.1},
      {SheenVisibility::kCharlie, 0.01, 0.05}, {SheenVisibility::kAshikhmin, 0.25, 0.5},
      {SheenVisibility::kAshikhmin, 0.7, 0.9}, {SheenVisibility::kAshikhmin, 0.01, 0.05}};
  for (const Point &p : points)
    for (SheenStrategy strategy : {SheenStrategy::kCharlieLobe, SheenStrategy::kUniform}) {
      const SheenAlbedoEstimator estimator(p.v, p.alpha, strategy, p.mu_o);
      const double maxWeight = estimator.MaxWeight();
      EXPECT_EQ(maxWeight, SheenMaxWeight(p.v, p.alpha, strategy, p.mu_o));
      std::mt19937_64 rng(5);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      double sum = 0.0, sum2 = 0.0, largest = 0.0;
      for (int s = 0; s < kSamples; ++s) {
        const double w = estimator.Weight(u(rng), u(rng));
        sum += w;
        sum2 += w * w;
        largest = std::max(largest, w);
      }
      const double mean = sum / kSamples;
      const double stdError = std::sqrt(std::max(0.0, sum2 / kSamples - mean * mean) / kSamples);
      const SheenIntegral q = IntegrateSheenAlbedo(p.v, p.alpha, p.mu_o, 1e-9);
      EXPECT_NEAR(mean, q.value,
                  2.576 * stdError + kUnseenEventCount * maxWeight / kSamples + q.bound)
          << ToString(p.v) << " " << ToString(strategy) << " alpha " << p.alpha << " mu " << p.mu_o;
      EXPECT_LE(largest, maxWeight);
      // The bound is not loose by orders of magnitude: the samples come
      // within 1/4 of it for these smooth lobes.
      EXPECT_GT(largest, 0.25 * maxWeight) << ToString(p.v) << " " << ToString(strategy);
    }
}

// Every weight of a dense grid of u lies below the bound, including the
// stiff corners.
TEST(SheenEstimator, MaxWeightBoundsEveryWeight) {
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin})
    for (SheenStrategy strategy : {SheenStrategy::kCharlieLobe, SheenStrategy::kUniform})
      for (double alpha : {1.0, 0.3, 0.05, 1e-3})
        for (double mu_o : {1e-4, 0.02, 0.3, 0.8, 1.0}) {
          const SheenAlbedoEstimator e(v, alpha, strategy, mu_o);
          const double bound = e.MaxWeight();
          ASSERT_TRUE(std::isfinite(bound));
          for (int a = 0; a < 200; ++a)
            for (int b = 0; b < 100; ++b) {
              const double w = e.Weight((a + 0.5) / 200.0, (b + 0.5) / 100.0);
              ASSERT_GE(w, 0.0);
              ASSERT_LE(w, bound) << ToString(v) << " " << ToString(strategy) << " alpha " << alpha
                                  << " mu " << mu_o;
            }
        }
}

TEST(SheenEstimator, DomainErrors) {
  EXPECT_THROW(SheenAlbedoEstimator(SheenVisibility::kCharlie, 0.5, SheenStrategy::kUniform, 0.0),
               std::domain_error);
  EXPECT_THROW(SheenAlbedoEstimator(SheenVisibility::kAshikhmin, 0.0, SheenStrategy::kUniform, 0.5),
               std::invalid_argument);
  // ashikhmin's lobe weight is unbounded at grazing view; uniform's is not
  EXPECT_TRUE(std::isinf(
      SheenMaxWeight(SheenVisibility::kAshikhmin, 0.5, SheenStrategy::kCharlieLobe, 0.0)));
  EXPECT_TRUE(std::isfinite(
      SheenMaxWeight(SheenVisibility::kAshikhmin, 0.5, SheenStrategy::kUniform, 0.0)));
}

}  // namespace
}  // namespace lutbake
