// Highway's run-time entry points for the lutbake executable alone, so that
// it does not load libhwy.so, whose static initialiser spends ~3 ms in every
// process measuring a timer (src/integrators/simd_targets.h). The kernels'
// HWY_DYNAMIC_DISPATCH asks only these two questions (which targets run
// here, and the chosen one); the library and the tests keep libhwy. The
// executable links with --as-needed, so libhwy is not loaded once nothing
// else needs it.
#include <hwy/targets.h>

#include <atomic>

#include "integrators/simd_targets.h"

namespace hwy {

namespace {

std::atomic<int64_t> targetsForTest{0};

}  // namespace

int64_t SupportedTargets() {
  const int64_t forTest = targetsForTest.load();
  if (forTest != 0) return forTest;
  static const int64_t detected = lutbake::DetectSimdTargets();
  return detected;
}

void SetSupportedTargetsForTest(int64_t targets) {
  targetsForTest.store(targets);
  GetChosenTarget().DeInit();
}

ChosenTarget &GetChosenTarget() {
  static ChosenTarget chosen;
  return chosen;
}

}  // namespace hwy
