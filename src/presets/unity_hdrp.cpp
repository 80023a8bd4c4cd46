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
        "perceptualRoughness (edges), B, E, Disney diffuse - 0.5";
    PresetTexture t;
    t.file = "PreIntegratedFGD_GGXDisneyDiffuse.exr";
    t.format = "exr";
    PresetAxis mu = EdgesAxis("mu", 64);
    mu.mapping = PresetMapping::kSquare;
    t.axes = {mu, EdgesAxis("roughness", 64)};
    PresetChannel diffuse{"disney_diffuse"};
    diffuse.offset = -0.5;
    t.channels = {{"B"}, {"E"}, diffuse};
    t.model.visibility = PresetVisibility::kCorrelated;
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
        "more). The Charlie + fabric texture is not in this preset yet.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
