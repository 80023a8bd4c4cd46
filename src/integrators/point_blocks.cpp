#include "lutbake/integrators/point_blocks.h"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "lutbake/core/hash.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/sobol.h"

namespace lutbake {

namespace {

// Past this much cached memory, Sobol blocks are computed on every use.
constexpr size_t kCacheBytes = size_t{256} << 20;

void Compute(PointSet set, uint64_t seed, int dims, int replicate, uint64_t block,
             PointBlockStorage *out) {
  const uint64_t first = block * kPointBlockSize;
  for (int d = 0; d < dims; ++d) {
    const uint64_t dimensionSeed =
        HashValues({seed, static_cast<uint64_t>(replicate), static_cast<uint64_t>(d)});
    double *u = out->u[d];
    if (set == PointSet::kScrambledSobol) {
      // Sobol bits of consecutive indices: from i - 1 to i the bits of
      // i ^ (i - 1) change, so the direction numbers of those bits toggle.
      uint32_t bits = SobolBits(static_cast<uint32_t>(first), d);
      for (size_t k = 0; k < kPointBlockSize; ++k) {
        const uint32_t i = static_cast<uint32_t>(first + k);
        if (k > 0) bits ^= SobolBits(i ^ (i - 1), d);
        u[k] = BitsToUnit(OwenScramble(bits, static_cast<uint32_t>(dimensionSeed)));
      }
    } else {
      // Counter-based: any prefix of the stream is reproducible without
      // replaying it.
      for (size_t k = 0; k < kPointBlockSize; ++k)
        u[k] = (static_cast<double>(MixBits(dimensionSeed + MixBits(first + k)) >> 11) + 0.5) *
               0x1p-53;
    }
  }
  const double *azimuth = out->u[dims - 2];
  for (size_t k = 0; k < kPointBlockSize; ++k) {
    // As the scalar samplers compute it (ggx.cpp): phi = 2 pi u.
    const double phi = 2.0 * kPi * azimuth[k];
    out->cosPhi[k] = std::cos(phi);
    out->sinPhi[k] = std::sin(phi);
  }
}

PointView View(const PointBlockStorage &b, int dims) {
  PointView v;
  v.n = kPointBlockSize;
  for (int d = 0; d < dims; ++d) v.u[d] = b.u[d];
  v.cosPhi = b.cosPhi;
  v.sinPhi = b.sinPhi;
  return v;
}

struct Cache {
  std::mutex mutex;
  std::map<std::tuple<uint64_t, int, int, uint64_t>, std::unique_ptr<PointBlockStorage>> blocks;
  size_t bytes = 0;
};

Cache &TheCache() {
  static Cache cache;
  return cache;
}

}  // namespace

PointView PointBlock(PointSet set, uint64_t seed, int dims, int replicate, uint64_t block,
                     PointBlockStorage *scratch) {
  if (set == PointSet::kIndependentRandom) {
    Compute(set, seed, dims, replicate, block, scratch);
    return View(*scratch, dims);
  }
  Cache &cache = TheCache();
  const auto key = std::make_tuple(seed, dims, replicate, block);
  {
    const std::lock_guard<std::mutex> lock(cache.mutex);
    const auto it = cache.blocks.find(key);
    if (it != cache.blocks.end()) return View(*it->second, dims);
  }
  auto fresh = std::make_unique<PointBlockStorage>();
  Compute(set, seed, dims, replicate, block, fresh.get());
  const std::lock_guard<std::mutex> lock(cache.mutex);
  const auto it = cache.blocks.find(key);  // another thread may have been first
  if (it != cache.blocks.end()) return View(*it->second, dims);
  if (cache.bytes + sizeof(PointBlockStorage) > kCacheBytes) {
    *scratch = *fresh;
    return View(*scratch, dims);
  }
  cache.bytes += sizeof(PointBlockStorage);
  const PointBlockStorage &stored = *cache.blocks.emplace(key, std::move(fresh)).first->second;
  return View(stored, dims);
}

}  // namespace lutbake
