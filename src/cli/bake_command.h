// `lutbake bake`: options, their validation, and the run function.
#pragma once

#include <CLI/CLI.hpp>
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
  std::string ndf = "ggx";
  std::string smith = "correlated";
  std::string fresnel = "schlick";
  std::string sheenVisibility = "charlie";
  std::string sheenAlpha = "linear";
  int size = 0;     // 0: the per-table defaults
  int etaSize = 0;  // texels of a 3D table's eta axis; 0: its default
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

// Option values (already validated) to library enums; shared with report.
NdfKind ParseNdf(const std::string &name);
SmithForm ParseSmith(const std::string &name);
FresnelModel ParseFresnel(const std::string &name);

// The model options given (ndf, smith, fresnel, sheen-visibility,
// sheen-alpha; already validated) into a request's optional models.
template <typename Options, typename Request>
void ModelsOf(const Options &o, CLI::App &app, Request *r) {
  SheenVisibility visibility = SheenVisibility::kCharlie;
  SheenAlpha alpha = SheenAlpha::kLinear;
  if (app.count("--ndf")) r->ndf = ParseNdf(o.ndf);
  if (app.count("--smith")) r->smith = ParseSmith(o.smith);
  if (app.count("--fresnel")) r->fresnel = ParseFresnel(o.fresnel);
  if (app.count("--sheen-visibility") && ParseSheenVisibility(o.sheenVisibility, &visibility))
    r->sheenVisibility = visibility;
  if (app.count("--sheen-alpha") && ParseSheenAlpha(o.sheenAlpha, &alpha)) r->sheenAlpha = alpha;
}

void SetupBakeCommand(CLI::App &app, BakeOptions &options);

// Returns the process exit status: 0 success, 1 runtime failure (cannot
// write), 2 usage error found after parsing.
// `app` is the bake subcommand, to tell which options were given.
int RunBake(const BakeOptions &options, const std::string &commandLine, CLI::App &app);

}  // namespace lutbake::cli
