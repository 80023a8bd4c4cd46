// Blender EEVEE (4.2+): the LTC arrays of its area lights, in
// source/blender/draw/engines/eevee/eevee_lut.cc (eevee_next before 4.2):
//   ltc_mat_ggx[64][64][4], ltc_mag_ggx[64][64][2], ltc_disk_integral[64][64][1]
// copied into layers of the utility texture as data[y][x] = array[y][x]
// (eevee_instance.hh, UtilityTexture) and sampled with
//   uv = vec2(roughness, sqrt(1 - NV)) * (63 / 64) + 0.5 / 64
// so array[j][i] holds roughness i / 63 and sqrt(1 - NV) = j / 63 (texel
// edges; NV = 1 on the first row), as three.js's LTC textures do. The matrix
// is read by eevee_ltc_lib.glsl as
//   ltc_matrix(lut) = mat3(vec3(lut.x, 0, lut.y), vec3(0, 1, 0), vec3(lut.z, 0, lut.w))
// (GLSL's mat3 takes columns), so lut = (m00, m20, m02, m22) of M^-1, its
// middle element 1. ltc_mag_ggx = (E, B): the lobe's albedo with F = 1 and
// its Schlick-weighted part (ltc_code's norm and fresnel). ltc_disk_integral
// is ltc_code's horizon-clipped sphere over its form factor |F|, sampled by
// ltc_diffuse_sphere_integral at uv = (z / 2 + 1 / 2, |F|), the same remap:
// array[j][i] at |F| = j / 63 and z = 2 i / 63 - 1.
//
// What Blender ships is ltc_code's 2016 fit (its three arrays equal three.js's
// LTC_MAT_1, LTC_MAT_2.xy and LTC_MAT_2.w to the 6 printed decimals,
// tests/data/presets/eevee_ltc_*_rows.csv), fitted to GGX with the
// height-correlated Smith G; this preset fits the same lobe (alpha =
// roughness^2, correlated), not the separable G of EEVEE's own brdf_ggx
// generator (the `eevee` preset), so that it replaces like with like.
//
// A preset of its own rather than new files of `eevee`: the `eevee` preset's
// file and preset.json stay as they are, and the LTC fit costs seconds where
// brdf_ggx costs a fraction of one (as threejs-ltc beside threejs).
#include "presets.h"

namespace lutbake {

namespace {

// An EEVEE 64 x 64 array over (roughness, sqrt(1 - NV)), edges.
PresetTexture EeveeLtcArray(const char *file) {
  PresetTexture t;
  t.file = file;
  t.format = "inc";
  PresetAxis mu = EdgesAxis("mu", 64);
  mu.mapping = PresetMapping::kOneMinusSquare;
  t.axes = {EdgesAxis("roughness", 64), mu};
  t.model.smith = SmithForm::kCorrelated;
  t.sampling =
      "vec2(roughness, sqrt(1.0 - NV)) * (63.0 / 64.0) + 0.5 / 64.0 (UTIL_TEX_UV_SCALE, "
      "UTIL_TEX_UV_BIAS), layer UTIL_LTC_MAT_LAYER / UTIL_LTC_MAG_LAYER (.zw)";
  t.source =
      "blender/blender source/blender/draw/engines/eevee/eevee_lut.cc (ltc_mat_ggx, "
      "ltc_mag_ggx, ltc_disk_integral), eevee_instance.hh (UtilityTexture), "
      "shaders/eevee_ltc_lib.glsl (ltc_matrix, ltc_diffuse_sphere_integral), "
      "eevee_shader_shared.hh";
  return t;
}

}  // namespace

const Preset &EeveeLtcPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "eevee-ltc";
    p.engine = "Blender EEVEE (4.2+)";
    p.summary =
        "ltc_mat_ggx.inc (64 x 64 x 4: M^-1 m00, m20, m02, m22), ltc_mag_ggx.inc (64 x 64 x 2: "
        "E, B), ltc_disk_integral.inc (64 x 64: clipped sphere); x = roughness, y = sqrt(1 - NV) "
        "(edges); correlated Smith";
    PresetTexture mat = EeveeLtcArray("ltc_mat_ggx.inc");
    mat.channels = {{"ltc_m00"}, {"ltc_m20"}, {"ltc_m02"}, {"ltc_m22"}};
    mat.notes =
        "The values of ltc_mat_ggx[64][64][4] in Blender's order [j][i][c] (j = sqrt(1 - NV) "
        "row): paste between the braces of eevee_lut.cc's initialiser. The fit keeps "
        "neighbouring texels on one branch; lutbake eval --table ltc_ggx states its errors.";
    PresetTexture mag = EeveeLtcArray("ltc_mag_ggx.inc");
    mag.channels = {{"E"}, {"B"}};
    mag.notes =
        "The values of ltc_mag_ggx[64][64][2], [j][i][c]: E = A + B of table dfg (F = 1) and B, "
        "integrated at each texel.";
    PresetTexture disk = EeveeLtcArray("ltc_disk_integral.inc");
    disk.axes = {EdgesAxis("(1 + z) / 2", 64), EdgesAxis("|F|", 64)};
    disk.channels = {{"clipped_sphere"}};
    disk.sampling =
        "vec2(avg_dir_z * 0.5 + 0.5, form_factor) * (63.0 / 64.0) + 0.5 / 64.0, layer "
        "UTIL_DISK_INTEGRAL_LAYER, component UTIL_DISK_INTEGRAL_COMP "
        "(ltc_diffuse_sphere_integral)";
    disk.notes =
        "The values of ltc_disk_integral[64][64][1], [j][i]: j = |F| row, i = (1 + z) / 2 "
        "column; no lobe (the axes are the cap's, not mu and roughness).";
    p.textures = {mat, mag, disk};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
