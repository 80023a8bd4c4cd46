#include "lutbake/integrators/sobol.h"

#include <gtest/gtest.h>

#include <vector>

namespace lutbake {
namespace {

// Every elementary interval [a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), ...) of area
// 2^-m holds exactly one of the first 2^m points: the (0, m, 2)-net property,
// which Owen scrambling preserves.
void ExpectNet(int m, uint32_t seed0, uint32_t seed1, bool scrambled) {
  const uint32_t n = 1u << m;
  for (int k = 0; k <= m; ++k) {
    std::vector<int> count(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
      uint32_t x = SobolBits(i, 0), y = SobolBits(i, 1);
      if (scrambled) {
        x = OwenScramble(x, seed0);
        y = OwenScramble(y, seed1);
      }
      const uint32_t cx = k == 0 ? 0 : x >> (32 - k);
      const uint32_t cy = m - k == 0 ? 0 : y >> (32 - (m - k));
      ++count[(cx << (m - k)) | cy];
    }
    for (uint32_t c = 0; c < n; ++c) ASSERT_EQ(count[c], 1) << "m=" << m << " k=" << k;
  }
}

TEST(Sobol, FirstTwoDimensionsFormZeroMTwoNets) {
  for (int m = 1; m <= 10; ++m) ExpectNet(m, 0, 0, false);
}

TEST(Sobol, ScramblingPreservesTheNet) {
  for (int m = 1; m <= 10; ++m) ExpectNet(m, 0x9e3779b9u * m, 0x85ebca6bu + m, true);
}

TEST(Sobol, HigherDimensionsAreStratifiedInOneDimension) {
  // Each dimension alone is a (0, m, 1)-net: the first 2^m points fall one per
  // interval of width 2^-m.
  for (int d = 0; d < kSobolDimensions; ++d) {
    std::vector<int> count(256, 0);
    for (uint32_t i = 0; i < 256; ++i) ++count[SobolBits(i, d) >> 24];
    for (int c : count) ASSERT_EQ(c, 1) << "dimension " << d;
  }
}

TEST(Sobol, ScrambledPointsAreUniformOnAverage) {
  // Over many seeds, the mean of a scrambled point is 1/2 (each point of an
  // Owen-scrambled set is uniform on [0, 1)). 4096 seeds: the standard error
  // of the mean is 1 / sqrt(12 * 4096) = 0.0045; allow 5 of them.
  double sum = 0.0;
  for (uint32_t seed = 0; seed < 4096; ++seed) sum += ScrambledSobol(5, 1, seed * 2654435761u);
  EXPECT_NEAR(sum / 4096.0, 0.5, 5 * 0.0045);
}

}  // namespace
}  // namespace lutbake
