// Babylon.js (7+): the LTC textures of its RectAreaLight, areaLightsLTC.bin,
// which it fetches from its asset CDN (Lights/LTC/ltcTextureTool.ts,
// DecodeLTCTextureDataAsync; the file is not in the npm package) and splits
// into two RawTexture.CreateRGBATexture(data, 64, 64, engine, false,
// false, BILINEAR, HALF_FLOAT) (Lights/areaLight.pure.ts: invertY false, so
// texel t = row * 64 + column with row 0 at v = 0). Its shader
// (ShadersInclude/ltcHelperFunctions.fx, a port of three.js's) samples
//   uv = vec2(roughness, sqrt(1 - dotNV)) * (63 / 64) + 0.5 / 64   (LTCUv)
//   mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))
//   fresnel = specularColor * t2.x + (1 - specularColor) * t2.y
// (lightsFragmentFunctions.fx; the PBR and OpenPBR materials the same, with
// roughness their perceptual roughness), so LTC1 = (m00, m20, m02, m22) of
// M^-1 and LTC2 = (E, B, -, -), roughness j / 63 in column j and
// sqrt(1 - NdotV) = i / 63 in row i: three.js's layout, in halves. LTC2's z
// and w, which Babylon does not read, hold ltc_code's export as three.js
// has it: 0 and the horizon-clipped sphere. GGX at alpha = roughness^2,
// height-correlated Smith (the G of ltc_code's fit and of Babylon's PBR).
#include "presets.h"

namespace lutbake {

const Preset &BabylonLtcPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "babylon-ltc";
    p.engine = "Babylon.js (7+)";
    p.summary =
        "areaLightsLTC.bin: Babylon's area-light LTC file, 64 x 64 texels of 8 halves: LTC1 = "
        "M^-1 (m00, m20, m02, m22), LTC2 = (E, B, 0, clipped sphere); x = roughness, y = "
        "sqrt(1 - NdotV) (edges)";
    PresetTexture t;
    t.file = "areaLightsLTC.bin";
    t.format = "babylon-ltc";
    PresetAxis mu = EdgesAxis("mu", 64);
    mu.mapping = PresetMapping::kOneMinusSquare;
    t.axes = {EdgesAxis("roughness", 64), mu};
    t.channels = {{"ltc_m00"}, {"ltc_m20"}, {"ltc_m02"}, {"ltc_m22"},
                  {"E"},       {"B"},       {"zero"},    {"clipped_sphere"}};
    // binary16 holds nothing positive below 2^-24: the fit's m00 at the
    // grazing mirror (NdotV = 0, roughness 0) is 4.6e-10 and would round to
    // 0, det M^-1 = 0 (a black light). Held at 2^-24 instead (det > 0); the
    // texel's bound carries the 6e-8 it moved.
    t.channels[0].clampMin = 0x1p-24;
    t.model.smith = SmithForm::kCorrelated;
    t.sampling =
        "texture2D(areaLightsLTC1Sampler / areaLightsLTC2Sampler, vec2(roughness, sqrt(1.0 - "
        "dotNV)) * (63.0 / 64.0) + 0.5 / 64.0) (LTCUv)";
    t.source =
        "BabylonJS/Babylon.js packages/dev/core/src/Lights/LTC/ltcTextureTool.ts, "
        "Lights/areaLight.ts, Shaders/ShadersInclude/ltcHelperFunctions.fx, "
        "lightsFragmentFunctions.fx";
    t.notes =
        "Serve it in place of https://assets.babylonjs.com/core/areaLights/areaLightsLTC.bin "
        "(Tools.GetAssetUrl / the scene's LTC provider). binary16 as Babylon uploads it; "
        "lutbake eval --table ltc_ggx states the fit's errors.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
