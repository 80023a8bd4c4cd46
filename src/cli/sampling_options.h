// The options that choose how a point or texel is integrated (estimator,
// samples, replicates, tolerance, seed), shared by `bake` and `eval`.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "lutbake/api/sampling.h"
#include "lutbake/tables/bake.h"

namespace lutbake::cli {

struct SamplingOptions {
  std::string estimator;  // empty: the command's default
  uint64_t samples = 0;   // 0: kDefaultSamples, or kToleranceStartSamples with --tolerance
  uint64_t seed = 0;
  int replicates = 0;    // 0: kDefaultReplicates, or kToleranceReplicates with --tolerance
  double tolerance = 0;  // 0: a fixed number of samples
  bool samplingOnly = false;
  uint64_t maxSamples = kDefaultMaxSamples;
};

// `unit` names what gets the samples in the help texts: "texel" or "point".
void AddSamplingOptions(CLI::App &app, SamplingOptions &options, const std::string &unit);

// The request the options describe (lutbake::ApplySampling reads it); `app`
// tells which options were given.
SamplingRequest SamplingRequestOf(const SamplingOptions &options, CLI::App &app);

}  // namespace lutbake::cli
