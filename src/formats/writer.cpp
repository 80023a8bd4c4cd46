#include "lutbake/formats/writer.h"

#include <cmath>

#include "lutbake/formats/source_formats.h"

namespace lutbake {

void RequireUnitRange(const Table &table, const std::string &path, const char *format) {
  for (size_t i = 0; i < table.values.size(); ++i) {
    const double v = table.values[i];
    if (v >= 0.0 && v <= 1.0) continue;
    const size_t texel = i / table.channels;
    const size_t slice = static_cast<size_t>(table.width()) * table.height();
    throw IoError("cannot write " + path + ": table " + table.Name() + " holds " + FormatDouble(v) +
                  " at texel (" + std::to_string(texel % table.width()) + ", " +
                  std::to_string((texel % slice) / table.width()) +
                  (table.is3D() ? ", " + std::to_string(texel / slice) : std::string()) +
                  ") channel " + std::to_string(i % table.channels) + "; " + format +
                  " stores values in [0, 1] only: write this table as exr, bin, ktx2 or dds");
  }
}

}  // namespace lutbake
