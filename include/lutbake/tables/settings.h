// The settings of a bake or an evaluation: the models, the estimator and
// its budget, the sizes; and what one point's integral returns. Every
// table definition (table_definition.h) reads the fields it needs.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "lutbake/core/cancellation.h"
#include "lutbake/models/fresnel.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/sheen.h"
#include "lutbake/models/smith.h"

namespace lutbake {

enum class Estimator {
  kQuadrature,           // panel Gauss-Legendre, two orders (albedo_quadrature.h): the default
  kVisibleNormal,        // visible-normal sampling, scrambled Sobol points
  kVisibleNormalRandom,  // visible-normal sampling, independent random points
  kNdf,                  // NDF sampling, scrambled Sobol points
  kCosine,               // cosine-weighted light directions, independent random points
  kUniform,              // uniform hemisphere light directions, independent random points
  kAdaptiveQuadrature,   // nested adaptive Gauss-Kronrod (reference_integrator.h): the
                         // reference that `lutbake check` and the tests hold tables to
};

inline constexpr Estimator kAllEstimators[] = {
    Estimator::kUniform,       Estimator::kCosine,
    Estimator::kNdf,           Estimator::kVisibleNormalRandom,
    Estimator::kVisibleNormal, Estimator::kAdaptiveQuadrature,
    Estimator::kQuadrature};

// The deterministic integrators (no samples, no seed).
constexpr bool IsQuadrature(Estimator e) {
  return e == Estimator::kQuadrature || e == Estimator::kAdaptiveQuadrature;
}

// "vndf", "vndf-random", "ndf", "cosine", "uniform", "adaptive", "quadrature".
std::string_view ToString(Estimator estimator);
bool ParseEstimator(std::string_view name, Estimator *estimator);

// The integration bound a default bake (no --samples, no --tolerance) asks
// of every texel: with the float32 rounding of the stored value (at most
// 3e-8 below 1) the stated bound stays below 4e-8, under 1e-7 everywhere.
inline constexpr double kDefaultQuadratureTolerance = 1e-8;
// Samples per texel of E and dfg when a sampled estimator is asked for
// without --samples: the smallest power of two at which every checked texel
// of a bake measured within 1e-4 of the reference (docs/accuracy-and-speed.md;
// tools/measure_default_error.sh reproduces it).
inline constexpr uint64_t kDefaultSamples = 65536;
// First round of a tolerance run: samples per texel before the first check.
inline constexpr uint64_t kToleranceStartSamples = 1024;
// E_avg integrates over mu as well (a 3D integral per texel); it gets as many
// samples per texel as a whole 32-texel row of E.
inline constexpr uint64_t kAverageSampleFactor = 32;
// Independent scrambles per texel. Randomised QMC converges about as 1/N
// here, so K replicates of N/K points cost sqrt(K) in error against one
// scramble of N points: K = 4 keeps that loss to 2x.
inline constexpr int kDefaultReplicates = 4;
// A tolerance run stops a texel as soon as its bound is below EPS, so the
// bound must not be fooled by a replicate spread that is small by chance:
// K = 8 (7 degrees of freedom) makes that rare.
inline constexpr int kToleranceReplicates = 8;
// In a tolerance run, a sampled texel whose bound predicts (error ~ 1/N, the
// rate `lutbake report` measures for the sampled estimators) more than this
// many samples to reach EPS is integrated by the quadrature instead, which
// costs about as much: a texel of the panel quadrature takes 5.1 us, 860
// visible-normal samples at 167 million a second (scripts/benchmark.sh).
inline constexpr uint64_t kQuadratureSwitchSamples = 1024;
// A sampled texel's bound adds kUnseenEventCount / N for events that none of
// its N samples met (-ln 0.01: bake.cpp, SampleTexel, says why).
inline constexpr double kUnseenEventCount = 4.605170185988091;
// The adaptive quadrature's error estimate is the sum of |K15 - G7| over its
// intervals plus the inner integrals' worst estimate. It can be too small:
// against a reference at 1e-13 over 1764 points (the extreme grid and 40
// mu per roughness, both NDFs and Smith forms) at tolerances 1.25e-5 to
// 1.25e-9, the real error exceeded the estimate by up to 11.4x (99% of
// points within 2.3x): the horizon's boundary layer in G2, of width ~alpha
// in theta, is far narrower than the last inner interval. At tolerance 1e-10
// and below the nested refinement left errors up to 8e-11. The bound a
// quadrature texel reports is therefore kQuadratureErrorFactor x the
// estimate + the floor.
inline constexpr double kQuadratureErrorFactor = 16.0;
inline constexpr double kQuadratureErrorFloor = 1e-10;
// Most samples per texel a --sampling-only tolerance run may spend (by default).
inline constexpr uint64_t kDefaultMaxSamples = uint64_t{1} << 26;
// Default tolerance of the adaptive quadrature outside tolerance runs.
inline constexpr double kQuadratureDefaultTolerance = 1e-12;

// How a roughness parameter r gives an NDF's alpha: linear alpha = r,
// squared alpha = r^2 (perceptual roughness). The sheen tables' roughness
// axis (glTF's sheenRoughness) takes either (BakeSettings::sheenAlpha); an
// engine preset states its own for each lobe (presets/preset.h, PresetModel).
enum class AlphaMapping { kLinear, kSquared };
// Every mapping, in the order the command line offers them.
inline constexpr AlphaMapping kAllAlphaMappings[] = {AlphaMapping::kLinear, AlphaMapping::kSquared};
// The sheen tables' option by its older name.
using SheenAlpha = AlphaMapping;
constexpr double AlphaFromRoughness(AlphaMapping mapping, double r) {
  return mapping == AlphaMapping::kSquared ? r * r : r;
}
// "linear", "squared".
std::string_view ToString(AlphaMapping mapping);
bool ParseSheenAlpha(std::string_view text, AlphaMapping *mapping);

struct BakeSettings {
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  FresnelModel fresnel = FresnelModel::kSchlick;
  SheenVisibility sheenVisibility = SheenVisibility::kCharlie;
  SheenAlpha sheenAlpha = SheenAlpha::kLinear;
  Estimator estimator = Estimator::kQuadrature;
  // Texels per axis: tableSizes[name] for a table listed there, else size,
  // else (0) the table's own default (TableDefinition::DefaultSize).
  int size = 0;
  std::map<std::string, int> tableSizes;
  // Texels of a 3D table's third axis (eta): 0 for the table's own default
  // (TableDefinition::DefaultDepth).
  int depthSize = 0;
  // Fixed runs: samples per texel. Tolerance runs: the first round.
  uint64_t samples = kDefaultSamples;
  uint64_t seed = 0;
  int replicates = kDefaultReplicates;
  // Tolerance run when > 0: every texel refined until its bound is <= this.
  // 0: the quadrature to kDefaultQuadratureTolerance, or the sampled
  // estimators with `samples` samples.
  double tolerance = 0.0;
  // Tolerance runs: may a texel switch to the quadrature (see above)? If
  // not, sampling alone continues up to maxSamples.
  bool allowQuadratureSwitch = true;
  uint64_t maxSamples = kDefaultMaxSamples;
  std::string commandLine;  // recorded in the metadata
  // Polled between texels when set: a bake whose token is cancelled stops
  // and throws Cancelled (cancellation.h). Not part of the result.
  const CancellationToken *cancellation = nullptr;

  // The texels per axis of the table called `name` whose default is `defaultSize`.
  int SizeFor(const std::string &name, int defaultSize) const {
    const auto it = tableSizes.find(name);
    if (it != tableSizes.end() && it->second > 0) return it->second;
    return size > 0 ? size : defaultSize;
  }
};

// The smallest non-zero alpha the albedo integrators accept (perceptual
// roughness 1e-12). Far below it alpha^2 leaves the normal doubles (alpha <
// 1e-154) and the grazing limit mu_o = 0 loses its scale; no renderer can
// tell a lobe 1e-24 rad wide from a mirror, and alpha = 0 is exact.
inline constexpr double kMinimumAlpha = 1e-24;

// The most channels a table holds (an LTC table's six: ltc_ggx.cpp).
inline constexpr int kMaxTableChannels = 6;

// One point, anywhere (not only at texel centres): its value in up to
// kMaxTableChannels channels, its error bound and what it cost.
struct PointValue {
  double value[kMaxTableChannels] = {};
  double error[kMaxTableChannels] = {};
  uint64_t samples = 0;
  uint64_t evaluations = 0;
  bool quadrature = false;
  bool exact = false;  // a closed form (the mirror, alpha = 0): error 0 by construction
};

}  // namespace lutbake
