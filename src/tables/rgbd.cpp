// RGBD encoding (rgbd.h): every divisor, the two bracketing bytes of each
// channel, the smallest max-norm error.
#include "lutbake/tables/rgbd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lutbake {

namespace {

// (q / 255)^2.2 for q = 0..255: the linear value of each byte, increasing.
const std::array<double, 256> &LinearOfByte() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int q = 0; q < 256; ++q) t[static_cast<size_t>(q)] = std::pow(q / 255.0, 2.2);
    return t;
  }();
  return table;
}

}  // namespace

double RgbdDecode(unsigned char q, unsigned char d) {
  return LinearOfByte()[q] * 255.0 / static_cast<double>(d);
}

RgbdTexel RgbdEncode(const double *values, int channels) {
  if (channels < 1 || channels > 3)
    throw std::invalid_argument("RGBD holds one to three values a texel");
  for (int c = 0; c < channels; ++c)
    if (!(values[c] >= 0.0))
      throw std::invalid_argument("RGBD holds values >= 0 (a value is negative or NaN)");
  const std::array<double, 256> &linear = LinearOfByte();
  RgbdTexel best;
  best.error = std::numeric_limits<double>::infinity();
  // d from 255 down, a strictly smaller error replacing: ties keep the larger d.
  for (int d = 255; d >= 1; --d) {
    RgbdTexel texel;
    texel.d = static_cast<unsigned char>(d);
    for (int c = 0; c < channels && texel.error < best.error; ++c) {
      // The byte whose linear value is the first at or above v d / 255,
      // and the one below it: the decoded value is monotone in q, so the
      // nearest is one of the two.
      const double target = values[c] * d / 255.0;
      const int above =
          static_cast<int>(std::lower_bound(linear.begin(), linear.end(), target) - linear.begin());
      double channelError = std::numeric_limits<double>::infinity();
      for (int q : {above - 1, above}) {
        if (q < 0 || q > 255) continue;
        const double e = std::abs(RgbdDecode(static_cast<unsigned char>(q), texel.d) - values[c]);
        if (e < channelError) {
          channelError = e;
          texel.rgb[static_cast<size_t>(c)] = static_cast<unsigned char>(q);
        }
      }
      texel.error = std::max(texel.error, channelError);
    }
    if (texel.error < best.error) best = texel;
  }
  return best;
}

}  // namespace lutbake
