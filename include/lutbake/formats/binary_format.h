// The .bin table format, version 1. Little-endian throughout; every field at
// a fixed offset so that it can be read without lutbake (docs/formats.md,
// "The .bin format", has the same table and a 10-line Python reader).
//
//   offset size  type      field
//   0      8     char[8]   magic "LUTBAKE\0"
//   8      4     u32       format version (1)
//   12     4     u32       data offset D: where the values start (a multiple of 8)
//   16     4     u32       dimensions (1 or 2)
//   20     4     u32       width  = texel count of axis x
//   24     4     u32       height = texel count of axis y (1 for a 1D table)
//   28     4     u32       channels (1, or 2 for dfg: A then B)
//   32     4     u32       value type (1 = IEEE-754 float32, 2 = float64)
//   36     4     u32       flags (bit 0: an error block follows the values)
//   40     48    axis x    char[24] name (UTF-8, NUL-padded), f64 min, f64 max,
//                          u32 count, u32 mapping (0 = linear, texel centres:
//                          texel i at min + (max - min) (i + 0.5) / count;
//                          1 = listed: texel i at the i-th of the axis's
//                          node values, see below)
//   88     48    axis y    same; name empty for a 1D table
//   136    4     u32       metadata length M in bytes
//   140    M     char[M]   metadata, UTF-8 lines "key=value\n" (EXR attributes)
//   140+M  8 n   f64[n]    node values of axis x when its mapping is 1 (n = its
//                          count, increasing), then those of axis y when its
//                          mapping is 1; nothing for linear axes
//   ...          zero padding up to D
//   D      S W H C         values, [y][x][channel], y = 0 first; S = 4 bytes
//                          for float32, 8 for float64
//   D+SWHC S W H C         error bounds of the stored values, same type and
//                          layout (when flags bit 0 is set); in float32 they
//                          are rounded up, so each covers the float32 rounding
//                          of its value as well
#pragma once

#include <string>

#include "lutbake/tables/table.h"

namespace lutbake {

inline constexpr char kBinaryMagic[8] = {'L', 'U', 'T', 'B', 'A', 'K', 'E', '\0'};
inline constexpr uint32_t kBinaryVersion = 1;
// 3D tables (glass_E(mu, r, eta)): version 2, the same fields with axis z
// (48 bytes, as the others) at offset 136, so that the metadata length is at
// 184 and the metadata at 188; dimensions 3; node values of listed axes x,
// then y, then z; values [z][y][x][channel]. 1D and 2D tables stay
// version 1, byte for byte.
inline constexpr uint32_t kBinaryVersion3D = 2;
inline constexpr uint32_t kBinaryFloat32 = 1;  // value type field
inline constexpr uint32_t kBinaryFloat64 = 2;

// Reads a .bin file back into a Table (values and errors as stored,
// widened to double). Throws IoError on a malformed or unreadable file.
Table ReadBinaryTable(const std::string &path);

}  // namespace lutbake
