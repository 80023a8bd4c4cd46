// Randomised quasi-Monte Carlo with an error estimate from independent
// scrambles.
//
// A texel's N samples are split into K replicates (K = min(replicates, N));
// replicate k uses Sobol points 0 .. n_k - 1 (n_k = N / K, the first N mod K
// replicates one more), Owen-scrambled with seeds derived from
// (texelSeed, k, dimension). Each replicate mean m_k is an unbiased estimate
// of the integral, and the K of them are independent, so
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

// sample(const double (&u)[Dims]) returns std::array<double, Channels>.
template <int Dims, int Channels, typename SampleFn>
ReplicatedEstimate<Channels> IntegrateReplicated(const SampleFn &sample, uint64_t samples,
                                                 int replicates, uint64_t texelSeed) {
  static_assert(Dims <= kSobolDimensions, "not enough Sobol dimensions");
  const uint64_t k = std::max<uint64_t>(1, std::min<uint64_t>(replicates, samples));
  std::array<std::array<double, Channels>, 64> replicateMeans{};
  const uint64_t kUsed = std::min<uint64_t>(k, replicateMeans.size());
  for (uint64_t r = 0; r < kUsed; ++r) {
    const uint64_t n = samples / kUsed + (r < samples % kUsed ? 1 : 0);
    uint32_t seeds[Dims];
    for (int d = 0; d < Dims; ++d)
      seeds[d] = static_cast<uint32_t>(HashValues({texelSeed, r, static_cast<uint64_t>(d)}));
    std::array<CompensatedSum, Channels> sums{};
    for (uint64_t i = 0; i < n; ++i) {
      double u[Dims];
      for (int d = 0; d < Dims; ++d) u[d] = ScrambledSobol(static_cast<uint32_t>(i), d, seeds[d]);
      const std::array<double, Channels> value = sample(u);
      for (int c = 0; c < Channels; ++c) sums[c].Add(value[c]);
    }
    for (int c = 0; c < Channels; ++c)
      replicateMeans[r][c] = sums[c].Value() / static_cast<double>(n);
  }
  ReplicatedEstimate<Channels> result;
  for (int c = 0; c < Channels; ++c) {
    double mean = 0.0;
    for (uint64_t r = 0; r < kUsed; ++r) mean += replicateMeans[r][c];
    mean /= static_cast<double>(kUsed);
    double spread = 0.0;
    for (uint64_t r = 0; r < kUsed; ++r) spread += Sqr(replicateMeans[r][c] - mean);
    result.mean[c] = mean;
    result.standardError[c] =
        kUsed > 1 ? std::sqrt(spread / static_cast<double>(kUsed * (kUsed - 1))) : 0.0;
  }
  return result;
}

}  // namespace lutbake
