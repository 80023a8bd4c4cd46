// Which of Highway's x86 targets this processor and its operating system
// can run, read from CPUID and XCR0 without Highway's run-time library.
//
// Why: libhwy.so's static initialiser measures its timer's resolution in
// every process that loads it, about 3 ms, 40% of `lutbake --version` and
// 2.5% of the default bake. The lutbake executable therefore answers
// Highway's two run-time questions itself (src/cli/highway_runtime.cpp)
// and does not load libhwy; the tests keep libhwy, and compare this
// answer with its own (simd_targets_test.cpp).
//
// A target is reported only where every feature its code is compiled with
// is present (hwy/ops/set_macros-inl.h, HWY_TARGET_STR_*) and the operating
// system saves the registers it uses (XCR0):
//   SSSE3: SSE2, SSE3, SSSE3;
//   SSE4:  SSSE3's, SSE4.1, SSE4.2, PCLMULQDQ, AES;
//   AVX2:  SSE4's, AVX, AVX2, BMI1, BMI2, FMA, F16C, and XCR0 SSE + AVX state;
//   AVX3:  AVX2's, AVX512F, AVX512VL, AVX512DQ, AVX512BW, and XCR0 opmask +
//          ZMM state.
// HWY_SCALAR and HWY_EMU128 are always reported.
#pragma once

#include <cstdint>

namespace lutbake {

// The CPUID words the decision reads: leaf 1 ECX and EDX, leaf 7 (subleaf
// 0) EBX, and XCR0 (0 where OSXSAVE is clear).
struct X86Features {
  uint32_t leaf1Ecx = 0, leaf1Edx = 0, leaf7Ebx = 0;
  uint64_t xcr0 = 0;
};

// Highway's target bits (HWY_AVX3, HWY_AVX2, ...) that `features` allow.
int64_t SimdTargetsOf(const X86Features &features);

// This processor's features (all zero on a processor that is not x86).
X86Features ReadX86Features();

// SimdTargetsOf(ReadX86Features()) on x86; HWY_STATIC_TARGET elsewhere.
int64_t DetectSimdTargets();

}  // namespace lutbake
