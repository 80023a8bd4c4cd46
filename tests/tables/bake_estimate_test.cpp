// EstimateBake: which texels it times, how it scales them to a table, and
// how the estimate reads. Times themselves are not asserted (they are this
// machine's); the counts and the arithmetic are.
#include "lutbake/tables/bake_estimate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

#include "lutbake/tables/bake.h"

namespace lutbake {
namespace {

EstimatedTable Default(const char *name) {
  EstimatedTable t;
  t.definition = &TableNamed(name);
  DefaultAxes(*t.definition, t.settings, &t.x, &t.y, &t.z);
  return t;
}

TEST(BakeEstimate, TimesAFewTexelsOfEachTableAndCountsThemAll) {
  const BakeEstimate e = EstimateBake({Default("E"), Default("Eavg"), Default("Favg")});
  EXPECT_EQ(e.texels, 32u * 32u + 32u + 32u);
  // At most kEstimateTexelsPerTable of each, at least one.
  EXPECT_GE(e.timedTexels, 3u);
  EXPECT_LE(e.timedTexels, 3u * kEstimateTexelsPerTable);
  EXPECT_TRUE(std::isfinite(e.cpuSeconds));
  EXPECT_GT(e.cpuSeconds, 0.0);
  EXPECT_GE(e.threads, 1);
  EXPECT_DOUBLE_EQ(e.seconds, e.cpuSeconds / e.threads);
}

TEST(BakeEstimate, AOneTexelTableIsTimedOnce) {
  EstimatedTable t = Default("Eavg");
  t.x = LinearAxis(t.x.name, 0.5, 0.5, 1);
  const BakeEstimate e = EstimateBake({t});
  EXPECT_EQ(e.texels, 1u);
  EXPECT_EQ(e.timedTexels, 1u);
}

TEST(BakeEstimate, ATableOverItsBudgetStopsAfterOneTexel) {
  // A budget of 0 s: the first texel is always timed, the second never.
  const BakeEstimate e = EstimateBake({Default("E"), Default("dfg")}, 0.0);
  EXPECT_EQ(e.timedTexels, 2u);
  EXPECT_EQ(e.texels, 32u * 32u + 128u * 128u);
}

TEST(BakeEstimate, SpreadsTheTimedTexelsOverEveryAxis) {
  // Evenly spread flat indices of a 16^3 table would all sit at i = 0; the
  // Latin hypercube visits a distinct value of each axis with each texel.
  EstimatedWork w;
  w.counts[0] = w.counts[1] = w.counts[2] = 16;
  std::set<int> is, js, ks;
  w.evaluateTexel = [&](int i, int j, int k) {
    ASSERT_TRUE(i >= 0 && i < 16 && j >= 0 && j < 16 && k >= 0 && k < 16);
    is.insert(i);
    js.insert(j);
    ks.insert(k);
  };
  const BakeEstimate e = EstimateWork({w});
  EXPECT_EQ(e.timedTexels, static_cast<size_t>(kEstimateTexelsPerTable));
  EXPECT_EQ(e.texels, 4096u);
  EXPECT_EQ(is.size(), static_cast<size_t>(kEstimateTexelsPerTable));
  EXPECT_EQ(js.size(), static_cast<size_t>(kEstimateTexelsPerTable));
  EXPECT_EQ(ks.size(), static_cast<size_t>(kEstimateTexelsPerTable));
}

TEST(BakeEstimate, ACallThatComputesSeveralTexelsCountsEachOnce) {
  // One call computes 4 texels: the per-texel cost is its time / 4, so the
  // estimate of 8 texels is twice the time of one call, not eight times.
  EstimatedWork w;
  w.counts[0] = 8;
  w.texelsPerCall = 4;
  int calls = 0;
  double busy = 0.0;
  w.evaluateTexel = [&](int, int, int) {
    ++calls;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 0.01) {
    }
    busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const BakeEstimate e = EstimateWork({w}, 1.0);
  ASSERT_EQ(calls, 8);
  // cpuSeconds = (time of the 8 calls) / (8 x 4) x 8 texels: at least the
  // busy time / 4 (the loop's own overhead only adds).
  EXPECT_GE(e.cpuSeconds, busy / 4.0);
  EXPECT_LT(e.cpuSeconds, busy);
}

TEST(BakeEstimate, ATexelThatTimesItselfCountsItsOwnSeconds) {
  // timeTexel reports 0.125 s a texel whatever its call took (the untimed
  // warm-up of an LTC texel): 2 texels timed of 16 within the 0.25 s budget,
  // the estimate 16 x 0.125 exactly; evaluateTexel is not called.
  EstimatedWork w;
  w.counts[0] = 4;
  w.counts[1] = 4;
  int calls = 0;
  w.timeTexel = [&](int, int, int) {
    ++calls;
    return 0.125;
  };
  w.evaluateTexel = [](int, int, int) { throw std::logic_error("not called"); };
  const BakeEstimate e = EstimateWork({w}, 0.25);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(e.timedTexels, 2u);
  EXPECT_EQ(e.cpuSeconds, 16 * 0.125);
}

TEST(BakeEstimate, ReadsInSecondsOrMinutes) {
  BakeEstimate e;
  e.threads = 2;
  e.texels = 5120;
  e.timedTexels = 16;
  e.seconds = 0.4;
  EXPECT_EQ(DescribeEstimate(e), "under a second on 2 threads (16 of 5120 texels timed)");
  e.seconds = 11.6;
  EXPECT_EQ(DescribeEstimate(e), "about 12 s on 2 threads (16 of 5120 texels timed)");
  e.seconds = 600.0;
  e.threads = 1;
  e.texels = e.timedTexels = 1;
  EXPECT_EQ(DescribeEstimate(e), "about 10 min on 1 thread (1 of 1 texel timed)");
}

}  // namespace
}  // namespace lutbake
