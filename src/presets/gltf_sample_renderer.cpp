// The Khronos glTF Sample Renderer / Sample Viewer: three lookup tables its
// shaders (source/Renderer/shaders/ibl.glsl, brdf.glsl) read at texel
// centres with vec2(NdotV, roughness), the first image row at roughness
// 0.5 / N (images are uploaded without a vertical flip):
//   u_GGXLUT     .rg = A, B: GGX, height-correlated Smith, alpha = r^2
//   u_CharlieLUT .b  = the Charlie sheen's albedo with the Ashikhmin
//                visibility, alpha = r^2 (its runtime generator samples h
//                at alpha = r^2 but weighs D at alpha = r: the defect is
//                not reproduced)
//   u_SheenELUT  .r  = sheen E for albedo scaling (1 - max3(sheenColor) E):
//                Charlie D and the glTF extension's Charlie visibility,
//                alpha = r^2. The shipped lut_sheen_E.png holds sRGB-encoded
//                values that the viewer reads as linear; these are linear.
// PNG holds [0, 1]: the sheen albedos above 1 (grazing, low roughness) are
// stored as 1, and each such texel's bound says how far that is.
#include "presets.h"

namespace lutbake {

const Preset &GltfSampleRendererPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "gltf-sample-renderer";
    p.engine = "Khronos glTF Sample Renderer / Sample Viewer";
    p.summary =
        "lut_ggx.png (A, B), lut_charlie.png (.b), lut_sheen_E.png: 16-bit, x = NdotV, "
        "y = roughness (centres)";
    const char *source =
        "KhronosGroup/glTF-Sample-Renderer source/Renderer/shaders/ibl.glsl, brdf.glsl, "
        "ibl_filtering.frag (LUT), source/Renderer/ibl_sampler.js; "
        "assets/images/lut_sheen_E.png";
    PresetTexture ggx;
    ggx.file = "lut_ggx.png";
    ggx.format = "png16";
    ggx.axes = {CentresAxis("mu", 1024), CentresAxis("roughness", 1024)};
    ggx.channels = {{"A"}, {"B"}};
    ggx.sampling = "texture(u_GGXLUT, clamp(vec2(NdotV, roughness), 0.0, 1.0)).rg";
    ggx.source = source;
    PresetTexture charlie = ggx;
    charlie.file = "lut_charlie.png";
    charlie.axes = {CentresAxis("mu", 256), CentresAxis("roughness", 256)};
    PresetChannel sheen{"sheen_E"};
    sheen.clampMax = 1.0;
    charlie.channels = {{"zero"}, {"zero"}, sheen};
    charlie.model.sheenVisibility = SheenVisibility::kAshikhmin;
    charlie.model.sheenAlpha = AlphaMapping::kSquared;
    charlie.sampling = "texture(u_CharlieLUT, clamp(vec2(NdotV, sheenRoughness), 0.0, 1.0)).b";
    charlie.notes =
        "256 x 256: the shader's normalised coordinates take any size. Values above 1 (grazing, "
        "low roughness) are stored as 1.";
    PresetTexture sheenE = charlie;
    sheenE.file = "lut_sheen_E.png";
    sheenE.channels = {sheen};
    sheenE.model.sheenVisibility = SheenVisibility::kCharlie;
    sheenE.sampling = "texture(u_SheenELUT, vec2(NdotV, sheenRoughness)).r";
    sheenE.notes =
        "Linear E (the viewer's shipped file holds sRGB-encoded E and reads it as linear); "
        "greyscale, 256 x 256.";
    p.textures = {ggx, charlie, sheenE};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
