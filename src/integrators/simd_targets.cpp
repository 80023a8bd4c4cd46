#include "integrators/simd_targets.h"

#include <hwy/targets.h>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#define LUTBAKE_X86 1
#endif

namespace lutbake {

namespace {

constexpr bool Has(uint64_t word, int bit) { return (word >> bit) & 1u; }

}  // namespace

int64_t SimdTargetsOf(const X86Features &f) {
  int64_t targets = HWY_SCALAR | HWY_EMU128;
  const bool ssse3 = Has(f.leaf1Edx, 26) && Has(f.leaf1Ecx, 0) && Has(f.leaf1Ecx, 9);
  if (!ssse3) return targets;
  targets |= HWY_SSSE3;
  const bool sse4 =
      Has(f.leaf1Ecx, 19) && Has(f.leaf1Ecx, 20) && Has(f.leaf1Ecx, 1) && Has(f.leaf1Ecx, 25);
  if (!sse4) return targets;
  targets |= HWY_SSE4;
  // OSXSAVE (leaf 1 ECX 27), and XCR0 bits 1 and 2: the OS saves XMM and YMM.
  const bool ymmState = Has(f.leaf1Ecx, 27) && (f.xcr0 & 0x6) == 0x6;
  const bool avx2 = ymmState && Has(f.leaf1Ecx, 28) && Has(f.leaf7Ebx, 5) &&  // AVX, AVX2
                    Has(f.leaf7Ebx, 3) && Has(f.leaf7Ebx, 8) &&               // BMI1, BMI2
                    Has(f.leaf1Ecx, 12) && Has(f.leaf1Ecx, 29);               // FMA, F16C
  if (!avx2) return targets;
  targets |= HWY_AVX2;
  // XCR0 bits 5 to 7: opmask, the upper halves of ZMM0-15, ZMM16-31.
  const bool zmmState = (f.xcr0 & 0xe6) == 0xe6;
  const bool avx3 = zmmState && Has(f.leaf7Ebx, 16) && Has(f.leaf7Ebx, 17) &&  // F, DQ
                    Has(f.leaf7Ebx, 30) && Has(f.leaf7Ebx, 31);                // BW, VL
  if (avx3) targets |= HWY_AVX3;
  return targets;
}

X86Features ReadX86Features() {
  X86Features f;
#ifdef LUTBAKE_X86
  unsigned a = 0, b = 0, c = 0, d = 0;
  const unsigned maxLeaf = __get_cpuid_max(0, nullptr);
  if (maxLeaf >= 1 && __get_cpuid(1, &a, &b, &c, &d)) {
    f.leaf1Ecx = c;
    f.leaf1Edx = d;
  }
  if (maxLeaf >= 7) {
    __cpuid_count(7, 0, a, b, c, d);
    f.leaf7Ebx = b;
  }
  if (Has(f.leaf1Ecx, 27)) {  // OSXSAVE: XGETBV may be executed
    uint32_t low = 0, high = 0;
    __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
    f.xcr0 = (static_cast<uint64_t>(high) << 32) | low;
  }
#endif
  return f;
}

int64_t DetectSimdTargets() {
#ifdef LUTBAKE_X86
  return SimdTargetsOf(ReadX86Features());
#else
  return HWY_STATIC_TARGET;
#endif
}

}  // namespace lutbake
