#include "lutbake/tables/shader_dialect.h"

#include <cstdio>

namespace lutbake::source_text {

std::string FloatLiteral(double value, const char *suffix) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(value)));
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + suffix;
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

}  // namespace lutbake::source_text
