// Bounds of stored values: each covers the integration bound and the
// rounding of its storage, and a float32 bound is rounded up, never down.
#include "lutbake/tables/storage.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lutbake/core/hash.h"

namespace lutbake {
namespace {

TEST(Storage, RoundUpToFloatIsTheSmallestFloatNotBelow) {
  RandomStream random(3);
  for (int i = 0; i < 100000; ++i) {
    const double b = std::ldexp(random.NextDouble(), -static_cast<int>(random.NextBits() % 40));
    const double up = RoundUpToFloat(b);
    EXPECT_GE(up, b);
    EXPECT_EQ(up, static_cast<double>(static_cast<float>(up)));  // a float32
    // The float32 below it is below b.
    EXPECT_LT(static_cast<double>(std::nextafter(static_cast<float>(up), 0.0f)), b);
  }
  EXPECT_EQ(RoundUpToFloat(0.0), 0.0);
  EXPECT_EQ(RoundUpToFloat(0.5), 0.5);
}

TEST(Storage, StoredBoundCoversTheRoundingOfEveryStorage) {
  RandomStream random(5);
  for (int i = 0; i < 100000; ++i) {
    const double value = random.NextDouble();
    const double bound = 1e-9 * random.NextDouble();
    for (ValueType type : {ValueType::kFloat32, ValueType::kHalf, ValueType::kFloat64}) {
      const double stored = StoredValue(value, type);
      const double b = StoredBound(value, bound, type);
      // Any truth within `bound` of the computed value is within b of the
      // stored one (the sum taken in extended precision).
      EXPECT_GE(static_cast<long double>(b),
                static_cast<long double>(bound) +
                    std::abs(static_cast<long double>(stored) - static_cast<long double>(value)))
          << ToString(type);
    }
    // float32 rounds to nearest: at most half an ulp, 2^-25 below 1.
    EXPECT_LE(std::abs(StoredValue(value, ValueType::kFloat32) - value), 0x1p-25);
    // Half storage rounds the float32 to binary16: twice, so half an ulp of
    // each (2^-12 + 2^-25 below 1).
    EXPECT_LE(std::abs(StoredValue(value, ValueType::kHalf) - value), 0x1p-12 + 0x1p-25);
    EXPECT_EQ(StoredBound(value, bound, ValueType::kFloat64), bound);
  }
}

TEST(Storage, MetadataStatesTheBoundsOfItsStorage) {
  Table t;
  t.x = LinearAxis("mu", 0.0, 1.0, 3);
  t.y = LinearAxis("", 0.0, 1.0, 1);
  t.values = {0.1, 0.7, 1.0 / 3.0};
  t.errors = {1e-9, 2e-9, 3e-9};
  t.metadata = {{"table", "E"}, {"errorBound", "text"}, {"errorMax", "stale"}, {"seed", "0"}};
  const auto m = MetadataForStorage(t, ValueType::kFloat32);
  ASSERT_EQ(m.size(), 6u);
  EXPECT_EQ(m[1].first, "errorBound");
  EXPECT_EQ(m[2].first, "errorMax");
  EXPECT_EQ(std::strtod(m[2].second.c_str(), nullptr),
            SummarizeStoredBounds(t, ValueType::kFloat32).max);
  EXPECT_EQ(m[3].first, "errorRms");
  EXPECT_EQ(m[4], (std::pair<std::string, std::string>{"errorStorage", "float32"}));
  EXPECT_EQ(m[5].first, "seed");
  // 1/3 in float32 is 0.33333334326..., 9.9e-9 away: the bound says so.
  EXPECT_GE(SummarizeStoredBounds(t, ValueType::kFloat32).max, 3e-9 + 9.9e-9);
  EXPECT_EQ(SummarizeStoredBounds(t, ValueType::kFloat64).max, 3e-9);
}

}  // namespace
}  // namespace lutbake
