// libFuzzer target for the KTX2 reader (float32 and half) (scripts/fuzz.sh runs it):
// every input is read or refused with IoError (table_fuzzer.h).
#include <cstddef>
#include <cstdint>

#include "lutbake/formats/table_reader.h"
#include "table_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  return lutbake::fuzz::FuzzTableReader(lutbake::ReadKtx2Table, data, size);
}
