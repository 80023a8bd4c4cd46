// MaterialX (AcademySoftwareFoundation/MaterialX): the directional albedo
// table its viewer renders once on the GPU (libraries/pbrlib/genglsl/lib/
// mx_generate_albedo_table.glsl, mx_generate_dir_albedo_table; source/
// MaterialXView/Viewer.cpp ALBEDO_TABLE_SIZE = 128, RenderPipelineGL.cpp
// updateAlbedoTable into a 3-channel float framebuffer) and its shaders
// read with DIRECTIONAL_ALBEDO_METHOD 1:
//   texture($albedoTable, vec2(NdotV, alpha)).rg   (GGX: F0 x + F90 y)
//   texture($albedoTable, vec2(NdotV, roughness)).b  (Imageworks sheen)
// uv = gl_FragCoord.xy / size: texel centres, the first row at 0.5 / N.
// The y axis is the GGX alpha itself (not a perceptual roughness), and the
// sheen's roughness, which mx_imageworks_sheen_NDF takes as Charlie's r =
// alpha, clamped to >= 0.005, with the Ashikhmin (Neubelt) visibility
// 1 / (4 (NdotL + NdotV - NdotL NdotV)). GGX: height-correlated Smith
// (mx_ggx_smith_G2); x = A = E[G2 (1 - Fc) / G1], y = B = E[G2 Fc / G1].
// MaterialX's own values come from 64 samples per texel (a spherical
// Fibonacci set), which docs/presets.md measures.
#include "presets.h"

namespace lutbake {

const Preset &MaterialxPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "materialx";
    p.engine = "MaterialX";
    p.summary =
        "albedoTable.exr: 128 x 128 float32, x = NdotV, y = alpha (centres), R = A, G = B, B = "
        "Imageworks sheen albedo (Ashikhmin V, r = alpha >= 0.005), the layout of "
        "mx_generate_dir_albedo_table";
    PresetTexture t;
    t.file = "albedoTable.exr";
    t.format = "exr";
    t.axes = {CentresAxis("mu", 128), CentresAxis("roughness", 128)};
    t.channels = {{"A"}, {"B"}, {"sheen_E"}};
    t.model.smith = SmithForm::kCorrelated;
    t.model.alpha = AlphaMapping::kLinear;  // the axis holds alpha
    t.model.sheenVisibility = SheenVisibility::kAshikhmin;
    t.model.sheenAlpha = AlphaMapping::kLinear;
    t.model.sheenAlphaMin = 0.005;  // mx_imageworks_sheen_NDF: max(roughness, 0.005)
    t.sampling =
        "texture($albedoTable, vec2(NdotV, alpha)).rg (mx_ggx_dir_albedo_table_lookup); "
        "texture($albedoTable, vec2(NdotV, roughness)).b "
        "(mx_imageworks_sheen_dir_albedo_table_lookup)";
    t.source =
        "AcademySoftwareFoundation/MaterialX libraries/pbrlib/genglsl/lib/"
        "mx_generate_albedo_table.glsl, mx_microfacet_specular.glsl "
        "(mx_ggx_dir_albedo_monte_carlo, "
        "mx_ggx_smith_G2), mx_microfacet_sheen.glsl (mx_imageworks_sheen_NDF, "
        "mx_imageworks_sheen_brdf); source/MaterialXView/Viewer.cpp (ALBEDO_TABLE_SIZE), "
        "RenderPipelineGL.cpp (updateAlbedoTable)";
    t.notes =
        "float32 EXR for the viewer's light handler (setAlbedoTable) in place of the rendered "
        "table; the sheen albedo exceeds 1 toward grazing low roughness, as float holds it.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
