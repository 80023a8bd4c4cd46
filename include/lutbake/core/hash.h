// Integer hashing for seeds. A seed of a texel's point set is a pure function
// of (table, texel, user seed, replicate, dimension), never of the thread that
// computes it: that is what makes output identical for any thread count.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace lutbake {

// The splitmix64 finaliser: a bijection on 64-bit integers with full avalanche.
constexpr uint64_t MixBits(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

// Order-sensitive combination of several values into one 64-bit hash.
inline uint64_t HashValues(std::initializer_list<uint64_t> values) {
  uint64_t h = 0x243f6a8885a308d3ULL;  // digits of pi, any odd constant works
  for (uint64_t v : values) h = MixBits(h ^ MixBits(v + 0x9e3779b97f4a7c15ULL));
  return h;
}

// A small counter-based generator for independent random points (tests and
// the plain Monte Carlo estimators): value i of stream s is MixBits of both.
class RandomStream {
 public:
  explicit RandomStream(uint64_t seed) : state_(MixBits(seed)) {}
  uint64_t NextBits() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return MixBits(state_);
  }
  // Uniform in [0, 1) with 53 random bits.
  double NextDouble() { return static_cast<double>(NextBits() >> 11) * 0x1p-53; }

 private:
  uint64_t state_;
};

}  // namespace lutbake
