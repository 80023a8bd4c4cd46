// `lutbake bake`: options, their validation, and the run function.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/tables/bake.h"
#include "plan_command.h"
#include "sampling_options.h"

namespace lutbake::cli {

struct BakeOptions {
  std::string outDir;
  std::string tables = "E,Eavg,Favg,dfg";
  std::map<std::string, std::string> models;  // by option name ("ndf", ...: lutbake::ModelOptions)
  int size = 0;                               // 0: the per-table defaults
  int etaSize = 0;                            // texels of a 3D table's eta axis; 0: its default
  SamplingOptions sampling;
  bool errorMap = false;
  int threads = 0;  // 0: all cores
  std::string formats = "exr,bin,header";
  std::string headerNamespace = "lutbake_luts";
  std::string headerType = "float";
  std::string binType = "float";
  double fitTolerance = 4.9e-4;
  std::string shaders;  // --shader glsl,hlsl,wgsl,msl: lutbake.<ext> beside the tables
  bool json = false, quiet = false, verbose = false;
  SceneOptions scene;  // --scene / --manifest: bake a plan
  bool skipUnsupported = false;
  std::string preset;       // --preset NAME: an engine's textures (preset_command.h)
  std::string presetFiles;  // --files A,B: only these of the preset's files
};

void SetupBakeCommand(CLI::App &app, BakeOptions &options);

// Returns the process exit status: 0 success, 1 runtime failure (cannot
// write), 2 usage error found after parsing.
// `app` is the bake subcommand, to tell which options were given.
int RunBake(const BakeOptions &options, const std::string &commandLine, CLI::App &app);

}  // namespace lutbake::cli
