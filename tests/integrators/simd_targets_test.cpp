#include "integrators/simd_targets.h"

#include <gtest/gtest.h>
#include <hwy/highway.h>

namespace lutbake {
namespace {

// The words of a processor with SSE2 to SSE4.2, PCLMULQDQ and AES, OSXSAVE,
// AVX, FMA and F16C (leaf 1), and AVX2, BMI1 and BMI2 (leaf 7).
X86Features Avx2Machine() {
  X86Features f;
  f.leaf1Edx = 1u << 26;
  f.leaf1Ecx = (1u << 0) | (1u << 1) | (1u << 9) | (1u << 12) | (1u << 19) | (1u << 20) |
               (1u << 25) | (1u << 27) | (1u << 28) | (1u << 29);
  f.leaf7Ebx = (1u << 3) | (1u << 5) | (1u << 8);
  f.xcr0 = 0x7;
  return f;
}

X86Features Avx512Machine() {
  X86Features f = Avx2Machine();
  f.leaf7Ebx |= (1u << 16) | (1u << 17) | (1u << 30) | (1u << 31);
  f.xcr0 = 0xe7;
  return f;
}

TEST(SimdTargets, AgreesWithHighwaysOwnDetectionHere) {
  // The test binary loads libhwy: its answer for this processor, on the
  // targets the kernels are compiled for.
  EXPECT_EQ(DetectSimdTargets() & HWY_TARGETS, hwy::SupportedTargets() & HWY_TARGETS);
}

TEST(SimdTargets, EachTargetNeedsAllItsFeatures) {
  const int64_t base = HWY_SCALAR | HWY_EMU128;
  EXPECT_EQ(SimdTargetsOf(X86Features{}), base);
  EXPECT_EQ(SimdTargetsOf(Avx2Machine()), base | HWY_SSSE3 | HWY_SSE4 | HWY_AVX2);
  EXPECT_EQ(SimdTargetsOf(Avx512Machine()), base | HWY_SSSE3 | HWY_SSE4 | HWY_AVX2 | HWY_AVX3);
  // AVX-512 in the processor but not saved by the operating system.
  X86Features noZmm = Avx512Machine();
  noZmm.xcr0 = 0x7;
  EXPECT_EQ(SimdTargetsOf(noZmm), base | HWY_SSSE3 | HWY_SSE4 | HWY_AVX2);
  // Without OSXSAVE neither AVX2 nor AVX-512, whatever XCR0 was read as.
  X86Features noXsave = Avx512Machine();
  noXsave.leaf1Ecx &= ~(1u << 27);
  EXPECT_EQ(SimdTargetsOf(noXsave), base | HWY_SSSE3 | HWY_SSE4);
  // One missing feature of a group drops that target and those above it.
  for (const int bit : {3, 5, 8}) {  // BMI1, AVX2, BMI2
    X86Features f = Avx512Machine();
    f.leaf7Ebx &= ~(1u << bit);
    EXPECT_EQ(SimdTargetsOf(f), base | HWY_SSSE3 | HWY_SSE4) << "leaf 7 EBX bit " << bit;
  }
  for (const int bit : {12, 28, 29}) {  // FMA, AVX, F16C
    X86Features f = Avx512Machine();
    f.leaf1Ecx &= ~(1u << bit);
    EXPECT_EQ(SimdTargetsOf(f), base | HWY_SSSE3 | HWY_SSE4) << "leaf 1 ECX bit " << bit;
  }
  for (const int bit : {16, 17, 30, 31}) {  // AVX512F, DQ, BW, VL
    X86Features f = Avx512Machine();
    f.leaf7Ebx &= ~(1u << bit);
    EXPECT_EQ(SimdTargetsOf(f), base | HWY_SSSE3 | HWY_SSE4 | HWY_AVX2) << "bit " << bit;
  }
  for (const int bit : {1, 19, 20, 25}) {  // PCLMULQDQ, SSE4.1, SSE4.2, AES
    X86Features f = Avx512Machine();
    f.leaf1Ecx &= ~(1u << bit);
    EXPECT_EQ(SimdTargetsOf(f), base | HWY_SSSE3) << "leaf 1 ECX bit " << bit;
  }
  X86Features noSsse3 = Avx512Machine();
  noSsse3.leaf1Ecx &= ~(1u << 9);
  EXPECT_EQ(SimdTargetsOf(noSsse3), base);
}

}  // namespace
}  // namespace lutbake
