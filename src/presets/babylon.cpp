// Babylon.js (npm @babylonjs/core, Misc/brdfTextureTools): the BRDF lookup
// textures it embeds as base64 PNGs and loads with isRGBD = true, invertY =
// false and a bilinear filter (loadBRDFTexture), expanding them once to
// RGBA16F by its rgbdDecode pass (RGBDTextureTools.ExpandRGBDTexture,
// fromRGBD: rgb^2.2 / a) where half floats render and filter, else
// sampling the 8-bit RGBD and decoding after the filter
// (ENVIRONMENTBRDF_RGBD). PNG row 0 is the first row of the texture, v =
// 0.5 / N: both axes at texel centres.
//
//   environmentBRDFTexture (256 x 256), getBRDFLookup (pbrBRDFFunctions.fx):
//     texture2D(environmentBrdfSampler, vec2(NdotV, perceptualRoughness))
//     x = B, y = E (height-correlated: reflectance = (R90 - R0) x + R0 y,
//     energy conservation 1 + R0 (1 / y - 1)), z = the sheen albedo,
//     Charlie D with the Ashikhmin visibility (visibility_Ashikhmin), alpha
//     = r^2, that getSheenReflectanceFromBRDFLookup scales sheen with
//     (above 1 toward grazing low roughness: RGBD holds up to 255).
//   openPBREnvironmentBRDFTexture (128 x 128), the same lookup in OpenPBR's
//     shaders: x = B, y = E, z = 16 C, C the F82-tint term (table f82;
//     getF82DirectionalAlbedo: (F90 - F0) x + F0 y - b z / BRDF_Z_SCALE,
//     BRDF_Z_SCALE = 16 "for 8-bit range"). Its bound is in the stored,
//     times-16, units.
//
// RGBD (rgbd.h) with the divisor of smallest error at every texel; the
// DDS files hold the same texels as RGBA16F (A = 1), which Babylon's DDS
// loader takes as they are (no RGBD: leave isRGBD false).
//   environmentFuzzBRDFTexture (32 x 32), getFuzzBRDFLookup: texture2D(
//     environmentFuzzBrdfSampler, vec2(sqrt(fuzz_roughness), NdotV)), each
//     channel mapped from [0, 1] to a fixed range: x -> a in [0.005, 0.88],
//     y -> b in [-0.18, 0.002], z -> R in [0, 0.75], the LTC entries and
//     reflectance of Zeltner et al.'s sheen (models/zeltner_sheen_ltc.h:
//     the authors' table, data, not a lutbake integral).
// Defects not reproduced. Babylon stores the fuzz values linearly in an RGB
// PNG but loads it with isRGBD = true, so its expansion reads
// pow(stored, 2.2): a, b and R as its shader sees them are off by up to
// 0.25, 0.07 and 0.21 (docs/presets.md). And it writes the authors' entry
// at alpha = i / 31, cos = j / 31 into texel (i, j), which the bilinear
// lookup at vec2(x, NdotV) reads at x = (i + 0.5) / 32: half a texel off.
// This preset's fuzz texture holds the values at the coordinates the
// shader samples (alpha = x, as Babylon's layout takes it), RGBD-encoded
// so that the expansion decodes them.
#include <string>

#include "presets.h"

namespace lutbake {

namespace {

constexpr const char *kSource =
    "BabylonJS/Babylon.js packages/dev/core/src/Misc/brdfTextureTools.ts, "
    "Misc/rgbdTextureTools.ts (ExpandRGBDTexture), Shaders/rgbdDecode.fragment.fx, "
    "Shaders/ShadersInclude/helperFunctions.fx (fromRGBD), pbrBRDFFunctions.fx "
    "(getBRDFLookup, getF82DirectionalAlbedo, BRDF_Z_SCALE), openpbrIblFunctions.fx";

constexpr const char *kRgbdNote =
    "RGBD: value = (rgb / 255)^2.2 / (a / 255), Babylon's fromRGBD with its default "
    "useExactSrgbConversions = false; each texel's divisor is the one of smallest error. "
    "Babylon's expansion to RGBA16F adds a half-float rounding (2^-11 relative) to the bound.";

PresetTexture BrdfTexture(const char *file, const char *format, int size) {
  PresetTexture t;
  t.file = file;
  t.format = format;
  t.axes = {CentresAxis("mu", size), CentresAxis("roughness", size)};
  t.model.smith = SmithForm::kCorrelated;
  t.sampling =
      "getBRDFLookup(NdotV, perceptualRoughness): texture2D(environmentBrdfSampler, "
      "vec2(NdotV, perceptualRoughness)).rgb (fromRGBD where not expanded)";
  t.source = kSource;
  return t;
}

}  // namespace

const Preset &BabylonPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "babylon";
    p.engine = "Babylon.js";
    p.summary =
        "environmentBRDFTexture 256 x 256 (B, E, Ashikhmin sheen E), "
        "openPBREnvironmentBRDFTexture 128 x 128 (B, E, 16 F82 C): x = NdotV, y = "
        "perceptualRoughness; environmentFuzzBRDFTexture 32 x 32 (Zeltner a, b, R in Babylon's "
        "ranges): x = sqrt(fuzz_roughness), y = NdotV; centres; 8-bit RGBD PNG, RGBA16F DDS";
    PresetTexture brdf = BrdfTexture("environmentBRDFTexture.png", "png-rgbd", 256);
    brdf.channels = {{"B"}, {"E"}, {"sheen_E"}};
    brdf.model.sheenVisibility = SheenVisibility::kAshikhmin;
    brdf.model.sheenAlpha = AlphaMapping::kSquared;
    brdf.notes = std::string(kRgbdNote) +
                 " z, the sheen albedo, exceeds 1 toward grazing low roughness; the divisor "
                 "that holds it there coarsens x and y of the same texel.";
    PresetTexture openpbr = BrdfTexture("openPBREnvironmentBRDFTexture.png", "png-rgbd", 128);
    PresetChannel f82{"f82"};
    f82.scale = 16.0;  // BRDF_Z_SCALE
    openpbr.channels = {{"B"}, {"E"}, f82};
    openpbr.notes = std::string(kRgbdNote) +
                    " z holds 16 C (BRDF_Z_SCALE): errorMax is in those units, 16 times C's.";
    PresetTexture brdfDds = brdf;
    brdfDds.file = "environmentBRDFTexture.dds";
    brdfDds.format = "dds-half";
    brdfDds.sampling = "texture2D(environmentBrdfSampler, vec2(NdotV, perceptualRoughness)).rgb";
    brdfDds.notes =
        "RGBA16F (A = 1): load with invertY = false and isRGBD = false, as "
        "scene.environmentBRDFTexture.";
    PresetTexture openpbrDds = openpbr;
    openpbrDds.file = "openPBREnvironmentBRDFTexture.dds";
    openpbrDds.format = "dds-half";
    openpbrDds.sampling = brdfDds.sampling;
    openpbrDds.notes = "RGBA16F (A = 1), z = 16 C; load with invertY = false, isRGBD = false.";
    // The fuzz texture: x = Zeltner's alpha, y = NdotV, both centres.
    PresetTexture fuzz;
    fuzz.file = "environmentFuzzBRDFTexture.png";
    fuzz.format = "png-rgbd";
    fuzz.axes = {CentresAxis("roughness", 32), CentresAxis("mu", 32)};
    fuzz.model.alpha = AlphaMapping::kLinear;
    // stored = (value - low) / (high - low), Babylon's ranges, clamped to
    // [0, 1] (the table's b reaches -0.18133, below -0.18).
    const auto ranged = [](const char *meaning, double low, double high) {
      PresetChannel c{meaning};
      c.scale = 1.0 / (high - low);
      c.offset = -low / (high - low);
      c.clampMin = 0.0;
      c.clampMax = 1.0;
      return c;
    };
    fuzz.channels = {ranged("zeltner_a", 0.005, 0.88), ranged("zeltner_b", -0.18, 0.002),
                     ranged("zeltner_R", 0.0, 0.75)};
    fuzz.sampling =
        "getFuzzBRDFLookup(NdotV, sqrt(fuzz_roughness)): texture2D(environmentFuzzBrdfSampler, "
        "vec2(sqrt(fuzz_roughness), NdotV)), then mix(ARange), mix(BRange), mix(RiRange)";
    fuzz.source = std::string(kSource) +
                  "; tizian/ltc-sheen pbrt-v3/src/materials/sheenltc.cpp (_ltcParamTableVolume)";
    fuzz.notes =
        "Zeltner et al.'s published table (data; its own fitting error is not in the bound), "
        "bilinear at alpha = (i + 0.5) / 32, cos = (j + 0.5) / 32, where Babylon's lookup reads; "
        "RGBD so that Babylon's expansion (pow 2.2) decodes it. Babylon's own texture stores the "
        "values linearly without a divisor, which that expansion misreads, and half a texel off. "
        "Bounds are in the stored, range-normalised units (times the range, 0.875, 0.182, 0.75, "
        "for a, b, R); b below -0.18 is stored as -0.18. Where half floats do not render, "
        "Babylon reads the bytes without decoding: that path reads neither texture right.";
    PresetTexture fuzzDds = fuzz;
    fuzzDds.file = "environmentFuzzBRDFTexture.dds";
    fuzzDds.format = "dds-half";
    fuzzDds.notes =
        "RGBA16F (A = 1), the range-normalised values; load with invertY = false, isRGBD = "
        "false.";
    p.textures = {brdf, openpbr, fuzz, brdfDds, openpbrDds, fuzzDds};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
