#include "source_text.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "lutbake/core/error.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

const char *ToString(ShaderLanguage language) {
  switch (language) {
    case ShaderLanguage::kGlsl: return "glsl";
    case ShaderLanguage::kHlsl: return "hlsl";
    case ShaderLanguage::kWgsl: return "wgsl";
    case ShaderLanguage::kMsl: return "msl";
  }
  return "";
}

bool ParseShaderLanguage(const std::string &name, ShaderLanguage *language) {
  for (ShaderLanguage l :
       {ShaderLanguage::kGlsl, ShaderLanguage::kHlsl, ShaderLanguage::kWgsl, ShaderLanguage::kMsl})
    if (name == ToString(l)) {
      *language = l;
      return true;
    }
  return false;
}

const char *ShaderExtension(ShaderLanguage language) {
  switch (language) {
    case ShaderLanguage::kGlsl: return ".glsl";
    case ShaderLanguage::kHlsl: return ".hlsl";
    case ShaderLanguage::kWgsl: return ".wgsl";
    case ShaderLanguage::kMsl: return ".metal";
  }
  return "";
}

namespace source_text {

Metadata EmbeddingMetadata(const Table &table, ValueType storage) {
  Metadata m = MetadataForStorage(table, storage);
  double moved = 0.0;
  for (double v : table.values)
    moved =
        std::max(moved, std::abs(StoredValue(v, storage) - StoredValue(v, ValueType::kFloat32)));
  m.emplace_back("width", std::to_string(table.width()));
  m.emplace_back("height", std::to_string(table.height()));
  m.emplace_back("depth", std::to_string(table.depth()));
  m.emplace_back("channels", std::to_string(table.channels));
  std::string meanings;
  if (table.definition)
    for (const std::string &c : table.definition->ChannelMeanings())
      meanings += (meanings.empty() ? "" : ", ") + c;
  m.emplace_back("channelMeanings", meanings);
  m.emplace_back("layout",
                 "values[((z * height + y) * width + x) * channels + c]: x (axisX) fastest, then "
                 "y (axisY), then z (axisZ) slices, channels interleaved");
  m.emplace_back("storage", storage == ValueType::kHalf
                                ? "IEEE 754 binary16 bit patterns, rounded to nearest even"
                                : "float32, exactly the EXR and .bin values");
  m.emplace_back("storageErrorMax", FormatDouble(moved));
  return m;
}

namespace {

std::string OneLine(const std::string &text) {
  std::string s;
  for (const char c : text) s += c == '\n' ? "\\n" : c == '\r' ? "\\r" : std::string(1, c);
  return s;
}

}  // namespace

void WriteMetadataComment(std::ostream &out, const std::string &title, const Metadata &metadata) {
  out << "// " << title << "\n";
  for (const auto &[key, value] : metadata) out << "//   " << key << ": " << OneLine(value) << "\n";
  out << "//\n";
}

void WriteAxisComment(std::ostream &out, const Table &table) {
  const auto line = [&](const char *which, const Axis &axis) {
    out << "// Axis " << which << " " << axis.name;
    if (axis.listed()) {
      out << ": " << axis.count << " texels at exactly";
      for (size_t i = 0; i < axis.nodes.size(); ++i)
        out << (i ? ", " : " ") << FormatDouble(axis.nodes[i]);
      out << " (linear in " << axis.name << " between them).\n";
    } else {
      out << " in [" << FormatDouble(axis.min) << ", " << FormatDouble(axis.max) << "], "
          << axis.count << " texels; texel i holds the value at " << axis.name
          << " = min + (max - min) (i + 0.5) / " << axis.count << " (texel centres).\n";
    }
  };
  line("x (width): ", table.x);
  if (table.is2D()) line("y (height):", table.y);
  if (table.is3D()) line("z (depth): ", table.z);
}

std::string HalfLiteral(double value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04x",
                static_cast<unsigned>(Imath::half(static_cast<float>(value)).bits()));
  return buffer;
}

void WriteValues(std::ostream &out, const Table &table, ValueType storage, const char *suffix,
                 bool trailingComma) {
  const bool half = storage == ValueType::kHalf;
  const size_t perLine = half ? 10 : 6;
  out << kValuesBegin << "\n";
  for (size_t i = 0; i < table.values.size(); ++i) {
    out << (i % perLine == 0 ? "    " : " ")
        << (half ? HalfLiteral(table.values[i]) : FloatLiteral(table.values[i], suffix));
    if (i + 1 < table.values.size() || trailingComma) out << ",";
    if (i % perLine == perLine - 1 || i + 1 == table.values.size()) out << "\n";
  }
  out << kValuesEnd << "\n";
}

std::string TexelCoordinate(const Dialect &d, const Axis &axis, const std::string &v) {
  const int n = axis.count;
  if (n <= 1) return d.Lit(0.0);
  if (axis.listed()) {
    std::string s;
    for (int i = 0; i + 1 < n; ++i) {
      const double lo = axis.nodes[static_cast<size_t>(i)],
                   hi = axis.nodes[static_cast<size_t>(i) + 1];
      s += (i ? " +\n      " : "") + std::string("clamp((") + v + " - " + d.Lit(lo) + ") * " +
           d.Lit(1.0 / (hi - lo)) + ", " + d.Lit(0.0) + ", " + d.Lit(1.0) + ")";
    }
    return s;
  }
  return "clamp((" + v + " - " + d.Lit(axis.min) + ") * " + d.Lit(n / (axis.max - axis.min)) +
         " - " + d.Lit(0.5) + ", " + d.Lit(0.0) + ", " + d.Lit(n - 1.0) + ")";
}

std::vector<std::string> AxisParams(const Table &table) {
  std::vector<std::string> params = {table.x.name};
  if (table.is2D()) params.push_back(table.y.name);
  if (table.is3D()) params.push_back(table.z.name);
  return params;
}

std::string Swizzle(int channels) {
  switch (channels) {
    case 1: return ".x";
    case 2: return ".xy";
    case 3: return ".xyz";
    default: return "";
  }
}

std::string ReadText(const std::string &path, size_t maxBytes) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw IoError("cannot open " + path);
  std::stringstream buffer;
  buffer << file.rdbuf();
  std::string text = buffer.str();
  if (text.size() > maxBytes)
    throw IoError(path + ": over " +
                  (maxBytes >= (size_t{1} << 30) ? std::to_string(maxBytes >> 30) + " GiB"
                                                 : std::to_string(maxBytes >> 20) + " MiB"));
  return text;
}

Metadata HeaderMetadata(const std::string &text) {
  Metadata metadata;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("//", 0) != 0 || line == "//") break;
    if (line.rfind("//   ", 0) != 0) continue;
    const size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;
    metadata.emplace_back(line.substr(5, colon - 5), line.substr(colon + 2));
  }
  return metadata;
}

}  // namespace source_text
}  // namespace lutbake
