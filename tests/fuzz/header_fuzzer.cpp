// libFuzzer target for the generated C++ header reader, ReadHeaderValues
// (scripts/fuzz.sh runs it): every input is read or refused with IoError,
// and what is read has as many values as its sizes say.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static lutbake::fuzz::InputFile file;
  const std::string &path = file.Hold(data, size);
  try {
    const lutbake::HeaderValues header = lutbake::ReadHeaderValues(path);
    const size_t expected = static_cast<size_t>(header.width) * header.height * header.depth *
                            static_cast<size_t>(header.channels);
    if (header.values.size() != expected) std::abort();
  } catch (const lutbake::IoError &) {
  }
  return 0;
}
