// Unreal Engine 4 and 5: the split-sum environment BRDF PreIntegratedGF,
// built on the CPU at start-up (Engine/Source/Runtime/Renderer/Private/
// SystemTextures.cpp) as a 128 x 32 PF_G16R16 texture and read by
// EnvBRDF (Engine/Shaders/Private/BRDF.ush) as
//   PreIntegratedGF.SampleLevel(PreIntegratedGFSampler, float2(NoV, Roughness), 0).rg
// with R = A, G = B (F0 A + saturate(50 F0.g) B): texel centres, the first
// row at Roughness = 0.5 / 32 (D3D: v = 0 is the first row). The model is
// GGX at alpha = Roughness^2 with Vis_SmithJointApprox(a = alpha), which
// the generator sums over 128 samples; here the same integral, exact.
#include "presets.h"

namespace lutbake {

const Preset &UnrealPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "unreal";
    p.engine = "Unreal Engine 4/5";
    p.summary =
        "PreIntegratedGF.png: 128 x 32 16-bit, x = NoV, y = Roughness (centres), R = A, G = B, "
        "Vis_SmithJointApprox";
    PresetTexture t;
    t.file = "PreIntegratedGF.png";
    t.format = "png16";
    t.axes = {CentresAxis("mu", 128), CentresAxis("roughness", 32)};
    t.channels = {{"A"}, {"B"}};
    t.model.fitted = FittedVisibility::kSmithJointApprox;
    t.sampling =
        "PreIntegratedGF.SampleLevel(PreIntegratedGFSampler, float2(NoV, Roughness), 0).rg";
    t.source =
        "EpicGames/UnrealEngine Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp "
        "(PreintegratedGF: 128 x 32, PF_G16R16), Engine/Shaders/Private/BRDF.ush (EnvBRDF, "
        "Vis_SmithJointApprox)";
    t.notes =
        "16-bit RGB PNG: R = A, G = B, B = 0, top row = Roughness 0.5 / 32 (UE's first row). UE "
        "4.0-era builds used Schlick-GGX k = alpha / 2 and 8 bits: see the godot preset for "
        "that model.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
