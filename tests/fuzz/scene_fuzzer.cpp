// libFuzzer target for the glTF / GLB material reader (scripts/fuzz.sh runs
// it). Any input must either be read or refused with InputError; anything
// else (another exception, a crash, a sanitizer report) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lutbake/plans/plan.h"
#include "lutbake/plans/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char *>(data), size);
  try {
    // Both containers: the same bytes as a .gltf and as a .glb.
    for (const char *name : {"fuzz.gltf", "fuzz.glb"}) {
      const auto materials = lutbake::ParseSceneMaterials(bytes, name);
      // What is read must plan without surprises.
      lutbake::MakePlan(materials, {});
    }
  } catch (const lutbake::InputError &) {
  }
  return 0;
}
