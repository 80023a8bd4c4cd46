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

// `lutbake check DIR` where DIR holds a preset.json: every file it lists is
// read back, its size and channels compared with preset.json, and every
// stored value with the preset's texel integrated again, within the file's
// stated errorMax plus the new value's own bound. Returns 0 (all hold), 1
// (a file fails or is unreadable) or 2 (preset.json malformed).
int CheckPresetDirectory(const std::string &dir, bool json);

void SetupPresetsCommand(CLI::App &app, bool &json);
// Lists the presets, one line each (or one JSON object); returns 0.
int RunPresets(bool json);

}  // namespace lutbake::cli
