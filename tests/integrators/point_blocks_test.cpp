// Point blocks: the shared, cached Sobol blocks hold exactly the scrambled
// Sobol points of sobol.h (and the random ones the counter-based stream),
// with the azimuth's cosine and sine as the scalar samplers compute them.
#include "lutbake/integrators/point_blocks.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lutbake/core/hash.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/sobol.h"

namespace lutbake {
namespace {

TEST(PointBlocks, SobolBlocksAreTheScrambledSobolPoints) {
  PointBlockStorage scratch;
  for (int dims : {2, 3})
    for (int r : {0, 5})
      for (uint64_t block : {0u, 1u, 37u}) {
        const uint64_t seed = 12345;
        const PointView v = PointBlock(PointSet::kScrambledSobol, seed, dims, r, block, &scratch);
        ASSERT_EQ(v.n, kPointBlockSize);
        for (size_t k = 0; k < v.n; k += 7) {
          const uint32_t i = static_cast<uint32_t>(block * kPointBlockSize + k);
          for (int d = 0; d < dims; ++d) {
            const uint32_t s = static_cast<uint32_t>(
                HashValues({seed, static_cast<uint64_t>(r), static_cast<uint64_t>(d)}));
            EXPECT_EQ(v.u[d][k], ScrambledSobol(i, d, s)) << dims << " " << r << " " << i;
          }
          EXPECT_EQ(v.cosPhi[k], std::cos(2.0 * kPi * v.u[dims - 2][k]));
          EXPECT_EQ(v.sinPhi[k], std::sin(2.0 * kPi * v.u[dims - 2][k]));
        }
        // Asked again, the same (cached) points.
        const PointView again =
            PointBlock(PointSet::kScrambledSobol, seed, dims, r, block, &scratch);
        EXPECT_EQ(again.u[0][kPointBlockSize - 1], v.u[0][kPointBlockSize - 1]);
      }
}

TEST(PointBlocks, RandomBlocksAreTheCounterBasedStream) {
  PointBlockStorage scratch;
  const PointView v = PointBlock(PointSet::kIndependentRandom, 99, 2, 3, 2, &scratch);
  for (size_t k = 0; k < v.n; k += 11)
    for (int d = 0; d < 2; ++d) {
      const uint64_t s = HashValues({99, 3, static_cast<uint64_t>(d)});
      EXPECT_EQ(v.u[d][k],
                (static_cast<double>(MixBits(s + MixBits(2 * kPointBlockSize + k)) >> 11) + 0.5) *
                    0x1p-53);
    }
}

}  // namespace
}  // namespace lutbake
