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

// The estimator of a (validated) name.
Estimator EstimatorNamed(const std::string &name);

// `unit` names what gets the samples in the help texts: "texel" or "point".
void AddSamplingOptions(CLI::App &app, SamplingOptions &options, const std::string &unit);

// The request the options describe (lutbake::ApplySampling reads it); `app`
// tells which options were given.
SamplingRequest SamplingRequestOf(const SamplingOptions &options, CLI::App &app);

// Copies the options into `settings`. Without --estimator the estimator is
// the quadrature (to --tolerance, or float32-exact), unless --samples,
// --replicates or --sampling-only ask for sampling: then visible-normal
// sampling. Returns 0, or 2 after printing "lutbake COMMAND: ..." for a
// combination that makes no sense.
int ApplySamplingOptions(const std::string &command, const SamplingOptions &options,
                         BakeSettings *settings);

}  // namespace lutbake::cli
