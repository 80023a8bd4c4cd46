// The engine presets, one definition per file (src/presets/<engine>.cpp),
// each listed once in registry.cpp. A preset is data: its textures' axes,
// channels, model, storage and format (lutbake/presets/preset.h).
#pragma once

#include "lutbake/presets/preset.h"

namespace lutbake {

const Preset &FilamentPreset();
const Preset &FilamentMobilePreset();
const Preset &UnrealPreset();
const Preset &UnityHdrpPreset();
const Preset &UnityHdrpLtcPreset();
const Preset &GodotPreset();
const Preset &ThreejsPreset();
const Preset &ThreejsLtcPreset();
const Preset &GltfSampleRendererPreset();
const Preset &LearnOpenGlPreset();
const Preset &EeveePreset();
const Preset &EeveeLtcPreset();
const Preset &CyclesPreset();
const Preset &BabylonPreset();
const Preset &BabylonLtcPreset();
const Preset &OsprayPreset();
const Preset &MaterialxPreset();

// Axis helpers for the definitions: an axis of `count` texels over the
// quantity "mu" or "roughness".
PresetAxis CentresAxis(const char *quantity, int count);
PresetAxis EdgesAxis(const char *quantity, int count);

}  // namespace lutbake
