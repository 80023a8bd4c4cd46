#include "lutbake/integrators/sobol.h"

#include <array>

namespace lutbake {

namespace {

using DirectionNumbers = std::array<std::array<uint32_t, 32>, kSobolDimensions>;

// Builds V_d[b] = m_b 2^(31 - b) from the degree s, the coefficients a of the
// primitive polynomial and the first s odd integers m (Joe and Kuo 2008,
// "new-joe-kuo-6.21201", dimensions 2 to 5); dimension 0 is van der Corput.
DirectionNumbers MakeDirectionNumbers() {
  struct Polynomial {
    int degree;
    uint32_t coefficients;
    uint32_t m[3];
  };
  constexpr Polynomial kPolynomials[kSobolDimensions - 1] = {
      {1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}, {3, 2, {1, 1, 1}}};
  DirectionNumbers v{};
  for (int b = 0; b < 32; ++b) v[0][b] = 1u << (31 - b);
  for (int d = 1; d < kSobolDimensions; ++d) {
    const Polynomial &p = kPolynomials[d - 1];
    const int s = p.degree;
    std::array<uint32_t, 32> m{};
    for (int b = 0; b < s; ++b) m[b] = p.m[b];
    // m_b = 2 a_1 m_{b-1} ^ 4 a_2 m_{b-2} ^ ... ^ 2^s m_{b-s} ^ m_{b-s}
    for (int b = s; b < 32; ++b) {
      uint32_t value = m[b - s] ^ (m[b - s] << s);
      for (int k = 1; k < s; ++k) {
        const uint32_t a_k = (p.coefficients >> (s - 1 - k)) & 1u;
        if (a_k) value ^= m[b - k] << k;
      }
      m[b] = value;
    }
    for (int b = 0; b < 32; ++b) v[d][b] = m[b] << (31 - b);
  }
  return v;
}

const DirectionNumbers &Directions() {
  static const DirectionNumbers v = MakeDirectionNumbers();
  return v;
}

uint32_t ReverseBits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

}  // namespace

uint32_t SobolBits(uint32_t index, int dim) {
  const auto &v = Directions()[dim];
  uint32_t result = 0;
  for (int b = 0; index != 0; ++b, index >>= 1)
    if (index & 1u) result ^= v[b];
  return result;
}

uint32_t OwenScramble(uint32_t bits, uint32_t seed) {
  // In bit-reversed order, each step below changes a bit only as a function
  // of itself and lower (originally: higher) bits, which is the structure of
  // a nested scramble; the constants are Burley's.
  uint32_t x = ReverseBits(bits);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return ReverseBits(x);
}

}  // namespace lutbake
