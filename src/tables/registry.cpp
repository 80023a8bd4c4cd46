// The registry: every table lutbake bakes, once. A new table is a new file
// in this folder (its TableDefinition), a line in definitions.h and a line
// here; nothing else lists tables.
#include <stdexcept>

#include "definitions.h"

namespace lutbake {

const std::vector<const TableDefinition *> &AllTables() {
  // clang-format off
  static const std::vector<const TableDefinition *> tables = {
      &DirectionalAlbedoTable(),
      &AverageAlbedoTable(),
      &FresnelAverageTable(),
      &SplitSumTable(),
      &F82Table(),
      &SheenAlbedoTable(),
      &SheenAverageAlbedoTable(),
      &GlassAlbedoTable(),
      &GlassAverageAlbedoTable(),
      &SpecularAlbedoTable(),
      &SpecularAverageAlbedoTable(),
      &OrenNayarAlbedoTable(),
      &OrenNayarFullAlbedoTable(),
      &BurleyAlbedoTable(),
      &LtcGgxTable(),
      &LtcSheenTable(),
      &LtcBurleyTable(),
      &LtcOrenNayarTable(),
  };
  // clang-format on
  return tables;
}

const TableDefinition *FindTable(std::string_view name) {
  for (const TableDefinition *table : AllTables())
    if (name == table->Name()) return table;
  return nullptr;
}

const TableDefinition &TableNamed(std::string_view name) {
  if (const TableDefinition *table = FindTable(name)) return *table;
  throw std::invalid_argument("no table named '" + std::string(name) + "'; the tables are " +
                              TableNameList());
}

std::string TableNameList() {
  std::string list;
  for (const TableDefinition *table : AllTables())
    list += (list.empty() ? "" : ", ") + std::string(table->Name());
  return list;
}

}  // namespace lutbake
