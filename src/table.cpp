#include "lutbake/table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lutbake {

const char *TableName(TableKind kind) {
  switch (kind) {
    case TableKind::kE: return "E";
    case TableKind::kEavg: return "Eavg";
    case TableKind::kFavg: return "Favg";
    case TableKind::kDfg: return "dfg";
  }
  return "?";
}

std::string FormatDouble(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string DescribeAxis(const Axis &axis) {
  return axis.name + " linear [" + FormatDouble(axis.min) + ", " + FormatDouble(axis.max) + "], " +
         std::to_string(axis.count) + " texels";
}

bool ParseAxisDescription(const std::string &text, Axis *axis) {
  // name, " linear [", min, ", ", max, "], ", count, " texels"
  const size_t space = text.find(" linear [");
  if (space == std::string::npos || space == 0) return false;
  const char *p = text.c_str() + space + 9;
  char *end = nullptr;
  const double lo = std::strtod(p, &end);
  if (end == p || std::strncmp(end, ", ", 2) != 0) return false;
  p = end + 2;
  const double hi = std::strtod(p, &end);
  if (end == p || std::strncmp(end, "], ", 3) != 0) return false;
  p = end + 3;
  const long count = std::strtol(p, &end, 10);
  if (end == p || std::strcmp(end, " texels") != 0) return false;
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi > lo) || count < 1 || count > (1 << 20))
    return false;
  *axis = Axis{text.substr(0, space), lo, hi, static_cast<int>(count)};
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
  map.values = table.errors;
  map.errors.assign(table.errors.size(), 0.0);
  for (auto &[key, value] : map.metadata)
    if (key == "table") value = std::string(TableName(table.kind)) + ".err";
  map.metadata.emplace_back("content", "per-texel error bound of " +
                                           std::string(TableName(table.kind)) +
                                           " (see errorBound); same layout and channels");
  return map;
}

}  // namespace lutbake
