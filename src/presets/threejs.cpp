// three.js (r182+): the DFG table embedded as half floats in
// src/renderers/shaders/DFGLUTData.js (16 x 16 RG16F, a DataTexture of
// HalfFloatType) and read in lights_physical_pars_fragment.glsl as
//   texture2D(dfgLUT, vec2(roughness, dotNV)).rg
// with R = A, G = B (F0 x + F90 y). The axes are transposed against the
// other engines: x = roughness, y = NdotV, texel centres on both.
// Height-correlated Smith, alpha = roughness^2.
#include "presets.h"

namespace lutbake {

const Preset &ThreejsPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "threejs";
    p.engine = "three.js";
    p.summary =
        "DFGLUTData.js: three.js's module (getDFGLUT), 16 x 16 RG16F, x = roughness, y = NdotV "
        "(centres), R = A, G = B";
    PresetTexture t;
    t.file = "DFGLUTData.js";
    t.format = "threejs-dfg";
    t.axes = {CentresAxis("roughness", 16), CentresAxis("mu", 16)};
    t.channels = {{"A"}, {"B"}};
    t.model.smith = SmithForm::kCorrelated;
    t.sampling = "texture2D(dfgLUT, vec2(roughness, dotNV)).rg";
    t.source =
        "mrdoob/three.js src/renderers/shaders/DFGLUTData.js, "
        "src/renderers/shaders/ShaderChunk/lights_physical_pars_fragment.glsl.js (DFGApprox)";
    t.notes =
        "three.js clamps roughness to >= 0.0525 in the shader, not in the table; its own table "
        "(4096 samples) is 1.4e-2 off in A on the grazing row.";
    p.textures = {t};
    return p;
  }();
  return preset;
}

}  // namespace lutbake
