// Baking a table: the axes of each table, the estimator per texel, the
// parallel loop, and the metadata that goes into every file.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "lutbake/models/fresnel.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"
#include "lutbake/tables/table.h"

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
// of a bake measured within 1e-4 of the reference (README;
// scripts/measure_default_error.sh reproduces it).
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

struct BakeSettings {
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  FresnelModel fresnel = FresnelModel::kSchlick;
  Estimator estimator = Estimator::kQuadrature;
  int sizeE = 32;
  int sizeEavg = 32;
  int sizeFavg = 32;
  int sizeDfg = 128;
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
};

// What a bake spent and achieved, per table.
struct BakeStats {
  uint64_t samples = 0;           // sampled estimator: samples over all texels
  uint64_t maxTexelSamples = 0;   // the most any texel used
  uint64_t quadratureTexels = 0;  // texels integrated by the quadrature
  uint64_t evaluations = 0;       // quadrature integrand evaluations
  uint64_t unconverged = 0;       // texels whose bound is above the tolerance
  double seconds = 0.0;
};

// Reports the fraction done in [0, 1]; called from worker threads, so it
// must be thread-safe. May be empty.
using ProgressFn = std::function<void(double)>;

// Axis definitions: every table states its axes here, in one place.
Axis RoughnessAxis(int count);
Axis MuAxis(int count);
void FresnelAxes(FresnelModel model, int count, Axis *x, Axis *y);

// The axes a table has by default (SPEC sections 2 and 3): mu and perceptual
// roughness over [0, 1], the Fresnel axes of FresnelAxes.
void DefaultAxes(TableKind kind, const BakeSettings &settings, Axis *x, Axis *y);

Table BakeTable(TableKind kind, const BakeSettings &settings, const ProgressFn &progress = {},
                BakeStats *stats = nullptr);
// The same on given axes (a bake plan's narrowed or listed roughness, its
// IORs): x and y as DefaultAxes would give them, in kind and order.
Table BakeTableOn(TableKind kind, const BakeSettings &settings, const Axis &x, const Axis &y,
                  const ProgressFn &progress = {}, BakeStats *stats = nullptr);

// The smallest non-zero alpha the albedo integrators accept (perceptual
// roughness 1e-12). Far below it alpha^2 leaves the normal doubles (alpha <
// 1e-154) and the grazing limit mu_o = 0 loses its scale; no renderer can
// tell a lobe 1e-24 rad wide from a mirror, and alpha = 0 is exact.
inline constexpr double kMinimumAlpha = 1e-24;

// One point, anywhere (not only at texel centres): its value in up to two
// channels, its error bound and what it cost.
struct PointValue {
  double value[2] = {0, 0};
  double error[2] = {0, 0};
  uint64_t samples = 0;
  uint64_t evaluations = 0;
  bool quadrature = false;
  bool exact = false;  // a closed form (the mirror, alpha = 0): error 0 by construction
};

// The seed of a sampled point's independent random points (vndf-random,
// cosine, uniform): a hash of the table, the point's coordinates (their bit
// patterns) and the user's seed. A bake seeds each texel with the seed of
// its centre; scrambled Sobol points are shared by a whole table instead
// (point_blocks.h). Either way `lutbake eval` at a texel centre with the
// bake's settings reproduces that texel bit for bit.
uint64_t PointSeed(TableKind kind, double x, double y, uint64_t seed);

// E (channel 0) or the split sum (A, B) at (mu_o, alpha), with the settings'
// estimator (a tolerance run when settings.tolerance > 0). mu_o in [0, 1]:
// mu_o = 0 is the grazing limit, evaluated by continuity (the integrands
// below are written in forms that stay finite there). alpha = 0 is the
// mirror, exact. Throws std::domain_error for alpha in (0, kMinimumAlpha),
// alpha > 1 or mu_o outside [0, 1].
PointValue EvaluateAlbedo(TableKind kind, const BakeSettings &settings, double mu_o, double alpha,
                          uint64_t pointSeed);
// E_avg(alpha) = 2 integral_0^1 E(mu) mu dmu, same conventions.
PointValue EvaluateAlbedoAverage(const BakeSettings &settings, double alpha, uint64_t pointSeed);
// F_avg of a Fresnel model at its parameters: x = F0 (Schlick) or eta
// (dielectric, conductor); y = k (conductor only). Deterministic quadrature.
PointValue EvaluateFresnelAverage(FresnelModel model, double x, double y);

// Samples per texel that a fixed-sample bake uses for a table (E_avg gets more).
uint64_t SamplesPerTexel(TableKind kind, const BakeSettings &settings);

const char *LutbakeVersion();

}  // namespace lutbake
