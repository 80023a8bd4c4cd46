// Sobol points with hash-based Owen scrambling.
//
// Dimension d of point i is the XOR of the direction numbers V_d[b] over the
// set bits b of i (Joe and Kuo's primitive polynomials and initial numbers
// for the first dimensions). Any 2^m consecutive points from index 0 form a
// (0, m, 2)-net in the first two dimensions: every elementary interval of
// area 2^-m holds exactly one point.
//
// Scrambling: a nested uniform (Owen) scramble is a random permutation of
// each binary digit that depends on all higher digits. We use the
// hash-based approximation of Laine and Karras as improved by Burley (2020):
// reverse the bits, apply an xor-multiply permutation that only propagates
// from low to high bits, reverse again. It keeps the net property, makes each
// point uniform on [0,1), and makes the estimator unbiased, so independent
// scrambles give an honest variance estimate.
#pragma once

#include <cstdint>

namespace lutbake {

inline constexpr int kSobolDimensions = 5;

// Raw 32-bit Sobol integer of point `index` in dimension `dim` (< kSobolDimensions).
uint32_t SobolBits(uint32_t index, int dim);

// Owen-style scramble of a 32-bit fixed-point value with a 32-bit seed.
uint32_t OwenScramble(uint32_t bits, uint32_t seed);

// Scrambled point as a double in (0, 1): the centre of its 2^-32 interval,
// so that no sample sits exactly on 0 or 1.
inline double BitsToUnit(uint32_t bits) { return (static_cast<double>(bits) + 0.5) * 0x1p-32; }

inline double ScrambledSobol(uint32_t index, int dim, uint32_t seed) {
  return BitsToUnit(OwenScramble(SobolBits(index, dim), seed));
}

}  // namespace lutbake
