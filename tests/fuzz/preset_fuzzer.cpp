// libFuzzer target for the reader of a preset directory's preset.json,
// ReadPresetListing (scripts/fuzz.sh runs it): every input is read or
// refused with IoError; what is read names a preset and holds an errorMax
// in [0, 1] for every file it lists. The files it lists are read by the
// table readers, fuzzed by their own targets.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input.h"
#include "lutbake/formats/writer.h"
#include "lutbake/api/presets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static lutbake::fuzz::InputFile file;
  const std::string &path = file.Hold(data, size);
  try {
    const lutbake::PresetListing listing = lutbake::ReadPresetListing(path);
    if (!listing.preset) std::abort();
    for (const auto &[name, errorMax] : listing.errorMaxByFile)
      if (!(errorMax >= 0.0 && errorMax <= 1.0)) std::abort();
  } catch (const lutbake::IoError &) {
  }
  return 0;
}
