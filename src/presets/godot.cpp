// Godot 4.5+ (Forward+): the DFG texture built by the compute shader
// servers/rendering/renderer_rd/shaders/environment/integrate_dfg.glsl
// (128 x 128 R16G16_SFLOAT) and read in scene_forward_clustered.glsl as
//   textureLod(sampler2D(dfg, SAMPLER_LINEAR_CLAMP), vec2(NoV, 1.0 - roughness), 0.0).rg
// R = B, G = E (specular = (f90 - f0) x + f0 y; energy compensation 1 +
// f0 (1 / E - 1)), GGX at alpha = roughness^2 with Schlick-GGX's separable
// G, k = alpha / 2 (LearnOpenGL's integrator). Texel centres; since v = 1 -
// roughness, the first row in memory is roughness 1 - 0.5 / 128.
// One stored revision of the generator evaluates row y at (N - y + 0.5) /
// N, one texel off from what the shader samples; this preset holds what
// the shader samples.
#include "presets.h"

namespace lutbake {

const Preset &GodotPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "godot";
    p.engine = "Godot 4.5+ (Forward+)";
    p.summary =
        "dfg.ktx2: 128 x 128 RG16F, x = NoV, y = 1 - roughness (centres), R = B, G = E, "
        "Schlick-GGX k = alpha / 2";
    PresetTexture t;
    t.file = "dfg.ktx2";
    t.format = "ktx2-half";
    PresetAxis roughness = CentresAxis("roughness", 128);
    roughness.reversed = true;
    t.axes = {CentresAxis("mu", 128), roughness};
    t.channels = {{"B"}, {"E"}};
    t.model.fitted = FittedVisibility::kSchlickGgx;
    t.sampling = "textureLod(dfg, vec2(NoV, 1.0 - roughness), 0.0).rg";
    t.source =
        "godotengine/godot servers/rendering/renderer_rd/shaders/environment/integrate_dfg.glsl, "
        "scene_forward_clustered.glsl (PR #103934, #106844)";
    t.notes =
        "Godot's Mobile and Compatibility renderers, and Forward+ before 4.5, use an analytic fit "
        "and sample no texture.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
