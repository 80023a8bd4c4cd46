#include "sampling_options.h"

#include "cli_util.h"

namespace lutbake::cli {

namespace {
constexpr uint64_t kMaxSamples = uint64_t{1} << 30;
}  // namespace

void AddSamplingOptions(CLI::App &app, SamplingOptions &o, const std::string &unit) {
  app.add_option("--estimator", o.estimator,
                 "quadrature (the default): panel Gauss-Legendre, deterministic, bound below 1e-8 "
                 "(or --tolerance); vndf (the default once --samples is given), vndf-random: "
                 "visible normals, Sobol or random points; ndf, cosine, uniform: baselines; "
                 "adaptive: Gauss-Kronrod (the reference of lutbake check)")
      ->type_name("NAME")
      ->check(OneOf(EstimatorNames()));
  app.add_option("--samples", o.samples,
                 "Samples per " + unit +
                     " of E and dfg (Eavg: 32x as many), sampled (visible normals unless "
                     "--estimator says otherwise); at least 2 so that the error can be "
                     "estimated. With a sampled --estimator: default 65536; with --tolerance, the "
                     "first round (default 1024)")
      ->type_name("N")
      ->check(InRange<uint64_t>(2, kMaxSamples, "samples per " + unit));
  app.add_option("--replicates", o.replicates,
                 "Independent scrambles per " + unit +
                     " whose spread gives the error bound (default 4; 8 with --tolerance)")
      ->type_name("K")
      ->check(InRange(2, 64, "replicates"));
  app.add_option("--tolerance", o.tolerance,
                 "Refine every " + unit +
                     " of E, Eavg and dfg until its integration bound is at most EPS: quadrature "
                     "orders, or sampled rounds that double the samples, switching to the "
                     "quadrature where cheaper. Files add their storage's rounding (float32: up to "
                     "3e-8; --bin-type double keeps it out)")
      ->type_name("EPS")
      ->check(RealInRange(1e-9, 0.1, "a number from 1e-9 to 0.1"));
  app.add_flag("--sampling-only", o.samplingOnly,
               "With --tolerance: never switch to the quadrature; sampling continues up to "
               "--max-samples");
  app.add_option("--max-samples", o.maxSamples,
                 "With --tolerance --sampling-only: most samples per " + unit + " (default 2^26)")
      ->type_name("N")
      ->check(InRange<uint64_t>(2, uint64_t{1} << 36, "samples per " + unit));
  AddSeedOption(app, o.seed, "Seed of the point-set scrambling");
}

SamplingRequest SamplingRequestOf(const SamplingOptions &o, CLI::App &app) {
  SamplingRequest r;
  Estimator estimator = Estimator::kVisibleNormal;
  if (!o.estimator.empty() && ParseEstimator(o.estimator, &estimator)) r.estimator = estimator;
  r.samples = o.samples;
  r.replicates = o.replicates;
  r.tolerance = o.tolerance;
  r.samplingOnly = o.samplingOnly;
  if (app.count("--max-samples") > 0) r.maxSamples = o.maxSamples;
  if (app.count("--seed") > 0) r.seed = o.seed;
  return r;
}

}  // namespace lutbake::cli
