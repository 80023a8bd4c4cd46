#include "lutbake/api/sampling.h"

#include <string>

#include "lutbake/core/error.h"

namespace lutbake {

void ApplySampling(const SamplingRequest &request, BakeSettings *s) {
  const bool tolerance = request.tolerance > 0.0;
  const bool samplingAsked = request.samples || request.replicates || request.samplingOnly;
  s->estimator = samplingAsked ? Estimator::kVisibleNormal : Estimator::kQuadrature;
  if (request.estimator) s->estimator = *request.estimator;
  s->tolerance = request.tolerance;
  s->samples = request.samples ? request.samples
               : tolerance     ? kToleranceStartSamples
                               : kDefaultSamples;
  s->replicates = request.replicates ? request.replicates
                  : tolerance        ? kToleranceReplicates
                                     : kDefaultReplicates;
  s->allowQuadratureSwitch = !request.samplingOnly;
  s->maxSamples = request.maxSamples.value_or(kDefaultMaxSamples);
  s->seed = request.seed.value_or(0);
  if (!tolerance && (request.samplingOnly || s->maxSamples != kDefaultMaxSamples))
    throw UsageError("--sampling-only and --max-samples apply only with --tolerance");
  if (IsQuadrature(s->estimator) && samplingAsked)
    throw UsageError(
        "--samples, --replicates and --sampling-only apply to the sampled estimators, not to "
        "--estimator " +
        std::string(ToString(s->estimator)));
}

}  // namespace lutbake
