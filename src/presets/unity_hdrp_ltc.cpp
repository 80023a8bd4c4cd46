// Unity HDRP: the slices of its LTC texture array (_LtcData,
// Runtime/Material/LTCAreaLight/LTCAreaLight.cs: a 64 x 64 Texture2DArray
// of R16G16B16A16_SFloat, one slice per LTCLightingModel: 0 GGX, 1
// DisneyDiffuse, 2 Charlie, 3 FabricLambert, 4 KajiyaKaySpecular, 5
// KajiyaKayDiffuse, 6 Marschner (no table: HDRP leaves it empty), 7
// CookTorrance, 8 Ward, 9 OrenNayar), each loaded from a C# array
// (Generated/LtcData.BRDF_<name>.cs):
//   double[64 * 64, 3 * 3] s_LtcMatrixData_BRDF_<name>, entry
//   [roughnessIndex + 64 * thetaIndex] = the nine elements, row by row, of
//   the transpose of M^-1 scaled so that its (2, 2) element is 1:
//   { m00, 0, m20, 0, m11, 0, m02, 0, 1 } (M^-1 = [[m00, 0, m02], [0, m11,
//   0], [m20, 0, 1]] acting on column vectors in the frame n = +z, view in
//   the +x half of the xz plane).
// LoadLUT puts elements 0, 2, 4, 6 (clamped above at 65504) into a texel's
// RGBA; the shaders (Lit.hlsl and the other materials' GetPreLightData) read
//   uv = Remap01ToHalfTexelCoord(float2(perceptualRoughness, sqrt(1 - clampedNdotV)), 64)
//   ltcTransform._m00_m02_m11_m20 = SAMPLE_TEXTURE2D_ARRAY_LOD(_LtcData, ..., uv, slice, 0)
//   ltcTransform._m22 = 1
// and light the polygon as mul(localVerts, ltcTransform) (row vectors: M^-1
// times the column vector). So texel (x, y) holds perceptual roughness x /
// 63 and NdotV = 1 - (y / 63)^2 (edges), as the arrays' comments state.
//
// The lobes, as HDRP's fitter (BRDF_*.cs) evaluates them at alpha =
// max((x / 63)^2, 0.001) (the arrays' comments), and how this preset fits
// them:
//   GGX       height-correlated Smith; alpha as HDRP's.
//   Disney    Burley's diffuse at perceptual roughness sqrt(max(alpha,
//             0.002)) (BRDF_Disney clamps alpha at 0.002). HDRP's fitter
//             also clamps L.V at 0 in f_d90, which its shader's DisneyDiffuse
//             does not: this preset fits the shader's lobe (table
//             ltc_burley's).
//   Charlie   D_Charlie with V_Charlie (no terminator softening) at
//             max(alpha, 0.002). HDRP's fitter interpolates the Lambda fit
//             at r' = 1 - alpha^2 where its shader's CharlieL (BSDF.hlsl)
//             uses 1 - (1 - alpha)^2: this preset fits the shader's (table
//             ltc_sheen's). NdotV is clamped at 1e-4 (HDRP's ClampNdotV)
//             on the last row, where the Charlie albedo is infinite.
//   OrenNayar sigma = max(0.002, (pi / 2) alpha). HDRP's fitter uses A = 1 -
//             0.5 s2 / (s2 + 0.57) (the 1992 paper's footnote); this preset
//             fits the qualitative model's 0.33 (table ltc_oren_nayar's).
//             HDRP's AxF material samples it for its SVBRDF diffuse
//             (SampleLtcMatrix, the same uv and matrix as Lit's).
// FabricLambert, KajiyaKaySpecular, KajiyaKayDiffuse, CookTorrance and
// Ward are not lobes lutbake integrates: those slices stay HDRP's own.
#include <string>

#include "lutbake/core/math.h"
#include "presets.h"

namespace lutbake {

namespace {

// One slice's C# array over (perceptual roughness, sqrt(1 - NdotV)), edges:
// M^-1 of the fit of `table`, each entry over m22.
PresetTexture HdrpLtcSlice(const char *file, const char *slice, const char *table,
                           double alphaMin) {
  PresetTexture t;
  t.file = file;
  t.format = "hdrp-ltc-cs";
  PresetAxis mu = EdgesAxis("mu", 64);
  mu.mapping = PresetMapping::kOneMinusSquare;
  t.axes = {EdgesAxis("roughness", 64), mu};
  const auto entry = [table](const char *meaning) {
    return PresetChannel{meaning, table, "ltc_m22"};
  };
  t.channels = {entry("ltc_m00"), {"zero"},         entry("ltc_m20"), {"zero"}, entry("ltc_m11"),
                {"zero"},         entry("ltc_m02"), {"zero"},         {"one"}};
  t.model.smith = SmithForm::kCorrelated;
  t.model.alpha = AlphaMapping::kSquared;
  t.model.alphaMin = alphaMin;
  t.sampling = std::string(
                   "ltcTransform._m00_m02_m11_m20 = SAMPLE_TEXTURE2D_ARRAY_LOD(_LtcData, "
                   "s_linear_clamp_sampler, Remap01ToHalfTexelCoord(float2("
                   "perceptualRoughness, sqrt(1 - clampedNdotV)), LTC_LUT_SIZE), ") +
               slice + ", 0); ltcTransform._m22 = 1";
  t.source =
      "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/Material/"
      "LTCAreaLight/LTCAreaLight.cs (LoadLUT, LTCLightingModel), Generated/LtcData.BRDF_*.cs, "
      "BRDF/BRDF_*.cs; Runtime/Material/Lit/Lit.hlsl (GetPreLightData, EvaluateBSDF_Rect)";
  t.notes =
      "Replaces HDRP's file of the same name. The doubles are lutbake's fit exactly; HDRP casts "
      "them to float and uploads R16G16B16A16_SFloat (binary16: 2^-11 relative). lutbake eval "
      "--table ltc_* states the fit's lobe error, polygon error and leakage. HDRP's other slices "
      "(FabricLambert, KajiyaKaySpecular, KajiyaKayDiffuse, CookTorrance, Ward; Marschner has "
      "no table) are lobes lutbake does not make: keep HDRP's files for them.";
  return t;
}

}  // namespace

const Preset &UnityHdrpLtcPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "unity-hdrp-ltc";
    p.engine = "Unity HDRP";
    p.summary =
        "LtcData.BRDF_GGX.cs, _Disney.cs, _Charlie.cs, _OrenNayar.cs: HDRP's LTC slices as its "
        "C# arrays (double[64 * 64, 9]: M^-1 transposed, m22 = 1); x = perceptual roughness, "
        "y = sqrt(1 - NdotV) (edges)";
    PresetTexture ggx =
        HdrpLtcSlice("LtcData.BRDF_GGX.cs", "LTCLIGHTINGMODEL_GGX", "ltc_ggx", 0.001);
    PresetTexture disney = HdrpLtcSlice("LtcData.BRDF_Disney.cs", "LTCLIGHTINGMODEL_DISNEY_DIFFUSE",
                                        "ltc_burley", 0.002);
    PresetTexture charlie =
        HdrpLtcSlice("LtcData.BRDF_Charlie.cs", "LTCLIGHTINGMODEL_CHARLIE", "ltc_sheen", 0.002);
    charlie.model.sheenVisibility = SheenVisibility::kCharlie;
    charlie.axes[1].lowest = 1e-4;  // ClampNdotV
    // sigma = (pi / 2) max(alpha, 0.002 / (pi / 2)) = max(0.002, (pi / 2) alpha).
    PresetTexture orenNayar =
        HdrpLtcSlice("LtcData.BRDF_OrenNayar.cs", "LTCLIGHTINGMODEL_OREN_NAYAR", "ltc_oren_nayar",
                     0.002 / (0.5 * kPi));
    p.textures = {ggx, disney, charlie, orenNayar};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
