#include "preset_command.h"

#include <cstdio>
#include <iostream>

#include "lutbake/api/presets.h"

namespace lutbake::cli {

int RunPresetCheck(const std::string &dir, bool json) {
  PresetCheck check;
  try {
    check = CheckPresetDirectory(dir);
  } catch (const IoError &e) {
    // The directory was given right; the file in it cannot be used.
    std::cerr << "lutbake check: " << e.what() << "\n";
    return 1;
  }
  if (json) {
    std::cout << check.json << "\n";
    return check.pass ? 0 : 1;
  }
  for (const PresetFileCheck &f : check.files) {
    char line[400];
    std::snprintf(line, sizeof line, "%-4s %-40s max |stored - integral| %.2e (errorMax %.2e)%s%s\n",
                  f.pass ? "pass" : "FAIL", f.file.c_str(), f.worst, f.errorMax,
                  f.pass ? "" : ": ", f.problem.c_str());
    std::cout << line;
  }
  return check.pass ? 0 : 1;
}

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
