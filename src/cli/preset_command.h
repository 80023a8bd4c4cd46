// `lutbake bake --preset NAME` (the textures an engine samples, and
// DIR/preset.json that describes them) and `lutbake presets` (the list).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "bake_command.h"
#include "lutbake/presets/preset.h"

namespace lutbake::cli {

// Every preset name (the accepted --preset values).
std::vector<std::string> PresetNames();

// Bakes o.preset into o.outDir; `app` is the bake subcommand, to refuse the
// options a preset fixes. Returns the exit status.
int RunPresetBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app);

// What `check` takes from a preset directory's preset.json: the preset it
// names, and the errorMax stated for each file it lists.
struct PresetListing {
  const Preset *preset = nullptr;
  std::map<std::string, double> errorMaxByFile;
};

// Reads `manifestPath` (at most 16 MiB of JSON): "preset" must name a
// preset, "files" must be an array of objects whose "file" is a string and
// "errorMax" a number in [0, 1]; other members are ignored. Throws IoError
// naming the file and what is accepted.
PresetListing ReadPresetListing(const std::string &manifestPath);

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
