// libFuzzer target for the source-embedding reader, ReadSourceTable
// (scripts/fuzz.sh runs it): the .inc, .js/.ts, GLSL/HLSL/WGSL/MSL arrays,
// c-array and three.js module formats all read through it. Every input is
// read or refused with IoError (table_fuzzer.h); what is read has the shape
// its metadata says and is looked up at its corners.
#include <cstddef>
#include <cstdint>

#include "lutbake/formats/table_reader.h"
#include "table_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  return lutbake::fuzz::FuzzTableReader(lutbake::ReadSourceTable, data, size);
}
