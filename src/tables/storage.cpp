#include "lutbake/tables/storage.h"

#include <Imath/half.h>

#include <cmath>
#include <limits>

#include "lutbake/tables/rgbd.h"

namespace lutbake {

const char *ToString(ValueType type) {
  switch (type) {
    case ValueType::kFloat32: return "float32";
    case ValueType::kFloat64: return "float64";
    case ValueType::kHalf: return "half";
    case ValueType::kUnorm8: return "unorm8";
    case ValueType::kUnorm16: return "unorm16";
    case ValueType::kRgbd8: return "rgbd8";
  }
  return "?";
}

double StoredValue(double value, ValueType type) {
  switch (type) {
    case ValueType::kFloat32: return static_cast<double>(static_cast<float>(value));
    case ValueType::kFloat64: return value;
    case ValueType::kHalf:
      return static_cast<double>(static_cast<float>(Imath::half(static_cast<float>(value))));
    case ValueType::kUnorm8: return QuantizeUnorm(value, 8) / 255.0;
    case ValueType::kUnorm16: return QuantizeUnorm(value, 16) / 65535.0;
    case ValueType::kRgbd8: {
      const RgbdTexel texel = RgbdEncode(&value, 1);
      return RgbdDecode(texel.rgb[0], texel.d);
    }
  }
  return value;
}

unsigned QuantizeUnorm(double value, int bits) {
  const double top = static_cast<double>((1u << bits) - 1u);
  // !(value > 0) also sends NaN to 0; the writers refuse NaN before this.
  if (!(value > 0.0)) return 0;
  if (value >= 1.0) return static_cast<unsigned>(top);
  return static_cast<unsigned>(std::floor(value * top + 0.5));
}

double RoundUpToFloat(double bound) {
  float f = static_cast<float>(bound);
  if (static_cast<double>(f) < bound) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return static_cast<double>(f);
}

double StoredBound(double value, double bound, ValueType type) {
  const double total = bound + std::abs(StoredValue(value, type) - value);
  if (type == ValueType::kFloat64) return total;
  // The sum is rounded to nearest in double, a relative 1.1e-16: far inside
  // the slack of any integration bound (the quadrature's has a floor of 1e-10).
  return RoundUpToFloat(total);
}

std::vector<double> StoredBounds(const Table &table, ValueType type) {
  std::vector<double> bounds(table.values.size());
  if (type == ValueType::kRgbd8) {
    // Texel by texel: the channels share the divisor.
    const size_t channels = static_cast<size_t>(table.channels);
    for (size_t t = 0; t + channels <= bounds.size(); t += channels) {
      const RgbdTexel texel = RgbdEncode(&table.values[t], table.channels);
      for (size_t c = 0; c < channels; ++c) {
        const double moved = std::abs(RgbdDecode(texel.rgb[c], texel.d) - table.values[t + c]);
        bounds[t + c] =
            RoundUpToFloat((t + c < table.errors.size() ? table.errors[t + c] : 0.0) + moved);
      }
    }
    return bounds;
  }
  for (size_t i = 0; i < bounds.size(); ++i)
    bounds[i] = StoredBound(table.values[i], i < table.errors.size() ? table.errors[i] : 0.0, type);
  return bounds;
}

BoundSummary SummarizeStoredBounds(const Table &table, ValueType type) {
  BoundSummary s;
  double sum = 0.0;
  const std::vector<double> bounds = StoredBounds(table, type);
  for (double b : bounds) {
    s.max = std::max(s.max, b);
    sum += b * b;
  }
  if (!bounds.empty()) s.rms = std::sqrt(sum / static_cast<double>(bounds.size()));
  return s;
}

std::vector<std::pair<std::string, std::string>> MetadataForStorage(const Table &table,
                                                                    ValueType type) {
  const BoundSummary s = SummarizeStoredBounds(table, type);
  std::vector<std::pair<std::string, std::string>> out;
  bool placed = false;
  const auto summary = [&] {
    out.emplace_back("errorMax", FormatDouble(s.max));
    out.emplace_back("errorRms", FormatDouble(s.rms));
    out.emplace_back("errorStorage", ToString(type));
    placed = true;
  };
  for (const auto &entry : table.metadata) {
    if (entry.first == "errorMax" || entry.first == "errorRms" || entry.first == "errorStorage")
      continue;
    out.push_back(entry);
    if (entry.first == "errorBound") summary();
  }
  if (!placed) summary();
  return out;
}

}  // namespace lutbake
