// LearnOpenGL's IBL specular chapter (JoeyDeVries/LearnOpenGL,
// src/6.pbr/2.2.1.ibl_specular/2.2.1.brdf.fs and 2.2.1.pbr.fs): a 512 x 512
// RG16F texture rendered by a full-screen quad, so texel (i, j) holds
// IntegrateBRDF(NdotV = (i + 0.5) / 512, roughness = (j + 0.5) / 512), with
// GGX importance sampling at alpha = roughness^2 and Schlick-GGX's
// separable G with k = alpha / 2; R = F0's scale A, G = the bias B, read as
//   texture(brdfLUT, vec2(max(dot(N, V), 0.0), roughness)).rg
//   specular = prefilteredColor * (F * brdf.x + brdf.y).
// The chapter integrates 1024 Hammersley samples per texel; this preset is
// the same integral, exact.
#include "presets.h"

namespace lutbake {

const Preset &LearnOpenGlPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "learnopengl";
    p.engine = "LearnOpenGL (IBL specular chapter)";
    p.summary =
        "brdf_lut.ktx2: 512 x 512 RG16F, x = NdotV, y = roughness at texel centres, R = A, "
        "G = B, Schlick-GGX k = alpha / 2";
    PresetTexture t;
    t.file = "brdf_lut.ktx2";
    t.format = "ktx2-half";
    t.axes = {CentresAxis("mu", 512), CentresAxis("roughness", 512)};
    t.channels = {{"A"}, {"B"}};
    t.model.fitted = FittedVisibility::kSchlickGgx;
    t.sampling = "texture(brdfLUT, vec2(max(dot(N, V), 0.0), roughness)).rg";
    t.source =
        "JoeyDeVries/LearnOpenGL src/6.pbr/2.2.1.ibl_specular/2.2.1.brdf.fs, 2.2.1.pbr.fs, "
        "ibl_specular.cpp (brdfLUTTexture: GL_RG16F 512 x 512)";
    t.notes = "The first row is roughness = 0.5 / 512 (OpenGL's first row is t = 0).";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
