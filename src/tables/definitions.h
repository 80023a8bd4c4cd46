// The table definitions, one per file in this folder; registry.cpp lists
// them. Private to the tables layer.
#pragma once

#include "lutbake/tables/table_definition.h"

namespace lutbake {

const TableDefinition &DirectionalAlbedoTable();   // E.cpp
const TableDefinition &AverageAlbedoTable();       // Eavg.cpp
const TableDefinition &FresnelAverageTable();      // Favg.cpp
const TableDefinition &SplitSumTable();            // dfg.cpp
const TableDefinition &SheenAlbedoTable();         // sheen_E.cpp
const TableDefinition &SheenAverageAlbedoTable();  // sheen_Eavg.cpp
const TableDefinition &F82Table();                 // f82.cpp

}  // namespace lutbake
