// Blender Cycles: the albedo tables of src/scene/shader.tables
// (blender/cycles@97dbe6f5 = blender/blender intern/cycles/scene/), read by
// lookup_table_read, _2D and _3D (src/kernel/util/lookup_table.h) at texel
// edges, x (i / (N - 1)) first, then y, then z: index (iz ny + iy) nx + ix.
// GGX at alpha = rough^2, height-correlated Smith for reflection and
// transmission (G2 = 1 / (1 + Lambda_i + Lambda_o),
// src/kernel/closure/bsdf_microfacet.h). The generator
// (src/app/cycles_precompute.cpp) clamps rough and mu to >= 1e-4 and the IOR
// coordinate z to [1e-4, 0.99].
//
//   table_ggx_E[32 x 32]        x = rough, y = mu                  E
//   table_ggx_Eavg[32]          x = rough                          E_avg
//   table_ggx_glass_E[16^3]     x = rough, y = mu, z: ior          glass_E(mu, r, ior)
//   table_ggx_glass_Eavg[16^2]  x = rough, y = z: ior              glass_Eavg(r, ior)
//   table_ggx_glass_inv_E, _inv_Eavg: the same at eta = 1 / ior (the view
//                               inside the glass)
//
// The IOR axis: z = sqrt(|(ior - 1) / (ior + 1)|), the generator's ior =
// ior_from_F0(z^4) = (1 + z^2) / (1 - z^2) (1.0089 at z = 1/15, 99.503 at
// z = 0.99). microfacet_ggx_preserve_energy reads 1 / E (and Kulla-Conty's
// F_ms from E_avg) for GGX reflection and glass, the Huang hair model 1 /
// glass_E. At ior = 1 (slice 0; the clamp z >= 1e-4 gives ior = 1 + 2e-8,
// 1.0f in Cycles' float) Cycles' microfacet closure is a pass-through, no
// rough lobe (bsdf_microfacet.h: fabsf(m_eta - 1.0f) < 1e-4f), and its
// table holds ~1 there; the preset writes 1. The shipped inverse tables
// were baked in 2023 by a sampler that kept refracted rays ending on the
// wrong side of the surface (tests/data/glass/README.md: up to +0.93); the
// preset writes the albedo today's sampler needs, not that defect. Cycles'
// own values come from 2^23 (E) and 2^26 (E_avg) samples printed to 6
// decimals; these are integrated to 1e-8 and printed to round-trip float32.
#include <cmath>

#include "presets.h"

namespace lutbake {

namespace {

// The generator's clamped coordinate as the axis quantity: rough or mu at
// edges, clamped to >= 1e-4.
PresetAxis ClampedEdges(const char *quantity, int count) {
  PresetAxis axis = EdgesAxis(quantity, count);
  axis.lowest = 1e-4;
  return axis;
}

// The IOR axis: 16 slices at z = k / 15 clamped to [1e-4, 0.99], the
// quantity (1 + z^2) / (1 - z^2) clamped to the IORs of those ends as the
// generator computes them in float: ior_from_F0(z^4) = (1 + sqrt(F0)) / (1 -
// sqrt(F0)), 99.5026932 at z = 0.99f (99.5025126 in exact arithmetic at z =
// 0.99; the slices between are at most a float ulp of z from k / 15).
PresetAxis IorAxis(const char *quantity) {
  PresetAxis axis = EdgesAxis(quantity, 16);
  axis.mapping = PresetMapping::kIorOfF0Root4;
  const auto iorOf = [](float z) {
    const float f0 = z * z * z * z, root = std::sqrt(f0);
    return static_cast<double>((1.0f + root) / (1.0f - root));
  };
  axis.lowest = iorOf(1e-4f);
  axis.highest = iorOf(0.99f);
  return axis;
}

PresetTexture CyclesTable(const std::string &name, std::vector<PresetAxis> axes,
                          const char *meaning, const std::string &sampling) {
  PresetTexture t;
  t.file = name + ".h";
  t.format = "c-array";
  t.axes = std::move(axes);
  t.channels = {{meaning}};
  t.model.smith = SmithForm::kCorrelated;
  if (std::string(meaning).rfind("glass", 0) == 0) t.model.unitEtaWindow = 1e-4;
  t.sampling = sampling;
  t.source = "blender/cycles src/scene/shader.tables (" + name +
             "), src/kernel/util/lookup_table.h, src/kernel/closure/bsdf_microfacet.h "
             "(microfacet_ggx_preserve_energy), src/app/cycles_precompute.cpp";
  return t;
}

}  // namespace

const Preset &CyclesPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "cycles";
    p.engine = "Blender Cycles";
    p.summary =
        "table_ggx_E.h (32 x 32), table_ggx_Eavg.h (32), table_ggx_glass_E.h and "
        "table_ggx_glass_inv_E.h (16^3), table_ggx_glass_Eavg.h and table_ggx_glass_inv_Eavg.h "
        "(16 x 16): C float arrays at texel edges, as shader.tables declares them";
    const PresetAxis rough = ClampedEdges("roughness", 32), mu = ClampedEdges("mu", 32);
    const PresetAxis rough16 = ClampedEdges("roughness", 16), mu16 = ClampedEdges("mu", 16);
    p.textures.push_back(
        CyclesTable("table_ggx_E", {rough, mu}, "E",
                    "lookup_table_read_2D(kg, rough, mu, kernel_data.tables.ggx_E, 32, 32)"));
    p.textures.push_back(CyclesTable("table_ggx_Eavg", {rough}, "Eavg",
                                     "lookup_table_read(kg, rough, kernel_data.tables.ggx_Eavg, "
                                     "32)"));
    const std::string z = ", z = sqrtf(fabsf((ior - 1) / (ior + 1)))";
    const auto read3D = [&](const std::string &table) {
      return "lookup_table_read_3D(kg, rough, mu, z, kernel_data.tables." + table +
             ", 16, 16, 16)" + z;
    };
    const auto read2D = [&](const std::string &table) {
      return "lookup_table_read_2D(kg, rough, z, kernel_data.tables." + table + ", 16, 16)" + z;
    };
    p.textures.push_back(CyclesTable("table_ggx_glass_E", {rough16, mu16, IorAxis("eta")},
                                     "glass_E", read3D("ggx_glass_E")));
    p.textures.push_back(CyclesTable("table_ggx_glass_Eavg", {rough16, IorAxis("eta")},
                                     "glass_Eavg", read2D("ggx_glass_Eavg")));
    p.textures.push_back(CyclesTable("table_ggx_glass_inv_E", {rough16, mu16, IorAxis("1/eta")},
                                     "glass_E", read3D("ggx_glass_inv_E")));
    p.textures.push_back(CyclesTable("table_ggx_glass_inv_Eavg", {rough16, IorAxis("1/eta")},
                                     "glass_Eavg", read2D("ggx_glass_inv_Eavg")));
    p.textures[4].notes = p.textures[5].notes =
        "The view is inside the glass (ior < 1: Cycles reads this table at 1 / ior). Cycles' "
        "shipped table was baked in 2023 by a sampler that kept refracted rays ending on the "
        "wrong side of the surface (up to +0.93); this is the albedo today's sampler needs.";
    for (size_t t = 2; t < 6; ++t)
      p.textures[t].notes +=
          std::string(p.textures[t].notes.empty() ? "" : " ") +
          "Slice 0 (ior = 1) holds 1: there Cycles' closure passes light straight through "
          "(|eta - 1| < 1e-4), with no lobe to compensate.";
    return p;
  }();
  return preset;
}

}  // namespace lutbake
