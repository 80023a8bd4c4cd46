// Highway's run-time entry points for the lutbake executable alone, so that
// it does not load libhwy.so, whose static initialiser spends ~3 ms in every
// process measuring a timer (src/integrators/simd_targets.h). The kernels'
// HWY_DYNAMIC_DISPATCH asks only these two questions (which targets run
// here, and the chosen one); the library and the tests keep libhwy. The
// executable links with --as-needed, so libhwy is not loaded once nothing
// else needs it (the ctest Executable.LoadsNoLibhwy checks that it is not).
#include <hwy/targets.h>

#include "integrators/simd_targets.h"

namespace hwy {

int64_t SupportedTargets() {
  static const int64_t detected = lutbake::DetectSimdTargets();
  return detected;
}

ChosenTarget &GetChosenTarget() {
  static ChosenTarget chosen;
  return chosen;
}

}  // namespace hwy
