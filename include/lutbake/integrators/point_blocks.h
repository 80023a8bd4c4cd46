// The points of the sampled estimators, in blocks of consecutive indices.
//
// Replicate r's point i has coordinates u_d, d < dims:
//   scrambled Sobol:     ScrambledSobol(i, d, seed_rd)  (sobol.h)
//   independent random:  (MixBits(seed_rd + MixBits(i)) >> 11 + 1/2) 2^-53
// with seed_rd = HashValues({seed, r, d}); and the azimuth of the
// visible-normal sampler, phi = 2 pi u_a for a = dims - 2, comes with
// cos(phi) and sin(phi). A bake seeds its Sobol points per table, not per
// texel: every texel of a table integrates with the same point sets
// (independent scrambles across replicates, so each texel's error estimate
// stays honest), and the process-wide cache here computes each block, its
// Sobol bits, scrambles and trigonometry, once for all of them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace lutbake {

enum class PointSet {
  kScrambledSobol,     // Owen-scrambled Sobol points, one scramble per replicate
  kIndependentRandom,  // independent uniform points (plain Monte Carlo)
};

inline constexpr int kMaxPointDimensions = 3;
inline constexpr size_t kPointBlockSize = 1024;

// n consecutive points of one replicate: coordinate d of the k-th is
// u[d][k]; cosPhi[k], sinPhi[k] are cos and sin of 2 pi u[dims - 2][k].
struct PointView {
  size_t n = 0;
  const double *u[kMaxPointDimensions] = {};
  const double *cosPhi = nullptr, *sinPhi = nullptr;
  // The view starting `k` points later, n - k of them.
  PointView Skip(size_t k) const {
    PointView v = *this;
    v.n -= k;
    for (const double *&p : v.u)
      if (p) p += k;
    v.cosPhi += k;
    v.sinPhi += k;
    return v;
  }
};

// Storage for one block computed outside the cache.
struct PointBlockStorage {
  double u[kMaxPointDimensions][kPointBlockSize];
  double cosPhi[kPointBlockSize], sinPhi[kPointBlockSize];
};

// Block b (points b kPointBlockSize to (b + 1) kPointBlockSize - 1) of
// replicate r, 2 <= dims <= kMaxPointDimensions. Sobol blocks come from the
// cache (computed on first use and kept for the process; past 256 MB of
// cache they are computed into `scratch`), random ones are computed into
// `scratch`. Thread-safe.
PointView PointBlock(PointSet set, uint64_t seed, int dims, int replicate, uint64_t block,
                     PointBlockStorage *scratch);

}  // namespace lutbake
