// The registry: every engine preset, once, in the order `lutbake presets`
// lists them.
#include <string>

#include "presets.h"

namespace lutbake {

const std::vector<const Preset *> &AllPresets() {
  // clang-format off
  static const std::vector<const Preset *> presets = {
      &FilamentPreset(),
      &FilamentMobilePreset(),
      &UnrealPreset(),
      &UnityHdrpPreset(),
      &UnityHdrpLtcPreset(),
      &GodotPreset(),
      &ThreejsPreset(),
      &ThreejsLtcPreset(),
      &GltfSampleRendererPreset(),
      &LearnOpenGlPreset(),
      &EeveePreset(),
      &EeveeLtcPreset(),
      &CyclesPreset(),
      &BabylonPreset(),
      &BabylonLtcPreset(),
      &OsprayPreset(),
      &MaterialxPreset(),
  };
  // clang-format on
  return presets;
}

const Preset *FindPreset(const std::string &name) {
  for (const Preset *preset : AllPresets())
    if (preset->name == name) return preset;
  return nullptr;
}

std::string PresetNameList() {
  std::string list;
  for (const Preset *preset : AllPresets()) list += (list.empty() ? "" : ", ") + preset->name;
  return list;
}

PresetAxis CentresAxis(const char *quantity, int count) {
  PresetAxis axis;
  axis.quantity = quantity;
  axis.count = count;
  return axis;
}

PresetAxis EdgesAxis(const char *quantity, int count) {
  PresetAxis axis = CentresAxis(quantity, count);
  axis.placement = TexelPlacement::kEdges;
  return axis;
}

}  // namespace lutbake
