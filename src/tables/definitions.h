// The table definitions, one per file in this folder; registry.cpp lists
// them. Private to the tables layer.
#pragma once

#include "lutbake/tables/table_definition.h"

namespace lutbake {

const TableDefinition &DirectionalAlbedoTable();      // E.cpp
const TableDefinition &AverageAlbedoTable();          // Eavg.cpp
const TableDefinition &FresnelAverageTable();         // Favg.cpp
const TableDefinition &SplitSumTable();               // dfg.cpp
const TableDefinition &F82Table();                    // f82.cpp
const TableDefinition &SheenAlbedoTable();            // sheen_E.cpp
const TableDefinition &SheenAverageAlbedoTable();     // sheen_Eavg.cpp
const TableDefinition &GlassAlbedoTable();            // glass_E.cpp
const TableDefinition &GlassAverageAlbedoTable();     // glass_Eavg.cpp
const TableDefinition &SpecularAlbedoTable();         // spec_E.cpp
const TableDefinition &SpecularAverageAlbedoTable();  // spec_Eavg.cpp
const TableDefinition &OrenNayarAlbedoTable();        // oren_nayar_E.cpp
const TableDefinition &OrenNayarFullAlbedoTable();    // oren_nayar_E.cpp
const TableDefinition &BurleyAlbedoTable();           // burley_E.cpp
const TableDefinition &LtcGgxTable();                 // ltc_ggx.cpp
const TableDefinition &LtcSheenTable();               // ltc_sheen.cpp
const TableDefinition &LtcBurleyTable();              // ltc_burley.cpp
const TableDefinition &LtcOrenNayarTable();           // ltc_oren_nayar.cpp

}  // namespace lutbake
