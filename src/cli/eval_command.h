// `lutbake eval`: any table at any points (not only texel centres), with the
// error bound of each value. For debugging shaders and for the tests of the
// extreme corners.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "sampling_options.h"

namespace lutbake::cli {

struct EvalOptions {
  std::string table;
  // The coordinates' comma-separated lists of points, by option name
  // ("mu", "roughness", ...: lutbake::EvalCoordinateOptions).
  std::map<std::string, std::string> coordinates;
  // The model options' values, by option name ("ndf", ...: lutbake::ModelOptions).
  std::map<std::string, std::string> models;
  SamplingOptions sampling;
  int threads = 0;
  bool json = false;
  bool verbose = false;
};

void SetupEvalCommand(CLI::App &app, EvalOptions &options);
// `app` is the eval subcommand, to tell which options were given.
int RunEval(const EvalOptions &options, CLI::App &app);

}  // namespace lutbake::cli
