// `lutbake presets` (the list), and the printing of `lutbake check DIR` for
// a preset's directory. Baking a preset is `lutbake bake --preset`
// (bake_command.h), which calls lutbake::Bake.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace lutbake::cli {

// `lutbake check DIR` where DIR holds a preset.json (lutbake::CheckPresetDirectory):
// one line per file, or one JSON object. Returns 0 (all hold) or 1.
int RunPresetCheck(const std::string &dir, bool json);

void SetupPresetsCommand(CLI::App &app, bool &json);
// Lists the presets, one line each (or one JSON object); returns 0.
int RunPresets(bool json);

}  // namespace lutbake::cli
