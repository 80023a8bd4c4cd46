#include "lutbake/table.h"

#include <algorithm>
#include <cmath>

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
