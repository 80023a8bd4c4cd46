#include "lutbake/formats/writer.h"

#include <cmath>

#include "lutbake/formats/source_formats.h"

namespace lutbake {

std::unique_ptr<TableWriter> MakeWriter(const std::string &formatName) {
  if (formatName == "exr") return MakeExrWriter();
  if (formatName == "bin") return MakeBinaryWriter();
  if (formatName == "header") return MakeCppHeaderWriter();
  if (formatName == "png8") return MakePngWriter(8);
  if (formatName == "png16") return MakePngWriter(16);
  if (formatName == "ktx2") return MakeKtx2Writer(ValueType::kFloat32);
  if (formatName == "ktx2-half") return MakeKtx2Writer(ValueType::kHalf);
  if (formatName == "dds") return MakeDdsWriter(ValueType::kFloat32);
  if (formatName == "dds-half") return MakeDdsWriter(ValueType::kHalf);
  if (formatName == "c-array") return MakeCArrayWriter();
  if (formatName == "threejs-dfg") return MakeThreejsDfgWriter();
  // Source embeddings (source_formats.h).
  if (formatName == "inc") return MakeIncWriter(ValueType::kFloat32);
  if (formatName == "inc-half") return MakeIncWriter(ValueType::kHalf);
  for (const bool ts : {false, true}) {
    const std::string stem = ts ? "ts" : "js";
    if (formatName == stem) return MakeJsWriter(ValueType::kFloat32, ts);
    if (formatName == stem + "-half") return MakeJsWriter(ValueType::kHalf, ts);
  }
  ShaderLanguage language;
  const size_t dash = formatName.rfind("-array");
  if (dash != std::string::npos && dash + 6 == formatName.size() &&
      ParseShaderLanguage(formatName.substr(0, dash), &language))
    return MakeShaderArrayWriter(language);
  return nullptr;
}

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
