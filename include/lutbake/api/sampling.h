// How a texel (bake) or a point (eval) is integrated, as a request states it:
// the estimator, its budget, the tolerance and the seed. Unset fields take
// the defaults that ApplySampling documents.
#pragma once

#include <cstdint>
#include <optional>

#include "lutbake/tables/settings.h"

namespace lutbake {

struct SamplingRequest {
  // Unset: the quadrature (to `tolerance`, or float32-exact), unless
  // samples, replicates or samplingOnly ask for sampling: then visible-normal
  // sampling.
  std::optional<Estimator> estimator;
  uint64_t samples = 0;       // 0: kDefaultSamples, or kToleranceStartSamples with a tolerance
  int replicates = 0;         // 0: kDefaultReplicates, or kToleranceReplicates with a tolerance
  double tolerance = 0;       // 0: no tolerance run
  bool samplingOnly = false;  // tolerance runs: never switch to the quadrature
  std::optional<uint64_t> maxSamples;  // tolerance runs with samplingOnly: kDefaultMaxSamples
  std::optional<uint64_t> seed;        // 0 when unset
};

// Copies the request into `settings` (estimator, samples, replicates,
// tolerance, seed). Throws UsageError for a combination that makes no sense
// (--sampling-only without --tolerance; --samples with the quadrature).
void ApplySampling(const SamplingRequest &request, BakeSettings *settings);

}  // namespace lutbake
