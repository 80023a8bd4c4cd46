// How a file stores a table's values, and the error bound of a value as
// stored. A bake computes each value in double with an integration bound;
// a file holds it rounded (to float32, float64 or half), so the bound a file
// states for a value is
//   bound + |stored - value|,
// and, when the bound itself is stored in float32, rounded up, never to
// nearest: a stated bound is never below the real distance of the stored
// value from the truth.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/table.h"

namespace lutbake {

// kUnorm8, kUnorm16: b-bit unsigned normalised integers (PNG), value
// q / (2^b - 1) with q = floor(v (2^b - 1) + 0.5): rounded to nearest, at
// most half a step 0.5 / (2^b - 1) from v for v in [0, 1] (the writers
// refuse values outside [0, 1]).
// kRgbd8: Babylon.js's RGBD (rgbd.h), the channels of a texel sharing one
// 8-bit divisor: a value's storage depends on its texel's other channels,
// so StoredBounds encodes texel by texel (StoredValue alone encodes a
// one-channel texel).
enum class ValueType { kFloat32, kFloat64, kHalf, kUnorm8, kUnorm16, kRgbd8 };

// "float32", "float64", "half", "unorm8", "unorm16", "rgbd8".
const char *ToString(ValueType type);

// The value as the storage holds it (half: rounded to float, then to
// binary16 nearest even, as the generated headers do; unorm: q / (2^b - 1)),
// widened to double.
double StoredValue(double value, ValueType type);

// The integer q a b-bit unorm stores for `value` in [0, 1] (clamped):
// floor(value (2^b - 1) + 0.5). bits is 8 or 16.
unsigned QuantizeUnorm(double value, int bits);

// The smallest float32 not below `bound`, widened to double.
double RoundUpToFloat(double bound);

// The bound of the stored value: bound + |StoredValue(value) - value|, then
// rounded up to float32 unless the storage is float64 (whose bounds are
// stored in float64 too).
double StoredBound(double value, double bound, ValueType type);

// Every stored bound of a table, in its layout; and their max and RMS.
std::vector<double> StoredBounds(const Table &table, ValueType type);
struct BoundSummary {
  double max = 0.0, rms = 0.0;
};
BoundSummary SummarizeStoredBounds(const Table &table, ValueType type);

// The table's metadata as a file of that storage states it: errorMax and
// errorRms of its stored bounds, and errorStorage (the storage they cover),
// in place of any the table carries.
std::vector<std::pair<std::string, std::string>> MetadataForStorage(const Table &table,
                                                                    ValueType type);

}  // namespace lutbake
