#include "preset_command.h"

#include <cstdio>
#include <iostream>

#include "lutbake/api/presets.h"

namespace lutbake::cli {

void SetupPresetsCommand(CLI::App &app, bool &json) {
  app.add_flag("--json", json, "Print the presets as one JSON object");
  app.footer("Example:\n  lutbake presets\n  lutbake bake --preset filament --out dfg");
}

int RunPresets(bool json) {
  if (json) {
    std::cout << PresetListJson() << "\n";
    return 0;
  }
  for (const Preset *preset : AllPresets())
    std::printf("%-22s %s\n", preset->name.c_str(), preset->summary.c_str());
  return 0;
}

}  // namespace lutbake::cli
