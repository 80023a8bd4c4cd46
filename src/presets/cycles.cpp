// Blender Cycles: the albedo tables of intern/cycles/scene/shader.tables,
// read by lookup_table_read_2D / _1D (intern/cycles/kernel/tables.h) at
// texel edges, x (i / (N - 1)) first: table_ggx_E[32 * 32] at x = rough, y
// = mu, and table_ggx_Eavg[32] at x = rough, both clamped to >= 1e-4 by the
// generator, GGX at alpha = rough^2, height-correlated Smith (used by
// microfacet_ggx_preserve_energy: 1 / E and Kulla-Conty's F_ms). Cycles'
// own values come from 2^23 (E) and 2^26 (E_avg) samples, printed to 6
// decimals; these are exact, printed to float precision.
#include "presets.h"

namespace lutbake {

const Preset &CyclesPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "cycles";
    p.engine = "Blender Cycles";
    p.summary =
        "table_ggx_E.h (32 x 32: x = rough, y = mu), table_ggx_Eavg.h (32): C float arrays at "
        "texel edges, as shader.tables declares them";
    PresetTexture e;
    e.file = "table_ggx_E.h";
    e.format = "c-array";
    PresetAxis rough = EdgesAxis("roughness", 32), mu = EdgesAxis("mu", 32);
    rough.lowest = 1e-4;
    mu.lowest = 1e-4;
    e.axes = {rough, mu};
    e.channels = {{"E"}};
    e.model.visibility = PresetVisibility::kCorrelated;
    e.sampling = "lookup_table_read_2D(kg, rough, mu, kernel_data.tables.ggx_E, 32, 32)";
    e.source =
        "blender/cycles src/scene/shader.tables (table_ggx_E), src/kernel/tables.h "
        "(lookup_table_read_2D), src/kernel/closure/bsdf_microfacet.h "
        "(microfacet_ggx_preserve_energy)";
    PresetTexture avg = e;
    avg.file = "table_ggx_Eavg.h";
    avg.axes = {rough};
    avg.channels = {{"Eavg"}};
    avg.sampling = "lookup_table_read(kg, rough, kernel_data.tables.ggx_Eavg, 32)";
    avg.source = "blender/cycles src/scene/shader.tables (table_ggx_Eavg)";
    p.textures = {e, avg};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
