// libFuzzer target for the .bin reader (binary_format.h) (scripts/fuzz.sh runs it):
// every input is read or refused with IoError (table_fuzzer.h).
#include <cstddef>
#include <cstdint>

#include "lutbake/formats/binary_format.h"
#include "table_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  return lutbake::fuzz::FuzzTableReader(lutbake::ReadBinaryTable, data, size);
}
