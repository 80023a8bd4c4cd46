// The engine presets as a caller sees them: the list (`lutbake presets`), and
// checking a directory a preset bake wrote (`lutbake check DIR` where DIR
// holds preset.json). Baking one is lutbake::Bake with request.preset set.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lutbake/presets/preset.h"

namespace lutbake {

// `lutbake presets --json`: {"presets": [{"name", "engine", "summary", "files"}]},
// with estimate: each preset's "estimate" {"seconds", "cpuSeconds",
// "threads", "texels", "timedTexels"} (EstimatePresetBake).
std::string PresetListJson(bool estimate = false);
// `lutbake presets`: one line per preset, its name and summary, and with
// estimate a second line with how long baking it will take.
std::string PresetListText(bool estimate = false);

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

// One file of a preset directory, read back and held to the re-integrated
// texels: every stored value within the file's stated errorMax plus the new
// value's own bound.
struct PresetFileCheck {
  std::string file;
  bool pass = false;
  double worst = 0.0;     // max |stored - integral|
  double errorMax = 0.0;  // as preset.json states it
  std::string problem;    // why it failed, if it did
};

struct PresetCheck {
  std::string preset;
  std::vector<PresetFileCheck> files;
  bool pass = false;
  std::string json;  // `check --json`'s object
};

// Throws IoError when preset.json cannot be used; a file that fails is a
// PresetFileCheck with pass false.
PresetCheck CheckPresetDirectory(const std::string &dir);

}  // namespace lutbake
