// RGBD: Babylon.js's 8-bit encoding of values above 1 (its BRDF lookup
// textures, its environment maps). A texel of up to three values v_c is
// stored as four bytes (q_r, q_g, q_b, d), d >= 1, and read back by the
// shader's fromRGBD (Babylon.js helperFunctions.fx, with the engine's
// default useExactSrgbConversions = false, so toLinearSpace is pow 2.2):
//   value_c = (q_c / 255)^2.2 / (d / 255).
// One divisor serves the whole texel: the largest value sets how small d
// may be (value <= 255 / d), and a smaller d spreads the 8-bit steps of the
// small values over a finer range. Babylon's own toRGBD takes d = floor(255
// / max v) (clamped to [1, 255]); that is the finest divisor that keeps the
// largest value in range, not the one with the smallest error (the rounding
// of q_c in gamma space is coarser near 1 than near 0). RgbdEncode tries
// every d from 1 to 255 and, for each, the two bytes q_c that bracket
// (v_c d / 255)^(1 / 2.2) 255, and keeps the pair with the smallest
// max_c |value_c - v_c|: the best the encoding allows, exactly.
#pragma once

#include <array>

namespace lutbake {

struct RgbdTexel {
  std::array<unsigned char, 3> rgb{};  // q_c; unused channels 0
  unsigned char d = 255;               // the divisor's byte, 1..255
  double error = 0.0;                  // max_c |RgbdDecode(c) - v_c|
};

// (q / 255)^2.2 / (d / 255), the value fromRGBD reads.
double RgbdDecode(unsigned char q, unsigned char d);

// The texel of `channels` (1 to 3) values that decodes closest to them (in
// the max norm over channels; ties to the larger d, then the smaller q).
// Values below 0 or NaN are refused (std::invalid_argument); values above
// 255, the largest the encoding holds, are stored as 255 and the error says
// by how much.
RgbdTexel RgbdEncode(const double *values, int channels);

}  // namespace lutbake
