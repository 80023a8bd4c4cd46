// Unity HDRP: _PreIntegratedFGD_GGXDisneyDiffuse, rendered at run time
// (Runtime/Material/PreIntegratedFGD/preIntegratedFGD_GGXDisneyDiffuse.shader,
// FGDTEXTURE_RESOLUTION = 64, A2B10G10R10_UNorm) and read by
// GetPreIntegratedFGDGGXAndDisneyDiffuse (PreIntegratedFGD.hlsl) at
//   Remap01ToHalfTexelCoord(float2(sqrt(NdotV), perceptualRoughness), 64)
// that is at texel edges: texel i holds sqrt(NdotV) = i / 63, texel j
// perceptualRoughness j / 63, the first row at 0. Channels: x = B, y = E
// (specularFGD = lerp(x, y, F0); energy compensation 1 / y - 1), z = the
// Disney diffuse albedo - 0.5 (diffuseFGD = z + 0.5). Exact
// height-correlated Smith (V_SmithJointGGX), alpha = perceptualRoughness^2.
#include "presets.h"

namespace lutbake {

const Preset &UnityHdrpPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "unity-hdrp";
    p.engine = "Unity HDRP";
    p.summary =
        "PreIntegratedFGD_GGXDisneyDiffuse.exr: 64 x 64, x = sqrt(NdotV), y = "
        "perceptualRoughness (edges), B, E, Disney diffuse - 0.5; "
        "PreIntegratedFGD_CharlieFabricLambert.exr: Charlie B / 2 pi, E / 2 pi, fabric Lambert";
    PresetTexture t;
    t.file = "PreIntegratedFGD_GGXDisneyDiffuse.exr";
    t.format = "exr";
    PresetAxis mu = EdgesAxis("mu", 64);
    mu.mapping = PresetMapping::kSquare;
    t.axes = {mu, EdgesAxis("roughness", 64)};
    PresetChannel diffuse{"disney_diffuse"};
    diffuse.offset = -0.5;
    t.channels = {{"B"}, {"E"}, diffuse};
    t.model.smith = SmithForm::kCorrelated;
    t.sampling =
        "SAMPLE_TEXTURE2D_LOD(_PreIntegratedFGD_GGXDisneyDiffuse, s_linear_clamp_sampler, "
        "Remap01ToHalfTexelCoord(float2(sqrt(NdotV), perceptualRoughness), "
        "FGDTEXTURE_RESOLUTION), 0).xyz";
    t.source =
        "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/"
        "Material/PreIntegratedFGD/PreIntegratedFGD.hlsl, PreIntegratedFGD.cs.hlsl, "
        "preIntegratedFGD_GGXDisneyDiffuse.shader; ShaderLibrary/BSDF.hlsl (DisneyDiffuseNoPI)";
    t.notes =
        "float32 EXR; HDRP renders this texture into A2B10G10R10_UNorm (quantisation 1/2046 "
        "more).";
    // The Charlie sheen and fabric Lambert (preIntegratedFGD_CharlieFabricLambert.shader,
    // GetPreIntegratedFGDCharlieAndFabricLambert): texel centres of (NdotV,
    // perceptualRoughness), x = B / 2 pi, y = E / 2 pi (the shader multiplies by 2 pi:
    // specularFGD = lerp(x, y, F0) 2 pi), z = FabricLambert = 1 - alpha / 2; Charlie D with
    // V_Charlie (no terminator softening, as glTF's), alpha = perceptualRoughness^2.
    PresetTexture charlie;
    charlie.file = "PreIntegratedFGD_CharlieFabricLambert.exr";
    charlie.format = "exr";
    charlie.axes = {CentresAxis("mu", 64), CentresAxis("roughness", 64)};
    const double inverseTwoPi = 0.15915494309189533577;
    PresetChannel b{"sheen_B"}, e{"sheen_E"};
    b.scale = e.scale = inverseTwoPi;
    charlie.channels = {b, e, {"fabric_lambert"}};
    charlie.model.sheenVisibility = SheenVisibility::kCharlie;
    charlie.model.sheenAlpha = AlphaMapping::kSquared;
    charlie.sampling =
        "SAMPLE_TEXTURE2D_LOD(_PreIntegratedFGD_CharlieAndFabric, s_linear_clamp_sampler, "
        "float2(NdotV, perceptualRoughness), 0).xyz";
    charlie.source =
        "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/"
        "Material/PreIntegratedFGD/PreIntegratedFGD.hlsl, "
        "preIntegratedFGD_CharlieFabricLambert.shader; ShaderLibrary/BSDF.hlsl (D_CharlieNoPI, "
        "V_Charlie, FabricLambertNoPI)";
    charlie.notes = "float32 EXR; x and y are divided by 2 pi as HDRP stores them.";
    p.textures = {t, charlie};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
