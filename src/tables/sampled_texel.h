// The sampled estimators' driver, shared by every table that samples: a
// fixed number of samples, or rounds (doubling) until the bound is at most
// the tolerance, with the replicate spread and the unseen-event term as the
// bound. Private to the tables layer.
#pragma once

#include <algorithm>
#include <cstdint>

#include "lutbake/core/hash.h"
#include "lutbake/integrators/point_blocks.h"
#include "lutbake/integrators/replicated_integrator.h"
#include "lutbake/tables/settings.h"

namespace lutbake {

// Scrambled Sobol points for vndf and ndf; independent random points for
// the others.
inline PointSet PointSetOf(Estimator estimator) {
  return estimator == Estimator::kVisibleNormal || estimator == Estimator::kNdf
             ? PointSet::kScrambledSobol
             : PointSet::kIndependentRandom;
}

// Scrambled Sobol points are shared by every texel of a table (their
// trigonometry is then computed once, point_blocks.h): seeded by the table
// and --seed. Independent random points keep the texel's own seed.
// The bound the default panel rules are asked for: the run's tolerance, or
// the float32-exact default.
inline double PanelTolerance(const BakeSettings &s) {
  return s.tolerance > 0.0 ? s.tolerance : kDefaultQuadratureTolerance;
}
// The adaptive Gauss-Kronrod reference's target: a tolerance run asks it
// for EPS / 32, so that its reported bound (16 x the estimate plus the
// floor) stays below EPS down to 1e-9.
inline double AdaptiveTolerance(const BakeSettings &s) {
  return s.tolerance > 0.0 ? s.tolerance / (2.0 * kQuadratureErrorFactor)
                           : kQuadratureDefaultTolerance;
}

inline uint64_t SampleSeed(uint64_t tableSeedId, const BakeSettings &s, uint64_t pointSeed) {
  return PointSetOf(s.estimator) == PointSet::kScrambledSobol
             ? HashValues({tableSeedId, s.seed, 0x736f626f6cULL})
             : pointSeed;
}

// Runs a sampled estimator on one point: a fixed number of samples, or in
// rounds (doubling) until the bound is at most the tolerance. `batch`
// fills the weights of a block of points (PointView) for each channel.
// Every weight must lie in [0, maxWeight]. Returns false when a tolerance
// run decides that the quadrature is the cheaper way to EPS (the caller then
// integrates the point with it).
template <int Dims, int Channels, typename BatchFn>
bool SampleTexel(const BakeSettings &s, const BatchFn &batch, uint64_t samples, uint64_t seed,
                 PointValue *out, double maxWeight = 1.0) {
  const PointSet points = PointSetOf(s.estimator);
  const auto finish = [&](const ReplicatedAccumulator<Dims, Channels> &acc) {
    const ReplicatedEstimate<Channels> e = acc.Estimate();
    const double sigmas = StudentT99(acc.replicates() - 1);
    // The spread of the replicates cannot see an event rarer than about one
    // in N: GGX's tail past the horizon is such an event (probability up to
    // ~1e-4, weight 0 instead of ~1), and when no sample meets it every
    // replicate is off by the same amount. With weights in [0, W], an event
    // that N samples all missed has, at 99% confidence, probability below
    // -ln(0.01) / N, and moves the integral by at most W times that: the
    // bound adds it.
    const double unseen = maxWeight * kUnseenEventCount / static_cast<double>(acc.samples());
    for (int c = 0; c < Channels; ++c) {
      out->value[c] = e.mean[c];
      out->error[c] = sigmas * e.standardError[c] + unseen;
    }
    out->samples = acc.samples();
  };
  if (s.tolerance <= 0.0) {
    const int k =
        static_cast<int>(std::max<uint64_t>(1, std::min<uint64_t>(s.replicates, samples)));
    ReplicatedAccumulator<Dims, Channels> acc(k, seed, points);
    acc.ExtendTotalBatched(batch, samples);
    finish(acc);
    return true;
  }
  ReplicatedAccumulator<Dims, Channels> acc(s.replicates, seed, points);
  const uint64_t k = static_cast<uint64_t>(acc.replicates());
  // When the unseen-event term alone needs more samples than the quadrature
  // costs, no sampling round can pay off: go to the quadrature at once.
  const double minimumSamples = maxWeight * kUnseenEventCount / s.tolerance;
  if (s.allowQuadratureSwitch && minimumSamples > static_cast<double>(kQuadratureSwitchSamples))
    return false;
  uint64_t perReplicate = std::max<uint64_t>(2, samples / k);
  for (;;) {
    acc.ExtendBatched(batch, perReplicate);
    finish(acc);
    const double bound = *std::max_element(out->error, out->error + Channels);
    if (bound <= s.tolerance) return true;
    // Error ~ 1/N: the samples this texel would need.
    const double needed = static_cast<double>(acc.samples()) * bound / s.tolerance;
    if (s.allowQuadratureSwitch && needed > static_cast<double>(kQuadratureSwitchSamples))
      return false;
    if (2 * perReplicate * k > s.maxSamples) return true;  // caller sees bound > EPS
    perReplicate *= 2;
  }
}

}  // namespace lutbake
