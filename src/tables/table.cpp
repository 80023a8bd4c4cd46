#include "lutbake/tables/table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "lutbake/tables/storage.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

std::string Table::DefinitionName() const { return definition ? definition->Name() : ""; }

std::string Table::Name() const { return name.empty() ? DefinitionName() : name; }

std::string FormatDouble(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

double Axis::TexelCoordinate(double value) const {
  if (!listed()) return (value - min) / (max - min) * count - 0.5;
  // Linear in the axis value between neighbouring nodes, clamped outside.
  if (!(value > nodes.front()) || nodes.size() == 1) return 0.0;
  if (!(value < nodes.back())) return static_cast<double>(nodes.size() - 1);
  const size_t upper = static_cast<size_t>(std::upper_bound(nodes.begin(), nodes.end(), value) -
                                           nodes.begin());  // in [1, n - 1]
  const double a = nodes[upper - 1], b = nodes[upper];
  return static_cast<double>(upper - 1) + (value - a) / (b - a);
}

Axis ListedAxis(std::string name, std::vector<double> nodes) {
  Axis axis;
  axis.name = std::move(name);
  axis.min = nodes.front();
  axis.max = nodes.back();
  axis.count = static_cast<int>(nodes.size());
  axis.nodes = std::move(nodes);
  return axis;
}

std::string DescribeAxis(const Axis &axis) {
  if (axis.listed()) {
    std::string text = axis.name + " values [";
    for (size_t i = 0; i < axis.nodes.size(); ++i)
      text += (i ? ", " : "") + FormatDouble(axis.nodes[i]);
    return text + "], " + std::to_string(axis.count) + " texels";
  }
  return axis.name + " linear [" + FormatDouble(axis.min) + ", " + FormatDouble(axis.max) + "], " +
         std::to_string(axis.count) + " texels";
}

bool ParseAxisDescription(const std::string &text, Axis *axis) {
  // name, " linear [", min, ", ", max, "], ", count, " texels"
  // name, " values [", v0, ", ", v1, ..., "], ", count, " texels"
  constexpr long kMaxCount = 1 << 20;
  const size_t linear = text.find(" linear [");
  const size_t values = text.find(" values [");
  const size_t space = std::min(linear, values);
  if (space == std::string::npos || space == 0) return false;
  const char *p = text.c_str() + space + 9;
  char *end = nullptr;
  std::vector<double> numbers;
  for (;;) {
    const double v = std::strtod(p, &end);
    if (end == p || !std::isfinite(v) || numbers.size() >= static_cast<size_t>(kMaxCount))
      return false;
    numbers.push_back(v);
    if (std::strncmp(end, "], ", 3) == 0) break;
    if (std::strncmp(end, ", ", 2) != 0) return false;
    p = end + 2;
  }
  p = end + 3;
  const long count = std::strtol(p, &end, 10);
  if (end == p || std::strcmp(end, " texels") != 0 || count < 1 || count > kMaxCount) return false;
  const std::string name = text.substr(0, space);
  if (space == linear) {
    // A range whose width overflows (-1e308 to 1e308) would give every
    // lookup a NaN coordinate.
    if (numbers.size() != 2 || !(numbers[1] > numbers[0]) ||
        !std::isfinite(numbers[1] - numbers[0]))
      return false;
    *axis = LinearAxis(name, numbers[0], numbers[1], static_cast<int>(count));
    return true;
  }
  if (numbers.size() != static_cast<size_t>(count)) return false;
  for (size_t i = 1; i < numbers.size(); ++i)
    if (!(numbers[i] > numbers[i - 1])) return false;
  *axis = ListedAxis(name, std::move(numbers));
  return true;
}

double Table::MaxError() const {
  double m = 0.0;
  for (double e : errors) m = std::max(m, e);
  return m;
}

double Table::RmsError() const {
  if (errors.empty()) return 0.0;
  double sum = 0.0;
  for (double e : errors) sum += e * e;
  return std::sqrt(sum / static_cast<double>(errors.size()));
}

const std::string *Table::FindMetadata(const std::string &key) const {
  for (const auto &[k, v] : metadata)
    if (k == key) return &v;
  return nullptr;
}

Table ErrorMapOf(const Table &table) {
  Table map = table;
  // The bounds of T.exr's float32 values, rounded up to float32: the EXR
  // stores each exactly.
  map.values = StoredBounds(table, ValueType::kFloat32);
  map.errors.assign(table.errors.size(), 0.0);
  for (auto &[key, value] : map.metadata)
    if (key == "table") value = table.DefinitionName() + ".err";
  map.metadata.emplace_back("content", "per-texel error bound of " + table.DefinitionName() +
                                           " (see errorBound); same layout and channels");
  return map;
}

Table FitMapOf(const Table &table) {
  Table map = table;
  map.channels = static_cast<int>(table.fitMapNames.size());
  map.channelNames = table.fitMapNames;
  map.values = table.fitMaps;
  map.errors.assign(table.fitMaps.size(), 0.0);
  map.fitMapNames.clear();
  map.fitMaps.clear();
  for (auto &[key, value] : map.metadata)
    if (key == "table") value = table.DefinitionName() + ".fit";
  map.metadata.emplace_back("content", "per-texel measures of the fit of " +
                                           table.DefinitionName() +
                                           " (see fitErrors); same layout, one channel each");
  return map;
}

}  // namespace lutbake
