// `lutbake presets`: the list. Baking a preset is `lutbake bake --preset`
// (lutbake::Bake), checking one `lutbake check DIR` (lutbake::Check).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace lutbake::cli {

void SetupPresetsCommand(CLI::App &app, bool &json);
// Lists the presets, one line each (or one JSON object); returns 0.
int RunPresets(bool json);

}  // namespace lutbake::cli
