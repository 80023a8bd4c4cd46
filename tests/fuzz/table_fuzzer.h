// The body of the table readers' libFuzzer targets (bin_fuzzer.cpp,
// exr_fuzzer.cpp, png_fuzzer.cpp, ktx2_fuzzer.cpp, dds_fuzzer.cpp): the input
// is written to an in-memory file and read; it must be read or refused with
// IoError. Anything else (another exception, a crash, a sanitizer report,
// an allocation over libFuzzer's -malloc_limit_mb) is a bug. What is read
// must hold together, and is looked up as `lutbake check` and `eval` do.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_input.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/table.h"

namespace lutbake::fuzz {

// Aborts (a finding) unless `table` has the shape its axes say.
inline void RequireConsistent(const Table &table) {
  const bool ok = (table.channels == 1 || table.channels == 2) &&
                  table.channelNames.size() == static_cast<size_t>(table.channels) &&
                  table.x.count >= 1 && table.y.count >= 1 && table.z.count >= 1 &&
                  table.values.size() == table.texelCount() * table.channels &&
                  (table.errors.empty() || table.errors.size() == table.values.size());
  if (!ok) std::abort();
}

// Looks up every channel at the axes' ends and middle (clamped lookups).
inline void LookUpCorners(const Table &table) {
  const auto probes = [](const Axis &axis) {
    return std::array<double, 3>{axis.min, 0.5 * (axis.min + axis.max), axis.max};
  };
  for (int c = 0; c < table.channels; ++c)
    for (double x : probes(table.x))
      for (double y : probes(table.y)) {
        if (table.is3D())
          for (double z : probes(table.z)) Lookup(table, table.values, x, y, z, c);
        else
          Lookup(table, x, y, c);
      }
}

template <typename Read>
int FuzzTableReader(Read read, const uint8_t *data, size_t size) {
  static InputFile file;
  const std::string &path = file.Hold(data, size);
  try {
    const Table table = read(path);
    RequireConsistent(table);
    LookUpCorners(table);
  } catch (const IoError &) {
  }
  return 0;
}

}  // namespace lutbake::fuzz
