#include "preset_command.h"

#include <iostream>

#include "lutbake/api/presets.h"

namespace lutbake::cli {

void SetupPresetsCommand(CLI::App &app, bool &json) {
  app.add_flag("--json", json, "Print the presets as one JSON object");
  app.footer("Example:\n  lutbake presets\n  lutbake bake --preset filament --out dfg");
}

int RunPresets(bool json) {
  std::cout << (json ? PresetListJson(true) + "\n" : PresetListText(true));
  return 0;
}

}  // namespace lutbake::cli
