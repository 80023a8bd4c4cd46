// `lutbake eval`: any table at any points (not only texel centres), with the
// error bound of each value. For debugging shaders and for the tests of the
// extreme corners.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "sampling_options.h"

namespace lutbake::cli {

struct EvalOptions {
  std::string table;
  std::string mu;  // comma-separated lists of points
  std::string perceptualRoughness;
  std::string f0, eta, k, tint;  // Favg parameters
  std::string sigma;             // Oren-Nayar roughness, radians
  std::string ndf = "ggx";
  std::string smith = "correlated";
  std::string fresnel = "schlick";
  std::string sheenVisibility = "charlie";
  std::string sheenAlpha = "linear";
  SamplingOptions sampling;
  int threads = 0;
  bool json = false;
};

void SetupEvalCommand(CLI::App &app, EvalOptions &options);
// `app` is the eval subcommand, to tell which options were given.
int RunEval(const EvalOptions &options, CLI::App &app);

}  // namespace lutbake::cli
