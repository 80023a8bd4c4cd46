// Baking a table: the axes of each table, the estimator per texel, the
// parallel loop, and the metadata that goes into every file.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "lutbake/fresnel.h"
#include "lutbake/ndf.h"
#include "lutbake/smith.h"
#include "lutbake/table.h"

namespace lutbake {

enum class Estimator {
  kVisibleNormal,  // visible-normal sampling, scrambled Sobol points (default)
  kNdf,            // plain NDF sampling, scrambled Sobol points
  kQuadrature,     // deterministic nested Gauss-Kronrod (reference_integrator.h)
};

std::string_view ToString(Estimator estimator);

// Samples per texel of E and dfg by default: the smallest power of two at
// which the default bake measured below 1e-4 at every checked texel against
// the quadrature reference (README, "Accuracy of the default bake";
// scripts/measure_default_error.sh reproduces it).
inline constexpr uint64_t kDefaultSamples = 65536;
// E_avg integrates over mu as well (a 3D integral per texel); it gets as many
// samples per texel as a whole 32-texel row of E.
inline constexpr uint64_t kAverageSampleFactor = 32;
// Independent scrambles per texel. Randomised QMC converges about as 1/N
// here, so K replicates of N/K points cost sqrt(K) in error against one
// scramble of N points: K = 4 keeps that loss to 2x.
inline constexpr int kDefaultReplicates = 4;
// The error bound written into files: the two-sided 99% quantile of Student's
// t with K - 1 = 3 degrees of freedom times the standard error, so that the
// bound holds for 99% of texels even though the spread of only 4 replicate
// means estimates the standard error.
inline constexpr double kErrorSigmas = 5.841;

struct BakeSettings {
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  FresnelModel fresnel = FresnelModel::kSchlick;
  Estimator estimator = Estimator::kVisibleNormal;
  int sizeE = 32;
  int sizeEavg = 32;
  int sizeFavg = 32;
  int sizeDfg = 128;
  uint64_t samples = kDefaultSamples;
  uint64_t seed = 0;
  int replicates = kDefaultReplicates;
  std::string commandLine;  // recorded in the metadata
};

// Reports the fraction done in [0, 1]; called from worker threads, so it
// must be thread-safe. May be empty.
using ProgressFn = std::function<void(double)>;

// Axis definitions: every table states its axes here, in one place.
Axis RoughnessAxis(int count);
Axis MuAxis(int count);
void FresnelAxes(FresnelModel model, int count, Axis *x, Axis *y);

Table BakeTable(TableKind kind, const BakeSettings &settings, const ProgressFn &progress = {});

// Samples per texel that BakeTable uses for a table (E_avg gets more).
uint64_t SamplesPerTexel(TableKind kind, const BakeSettings &settings);

const char *LutbakeVersion();

}  // namespace lutbake
