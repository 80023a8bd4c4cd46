// Randomised quasi-Monte Carlo with an error estimate from independent
// scrambles.
//
// A texel's N samples are split into K replicates (K = min(replicates, N));
// replicate k uses points 0 .. n_k - 1 of its own point set (n_k = N / K,
// the first N mod K replicates one more): Owen-scrambled Sobol points with
// seeds derived from (seed, k, dimension), or, for plain Monte Carlo,
// independent points (point_blocks.h). Each replicate mean m_k is an
// unbiased estimate of the integral, and the K of them are independent, so
//   estimate        = (1/K) sum_k m_k
//   standard error  = sqrt( sum_k (m_k - estimate)^2 / (K (K - 1)) ).
//
// The samples are evaluated in batches (up to a block of points at a time,
// which a SIMD kernel can take whole) and summed in chunks of 256 aligned
// on the sample index: within a chunk, sample i goes into partial sum
// i mod 4; a finished chunk's sum ((s0 + s1) + (s2 + s3)) is added to the
// replicate's total with Neumaier's compensated summation. The sum of the
// first n samples therefore depends on n alone, not on how they were
// batched, nor on which rounds of a tolerance run brought them in.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "lutbake/core/math.h"
#include "lutbake/integrators/point_blocks.h"

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

// Two-sided 99% quantile of Student's t with `dof` degrees of freedom: the
// error bound is this many standard errors, so that it holds for 99% of
// texels even though only K replicate means estimate the standard error.
double StudentT99(int dof);

// Samples per chunk of the summation (see above).
inline constexpr uint64_t kSumChunk = 256;

// The replicates of one texel, resumable: Extend(n) brings every replicate
// to n samples, continuing each replicate's own point sequence, so that a
// tolerance run's rounds (n, 2n, 4n, ...) end with exactly the estimate a
// single run of the final size gives.
//
// A batch function `batch(const PointView &points, double *out[Channels])`
// writes the weights of points.n samples; a sample function
// `sample(const double (&u)[Dims])` returns std::array<double, Channels> for
// one. Dims is 2 or 3.
template <int Dims, int Channels>
class ReplicatedAccumulator {
 public:
  static constexpr int kMaxReplicates = 64;
  static_assert(Dims >= 2 && Dims <= kMaxPointDimensions, "2 or 3 dimensions");

  ReplicatedAccumulator(int replicates, uint64_t seed, PointSet points)
      : replicates_(std::clamp(replicates, 1, kMaxReplicates)), seed_(seed), points_(points) {}

  int replicates() const { return replicates_; }
  uint64_t samplesPerReplicate() const { return sums_[0].count; }
  uint64_t samples() const {
    uint64_t total = 0;
    for (int r = 0; r < replicates_; ++r) total += sums_[r].count;
    return total;
  }

  // Replicate r to n samples (never fewer than it has), in batches.
  template <typename BatchFn>
  void ExtendReplicateBatched(const BatchFn &batch, int r, uint64_t n) {
    PointBlockStorage scratch;
    double buffer[Channels][kPointBlockSize];
    double *out[Channels];
    for (int c = 0; c < Channels; ++c) out[c] = buffer[c];
    while (sums_[r].count < n) {
      const uint64_t i = sums_[r].count, block = i / kPointBlockSize;
      const uint64_t offset = i % kPointBlockSize;
      const uint64_t count = std::min<uint64_t>(kPointBlockSize - offset, n - i);
      PointView view = PointBlock(points_, seed_, Dims, r, block, &scratch).Skip(offset);
      view.n = count;
      batch(view, out);
      Add(r, out, count);
    }
  }

  template <typename BatchFn>
  void ExtendBatched(const BatchFn &batch, uint64_t n) {
    for (int r = 0; r < replicates_; ++r) ExtendReplicateBatched(batch, r, n);
  }

  // N samples in all, split over the replicates: n = N / K each, the first
  // N mod K replicates one more.
  template <typename BatchFn>
  void ExtendTotalBatched(const BatchFn &batch, uint64_t total) {
    const uint64_t k = static_cast<uint64_t>(replicates_);
    for (int r = 0; r < replicates_; ++r)
      ExtendReplicateBatched(batch, r, total / k + (static_cast<uint64_t>(r) < total % k ? 1 : 0));
  }

  // The same with a function of one sample.
  template <typename SampleFn>
  void Extend(const SampleFn &sample, uint64_t n) {
    ExtendBatched(PerSample(sample), n);
  }
  template <typename SampleFn>
  void ExtendTotal(const SampleFn &sample, uint64_t total) {
    ExtendTotalBatched(PerSample(sample), total);
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
  struct ReplicateSum {
    uint64_t count = 0;
    std::array<CompensatedSum, Channels> total{};
    double chunk[Channels][4] = {};
  };

  template <typename SampleFn>
  static auto PerSample(const SampleFn &sample) {
    return [&sample](const PointView &points, double *out[Channels]) {
      for (size_t k = 0; k < points.n; ++k) {
        double u[Dims];
        for (int d = 0; d < Dims; ++d) u[d] = points.u[d][k];
        const std::array<double, Channels> value = sample(u);
        for (int c = 0; c < Channels; ++c) out[c][k] = value[c];
      }
    };
  }

  static double ChunkSum(const double (&s)[4]) { return (s[0] + s[1]) + (s[2] + s[3]); }

  void Add(int r, double *const weights[Channels], uint64_t count) {
    ReplicateSum &s = sums_[r];
    for (uint64_t k = 0; k < count; ++k) {
      const uint64_t i = s.count + k;
      for (int c = 0; c < Channels; ++c) s.chunk[c][i % 4] += weights[c][k];
      if ((i + 1) % kSumChunk == 0)
        for (int c = 0; c < Channels; ++c) {
          s.total[c].Add(ChunkSum(s.chunk[c]));
          for (double &partial : s.chunk[c]) partial = 0.0;
        }
    }
    s.count += count;
  }

  double ReplicateMean(int r, int c) const {
    const ReplicateSum &s = sums_[r];
    if (s.count == 0) return 0.0;
    return (s.total[c].Value() + ChunkSum(s.chunk[c])) / static_cast<double>(s.count);
  }

  int replicates_;
  uint64_t seed_;
  PointSet points_;
  ReplicateSum sums_[kMaxReplicates] = {};
};

// One-shot form: N samples split over K = min(replicates, N) replicates, the
// first N mod K replicates one more.
// sample(const double (&u)[Dims]) returns std::array<double, Channels>.
template <int Dims, int Channels, typename SampleFn>
ReplicatedEstimate<Channels> IntegrateReplicated(const SampleFn &sample, uint64_t samples,
                                                 int replicates, uint64_t seed,
                                                 PointSet points = PointSet::kScrambledSobol) {
  const int k = static_cast<int>(std::max<uint64_t>(1, std::min<uint64_t>(replicates, samples)));
  ReplicatedAccumulator<Dims, Channels> accumulator(k, seed, points);
  accumulator.ExtendTotal(sample, samples);
  return accumulator.Estimate();
}

}  // namespace lutbake
