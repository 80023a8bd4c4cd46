// The lobe an LTC table fits, for code outside the tables layer that fits
// the same lobe over a grid of its own (a preset's texture, whose texels
// sit at an engine's coordinates rather than the table's).
#pragma once

#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// Does `table` fit a lobe (ltc_ggx, ltc_sheen, ltc_burley, ltc_oren_nayar)?
bool FitsLobe(const TableDefinition &table);
// The lobe `table` fits at its y coordinate (perceptual roughness, sheen
// roughness or sigma, as the table's axes have it) under `settings`: the
// lobe its own bake fits there. Throws std::invalid_argument for a table
// that fits no lobe.
LtcLobe FittedLobe(const TableDefinition &table, const BakeSettings &settings, double y);

}  // namespace lutbake
