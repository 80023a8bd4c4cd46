// Filament (google/filament): the DFG texture of image-based lighting,
// generated at build time by cmgen --ibl-dfg-multiscatter --ibl-dfg-cloth
// into generated/data/dfg.inc (libs/ibl/src/CubemapIBL.cpp, CubemapIBL::DFG;
// tools/cmgen/src/cmgen.cpp, iblLutDfg; filament/CMakeLists.txt,
// DFG_LUT_SIZE) and uploaded as RGB16F by filament/src/DFG.cpp. The shader
// (shaders/src/surface_light_indirect.fs) reads
//   textureLod(sampler0_iblDFG, vec2(NoV, perceptualRoughness), 0.0).rgb
// with a linear filter: texel centres on both axes, the first row in
// memory at roughness 0.5 / N. Channels: R = B, G = E (so that
// mix(dfg.x, dfg.y, f0) = f0 A + B and energy compensation 1 + f0 (1 /
// dfg.y - 1)), B = the cloth / sheen albedo: Charlie D with the Ashikhmin
// (Neubelt) visibility 1 / (4 (NoL + NoV - NoL NoV)), alpha = r^2, unclamped
// (it exceeds 1 at grazing low roughness), which sheenScaling = 1 -
// max3(sheenColor) dfg.z uses.
// Defect not reproduced: CubemapIBL::DFG evaluates image row y at
// roughness (N - y + 0.5) / N and cmgen writes it flipped, so memory row j
// holds min((j + 1.5) / N, 1): every row one texel too rough (seen in a
// shipped v1.19.0 table). This preset holds (j + 0.5) / N, what the shader
// samples there.
#include "presets.h"

namespace lutbake {

namespace {

Preset MakeFilament(const char *name, int size, const char *what) {
  Preset p;
  p.name = name;
  p.engine = "Filament";
  p.summary = std::string("dfg.inc: ") + what + " " + std::to_string(size) + " x " +
              std::to_string(size) +
              " RGB16F half bits, x = NoV, y = perceptualRoughness (centres), R = B, G = E, "
              "B = cloth (Charlie, Ashikhmin V)";
  PresetTexture t;
  t.file = "dfg.inc";
  t.format = "inc-half";
  t.axes = {CentresAxis("mu", size), CentresAxis("roughness", size)};
  t.channels = {{"B"}, {"E"}, {"sheen_E"}};
  t.model.smith = SmithForm::kCorrelated;
  t.model.sheenVisibility = SheenVisibility::kAshikhmin;
  t.model.sheenAlpha = AlphaMapping::kSquared;
  t.sampling = "textureLod(sampler0_iblDFG, vec2(NoV, perceptualRoughness), 0.0).rgb";
  t.source =
      "google/filament libs/ibl/src/CubemapIBL.cpp (CubemapIBL::DFG, DFV_Multiscatter, "
      "DFV_Charlie_Uniform), tools/cmgen/src/cmgen.cpp (iblLutDfg), filament/src/DFG.cpp, "
      "shaders/src/surface_light_indirect.fs (PrefilteredDFG_LUT, specularDFG)";
  t.notes =
      "Filament's generator puts memory row j at roughness min((j + 1.5) / N, 1), one texel too "
      "rough; this file holds (j + 0.5) / N, what the shader samples. Replace "
      "generated/data/dfg.inc and rebuild; DFG.cpp's static_assert checks the size.";
  p.textures = {t};
  return p;
}

}  // namespace

const Preset &FilamentPreset() {
  static const Preset preset = MakeFilament("filament", 128, "desktop");
  return preset;
}

const Preset &FilamentMobilePreset() {
  static const Preset preset = MakeFilament("filament-mobile", 64, "mobile (IS_MOBILE_TARGET)");
  return preset;
}

}  // namespace lutbake
