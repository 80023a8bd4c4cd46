// `lutbake bake --preset NAME` (the textures an engine samples, and
// DIR/preset.json that describes them) and `lutbake presets` (the list).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "bake_command.h"

namespace lutbake::cli {

// Every preset name (the accepted --preset values).
std::vector<std::string> PresetNames();

// Bakes o.preset into o.outDir; `app` is the bake subcommand, to refuse the
// options a preset fixes. Returns the exit status.
int RunPresetBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app);

void SetupPresetsCommand(CLI::App &app, bool &json);
// Lists the presets, one line each (or one JSON object); returns 0.
int RunPresets(bool json);

}  // namespace lutbake::cli
