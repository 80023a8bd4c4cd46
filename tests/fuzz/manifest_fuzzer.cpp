// libFuzzer target for the manifest reader (scripts/fuzz.sh runs it). Any
// input must either be read or refused with InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lutbake/plans/manifest.h"
#include "lutbake/plans/plan.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  try {
    const lutbake::Manifest m = lutbake::ParseManifest(text, "fuzz.json");
    lutbake::PlanOptions options;
    options.defaultIbl = m.ibl;
    options.defaultCompensation = m.compensation;
    lutbake::MakePlan(m.materials, options);
  } catch (const lutbake::InputError &) {
  }
  return 0;
}
