// RGBD (rgbd.h): the encoder's texel against a brute force over every
// divisor and every byte, its decode against Babylon's formula, and its
// refusals and clamp.
#include "lutbake/tables/rgbd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace lutbake {
namespace {

double Decode(int q, int d) { return std::pow(q / 255.0, 2.2) / (d / 255.0); }

// min over d of max over c of min over q |Decode(q, d) - v_c|.
double BruteForce(const double *v, int channels) {
  double best = 1e300;
  for (int d = 1; d <= 255; ++d) {
    double texel = 0.0;
    for (int c = 0; c < channels; ++c) {
      double channel = 1e300;
      for (int q = 0; q <= 255; ++q) channel = std::min(channel, std::abs(Decode(q, d) - v[c]));
      texel = std::max(texel, channel);
    }
    best = std::min(best, texel);
  }
  return best;
}

TEST(Rgbd, DecodeIsBabylonsFromRgbd) {
  EXPECT_DOUBLE_EQ(RgbdDecode(255, 255), 1.0);
  EXPECT_DOUBLE_EQ(RgbdDecode(255, 1), 255.0);
  EXPECT_EQ(RgbdDecode(0, 7), 0.0);
  EXPECT_NEAR(RgbdDecode(128, 64), std::pow(128 / 255.0, 2.2) * 255 / 64, 1e-15);
}

// Random texels of one to three values over [0, 1], [0, 40] and small
// values: the encoder's error is the brute force's minimum, and is what
// the chosen bytes decode to.
TEST(Rgbd, EncoderFindsTheSmallestError) {
  std::mt19937_64 random(20261126);
  for (int trial = 0; trial < 60; ++trial) {
    const int channels = 1 + trial % 3;
    const double top = trial % 4 == 0 ? 40.0 : trial % 4 == 1 ? 0.02 : 1.0;
    std::uniform_real_distribution<double> value(0.0, top);
    double v[3] = {value(random), value(random), value(random)};
    const RgbdTexel texel = RgbdEncode(v, channels);
    double error = 0.0;
    for (int c = 0; c < channels; ++c)
      error =
          std::max(error, std::abs(RgbdDecode(texel.rgb[static_cast<size_t>(c)], texel.d) - v[c]));
    EXPECT_EQ(error, texel.error);
    // Equal up to the rounding of the two decodes (values up to 40: 1e-14).
    EXPECT_LE(texel.error, BruteForce(v, channels) + 1e-12) << trial;
    EXPECT_GE(texel.d, 1);
  }
}

TEST(Rgbd, RefusesNegativeAndNanAndClampsAbove255) {
  const double negative[1] = {-1e-9};
  EXPECT_THROW(RgbdEncode(negative, 1), std::invalid_argument);
  const double nan[1] = {std::nan("")};
  EXPECT_THROW(RgbdEncode(nan, 1), std::invalid_argument);
  const double large[2] = {300.0, 1.0};
  const RgbdTexel texel = RgbdEncode(large, 2);
  EXPECT_EQ(texel.d, 1);
  EXPECT_EQ(texel.rgb[0], 255);
  EXPECT_NEAR(texel.error, 45.0, 1e-9);
  EXPECT_THROW(RgbdEncode(large, 4), std::invalid_argument);
}

}  // namespace
}  // namespace lutbake
