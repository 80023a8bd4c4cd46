// three.js (r150+): the LTC tables of its rect area lights, in
// examples/jsm/lights/RectAreaLightTexturesLib.js (LTC_MAT_1 and LTC_MAT_2,
// 64 x 64 RGBA, made into DataTextures of floats and of halves), read in
// lights_physical_pars_fragment.glsl.js (and the node library's
// PhysicalLightingModel / BSDF/LTC.js) as
//   uv = vec2(roughness, sqrt(1 - dotNV)) * (63 / 64) + 0.5 / 64
//   t1 = texture2D(ltc_1, uv); t2 = texture2D(ltc_2, uv)
//   mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))
//   fresnel = F0 t2.x + (F90 - F0) t2.y
// so texel (row i, column j) holds roughness j / 63 and sqrt(1 - NdotV) =
// i / 63 (texel edges; NdotV = 1 on the first row), t1 = (m00, m20, m02,
// m22) of M^-1 (models/ltc.h: GLSL's mat3 takes columns) and t2 = (E, B, 0,
// w): the lobe's albedo and its Schlick-weighted part (F = 1), and in w the
// horizon-clipped sphere that ltc_code's export adds (three.js samples it
// only in a commented-out alternative to its clipping: 'clipped_sphere',
// over the texture's own u = z / 2 + 1 / 2 and v = |F|). GGX at alpha =
// roughness^2, height-correlated Smith (three.js's own G for point lights).
// A separate preset from `threejs` because it replaces a different file (an
// addon, not the renderer's DFG table) and costs a fit of seconds.
#include "presets.h"

namespace lutbake {

const Preset &ThreejsLtcPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "threejs-ltc";
    p.engine = "three.js";
    p.summary =
        "RectAreaLightTexturesLib.js: three.js's rect-area-light addon, LTC_MAT_1 = M^-1 (m00, "
        "m20, m02, m22), LTC_MAT_2 = (E, B, 0, clipped sphere), 64 x 64, x = roughness, y = "
        "sqrt(1 - NdotV) (edges)";
    PresetTexture t;
    t.file = "RectAreaLightTexturesLib.js";
    t.format = "threejs-ltc";
    PresetAxis mu = EdgesAxis("mu", 64);
    mu.mapping = PresetMapping::kOneMinusSquare;
    t.axes = {EdgesAxis("roughness", 64), mu};
    t.channels = {{"ltc_m00"}, {"ltc_m20"}, {"ltc_m02"}, {"ltc_m22"},
                  {"E"},       {"B"},       {"zero"},    {"clipped_sphere"}};
    t.model.smith = SmithForm::kCorrelated;
    t.sampling =
        "texture2D(ltc_1 / ltc_2, vec2(roughness, sqrt(1.0 - dotNV)) * (63.0 / 64.0) + 0.5 / "
        "64.0) (LTC_Uv)";
    t.source =
        "mrdoob/three.js examples/jsm/lights/RectAreaLightTexturesLib.js, "
        "RectAreaLightUniformsLib.js, src/renderers/shaders/ShaderChunk/"
        "lights_physical_pars_fragment.glsl.js (LTC_Uv, LTC_Evaluate, RE_Direct_RectArea)";
    t.notes =
        "Replaces examples/jsm/lights/RectAreaLightTexturesLib.js as it is (same imports, class "
        "and static textures). The fit keeps neighbouring texels on one branch and states no "
        "sampled objective: lutbake eval --table ltc_ggx states its errors.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
