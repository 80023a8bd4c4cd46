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

std::string FloatLiteral(double value, const char *suffix) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(value)));
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + suffix;
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

std::string Dialect::Float(int n) const {
  const std::string size = std::to_string(n);
  switch (language_) {
    case ShaderLanguage::kGlsl: return n == 1 ? "float" : "vec" + size;
    case ShaderLanguage::kWgsl: return n == 1 ? "f32" : "vec" + size + "<f32>";
    case ShaderLanguage::kHlsl:
    case ShaderLanguage::kMsl: return n == 1 ? "float" : "float" + size;
  }
  return "";
}

std::string Dialect::Int() const { return language_ == ShaderLanguage::kWgsl ? "i32" : "int"; }

const char *Dialect::LiteralSuffix() const {
  // GLSL ES 3.00 and WGSL read "0.5" as float (WGSL: an abstract float that
  // converts to f32); Metal and HLSL take the f suffix as float32 too.
  return language_ == ShaderLanguage::kMsl || language_ == ShaderLanguage::kHlsl ? "f" : "";
}

std::string Dialect::Lit(double value) const { return FloatLiteral(value, LiteralSuffix()); }

std::string Dialect::Vec(const std::vector<std::string> &args) const {
  if (args.size() == 1) return args[0];
  std::string s = Float(static_cast<int>(args.size())) + "(";
  for (size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + args[i];
  return s + ")";
}

std::string Dialect::Let(const std::string &type, const std::string &name,
                         const std::string &expr) const {
  if (language_ == ShaderLanguage::kWgsl)
    return "  let " + name + ": " + type + " = " + expr + ";\n";
  return "  " + type + " " + name + " = " + expr + ";\n";
}

std::string Dialect::Function(const std::string &result, const std::string &name,
                              const std::vector<std::pair<std::string, std::string>> &params,
                              const std::string &body) const {
  std::string s;
  if (language_ == ShaderLanguage::kWgsl) {
    s = "fn " + name + "(";
    for (size_t i = 0; i < params.size(); ++i)
      s += (i ? ", " : "") + params[i].second + ": " + params[i].first;
    s += ") -> " + result + " {\n";
  } else {
    s = (language_ == ShaderLanguage::kMsl ? "inline " : "") + result + " " + name + "(";
    for (size_t i = 0; i < params.size(); ++i)
      s += (i ? ", " : "") + params[i].first + " " + params[i].second;
    s += ") {\n";
  }
  return s + body + "}\n\n";
}

std::string Dialect::ToInt(const std::string &expr) const { return Int() + "(" + expr + ")"; }
std::string Dialect::ToFloat(const std::string &expr) const { return Float() + "(" + expr + ")"; }

std::string Dialect::Select(const std::string &cond, const std::string &a,
                            const std::string &b) const {
  if (language_ == ShaderLanguage::kWgsl) return "select(" + b + ", " + a + ", " + cond + ")";
  return "(" + cond + " ? " + a + " : " + b + ")";
}

std::string Dialect::ConstInt(const std::string &name, long value) const {
  const std::string v = std::to_string(value);
  switch (language_) {
    case ShaderLanguage::kGlsl: return "const int " + name + " = " + v + ";\n";
    case ShaderLanguage::kHlsl: return "static const int " + name + " = " + v + ";\n";
    case ShaderLanguage::kWgsl: return "const " + name + ": i32 = " + v + ";\n";
    case ShaderLanguage::kMsl: return "constant int " + name + " = " + v + ";\n";
  }
  return "";
}

std::string Dialect::ArrayOpen(const std::string &name, size_t count) const {
  const std::string n = std::to_string(count);
  switch (language_) {
    case ShaderLanguage::kGlsl: return "const float " + name + "[" + n + "] = float[" + n + "](\n";
    case ShaderLanguage::kHlsl: return "static const float " + name + "[" + n + "] = {\n";
    // A private variable, not a const: indexing a const array with a
    // run-time index makes some compilers copy it into every invocation.
    case ShaderLanguage::kWgsl:
      return "var<private> " + name + ": array<f32, " + n + "> = array<f32, " + n + ">(\n";
    case ShaderLanguage::kMsl: return "constant float " + name + "[" + n + "] = {\n";
  }
  return "";
}

std::string Dialect::ArrayClose() const {
  return language_ == ShaderLanguage::kGlsl || language_ == ShaderLanguage::kWgsl ? ");\n" : "};\n";
}

std::vector<std::pair<std::string, std::string>> Dialect::TextureParams(
    const std::string &name) const {
  switch (language_) {
    // highp: GLSL ES gives samplers lowp by default.
    case ShaderLanguage::kGlsl: return {{"highp sampler2D", name}};
    case ShaderLanguage::kHlsl:
      return {{"Texture2D<float4>", name}, {"SamplerState", name + "_sampler"}};
    case ShaderLanguage::kWgsl: return {{"texture_2d<f32>", name}, {"sampler", name + "_sampler"}};
    case ShaderLanguage::kMsl: return {{"texture2d<float>", name}, {"sampler", name + "_sampler"}};
  }
  return {};
}

std::string Dialect::TextureArgs(const std::string &name) const {
  return language_ == ShaderLanguage::kGlsl ? name : name + ", " + name + "_sampler";
}

std::string Dialect::SampleLevel0(const std::string &name, const std::string &uv) const {
  switch (language_) {
    case ShaderLanguage::kGlsl: return "textureLod(" + name + ", " + uv + ", 0.0)";
    case ShaderLanguage::kHlsl:
      return name + ".SampleLevel(" + name + "_sampler, " + uv + ", 0.0f)";
    case ShaderLanguage::kWgsl:
      return "textureSampleLevel(" + name + ", " + name + "_sampler, " + uv + ", 0.0)";
    case ShaderLanguage::kMsl:
      return name + ".sample(" + name + "_sampler, " + uv + ", level(0.0f))";
  }
  return "";
}

std::string Dialect::Prologue() const {
  return language_ == ShaderLanguage::kMsl ? "#include <metal_stdlib>\nusing namespace metal;\n\n"
                                           : "";
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
