// Randomised quasi-Monte Carlo with an error estimate from independent
// scrambles.
//
// A texel's N samples are split into K replicates (K = min(replicates, N));
// replicate k uses Sobol points 0 .. n_k - 1 (n_k = N / K, the first N mod K
// replicates one more), Owen-scrambled with seeds derived from
// (texelSeed, k, dimension); or, for plain Monte Carlo, independent points. Each replicate mean m_k
// is an unbiased estimate of the integral, and the K of them are independent, so
//   estimate        = (1/K) sum_k m_k
//   standard error  = sqrt( sum_k (m_k - estimate)^2 / (K (K - 1)) ).
// Sums over samples use Neumaier's compensated summation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "lutbake/hash.h"
#include "lutbake/math.h"
#include "lutbake/sobol.h"

namespace lutbake {

template <int Channels>
struct ReplicatedEstimate {
  std::array<double, Channels> mean{};
  std::array<double, Channels> standardError{};
};

// Compensated running sum (Neumaier): error independent of the number of terms
// to first order.
struct CompensatedSum {
  double sum = 0.0, compensation = 0.0;
  void Add(double x) {
    const double t = sum + x;
    if (std::abs(sum) >= std::abs(x))
      compensation += (sum - t) + x;
    else
      compensation += (x - t) + sum;
    sum = t;
  }
  double Value() const { return sum + compensation; }
};

enum class PointSet {
  kScrambledSobol,     // Owen-scrambled Sobol points, one scramble per replicate
  kIndependentRandom,  // independent uniform points (plain Monte Carlo)
};

// Two-sided 99% quantile of Student's t with `dof` degrees of freedom: the
// error bound is this many standard errors, so that it holds for 99% of
// texels even though only K replicate means estimate the standard error.
double StudentT99(int dof);

// The replicates of one texel, resumable: Extend(n) brings every replicate
// to n samples, continuing each replicate's own point sequence, so that a
// tolerance run's rounds (n, 2n, 4n, ...) end with exactly the estimate a
// single run of the final size gives.
template <int Dims, int Channels>
class ReplicatedAccumulator {
 public:
  static constexpr int kMaxReplicates = 64;

  ReplicatedAccumulator(int replicates, uint64_t texelSeed, PointSet points)
      : replicates_(std::clamp(replicates, 1, kMaxReplicates)), points_(points) {
    static_assert(Dims <= kSobolDimensions, "not enough Sobol dimensions");
    for (int r = 0; r < replicates_; ++r) {
      for (int d = 0; d < Dims; ++d)
        seeds_[r][d] = HashValues({texelSeed, static_cast<uint64_t>(r), static_cast<uint64_t>(d)});
    }
  }

  int replicates() const { return replicates_; }
  uint64_t samplesPerReplicate() const { return counts_[0]; }
  uint64_t samples() const {
    uint64_t total = 0;
    for (int r = 0; r < replicates_; ++r) total += counts_[r];
    return total;
  }

  // Replicate r to n samples (never fewer than it has).
  template <typename SampleFn>
  void ExtendReplicate(const SampleFn &sample, int r, uint64_t n) {
    for (uint64_t i = counts_[r]; i < n; ++i) {
      double u[Dims];
      if (points_ == PointSet::kScrambledSobol) {
        for (int d = 0; d < Dims; ++d)
          u[d] = ScrambledSobol(static_cast<uint32_t>(i), d, static_cast<uint32_t>(seeds_[r][d]));
      } else {
        // Counter-based: point i of replicate r is a hash of both, so any
        // prefix of the stream is reproducible without replaying it.
        for (int d = 0; d < Dims; ++d)
          u[d] = (static_cast<double>(MixBits(seeds_[r][d] + MixBits(i)) >> 11) + 0.5) * 0x1p-53;
      }
      const std::array<double, Channels> value = sample(u);
      for (int c = 0; c < Channels; ++c) sums_[r][c].Add(value[c]);
    }
    counts_[r] = std::max(counts_[r], n);
  }

  template <typename SampleFn>
  void Extend(const SampleFn &sample, uint64_t n) {
    for (int r = 0; r < replicates_; ++r) ExtendReplicate(sample, r, n);
  }

  // N samples in all, split over the replicates: n = N / K each, the first
  // N mod K replicates one more.
  template <typename SampleFn>
  void ExtendTotal(const SampleFn &sample, uint64_t total) {
    const uint64_t k = static_cast<uint64_t>(replicates_);
    for (int r = 0; r < replicates_; ++r)
      ExtendReplicate(sample, r, total / k + (static_cast<uint64_t>(r) < total % k ? 1 : 0));
  }

  ReplicatedEstimate<Channels> Estimate() const {
    ReplicatedEstimate<Channels> result;
    for (int c = 0; c < Channels; ++c) {
      double mean = 0.0;
      for (int r = 0; r < replicates_; ++r) mean += ReplicateMean(r, c);
      mean /= replicates_;
      double spread = 0.0;
      for (int r = 0; r < replicates_; ++r) spread += Sqr(ReplicateMean(r, c) - mean);
      result.mean[c] = mean;
      result.standardError[c] =
          replicates_ > 1
              ? std::sqrt(spread / (static_cast<double>(replicates_) * (replicates_ - 1)))
              : 0.0;
    }
    return result;
  }

 private:
  double ReplicateMean(int r, int c) const {
    return counts_[r] ? sums_[r][c].Value() / static_cast<double>(counts_[r]) : 0.0;
  }

  int replicates_;
  PointSet points_;
  uint64_t seeds_[kMaxReplicates][Dims];
  uint64_t counts_[kMaxReplicates] = {};
  std::array<CompensatedSum, Channels> sums_[kMaxReplicates] = {};
};

// One-shot form: N samples split over K = min(replicates, N) replicates, the
// first N mod K replicates one sample more.
// sample(const double (&u)[Dims]) returns std::array<double, Channels>.
template <int Dims, int Channels, typename SampleFn>
ReplicatedEstimate<Channels> IntegrateReplicated(const SampleFn &sample, uint64_t samples,
                                                 int replicates, uint64_t texelSeed,
                                                 PointSet points = PointSet::kScrambledSobol) {
  const int k = static_cast<int>(std::max<uint64_t>(1, std::min<uint64_t>(replicates, samples)));
  ReplicatedAccumulator<Dims, Channels> accumulator(k, texelSeed, points);
  accumulator.ExtendTotal(sample, samples);
  return accumulator.Estimate();
}

}  // namespace lutbake
