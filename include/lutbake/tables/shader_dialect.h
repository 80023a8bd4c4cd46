// The spelling of the four shading languages lutbake writes (GLSL ES 3.00 /
// 4.50, HLSL, WGSL, Metal): types, declarations, functions, texture reads.
// The shader code file (formats/shader_code.cpp) and the tables' own shader
// helpers (TableDefinition::ShaderHelpers, beside each table's C++ header
// helpers) write through it, so a table's helpers need nothing of the
// formats layer.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace lutbake {

enum class ShaderLanguage { kGlsl, kHlsl, kWgsl, kMsl };

namespace source_text {

// A float32 value printed to round-trip ("%.9g"), always with a '.' or an
// exponent so that every language reads a floating-point literal; `suffix`
// ("f" for C, C++, HLSL and Metal) is appended.
std::string FloatLiteral(double value, const char *suffix);

// One shading language's spelling of types, declarations and texture reads.
class Dialect {
 public:
  explicit Dialect(ShaderLanguage language) : language_(language) {}
  ShaderLanguage language() const { return language_; }
  // float, or a vector of n floats (n = 2, 3, 4).
  std::string Float(int n = 1) const;
  std::string Int() const;
  std::string Lit(double value) const;  // a float literal
  // A vector constructor (n > 1) or the one expression (n = 1).
  std::string Vec(const std::vector<std::string> &args) const;
  // A local declaration, "  float x = e;\n" or "  let x: f32 = e;\n".
  std::string Let(const std::string &type, const std::string &name, const std::string &expr) const;
  // A function; params are (type, name) pairs; body is its statements.
  std::string Function(const std::string &result, const std::string &name,
                       const std::vector<std::pair<std::string, std::string>> &params,
                       const std::string &body) const;
  std::string ToInt(const std::string &expr) const;
  std::string ToFloat(const std::string &expr) const;
  // cond ? a : b
  std::string Select(const std::string &cond, const std::string &a, const std::string &b) const;
  // A module-scope integer constant and float32 array (values from
  // WriteValues in between `open` and `close`).
  std::string ConstInt(const std::string &name, long value) const;
  std::string ArrayOpen(const std::string &name, size_t count) const;
  std::string ArrayClose() const;
  const char *LiteralSuffix() const;
  // The parameters that pass a 2D texture (and its sampler), the arguments
  // that forward them, and a read of it at uv with no mip bias: a vec4.
  std::vector<std::pair<std::string, std::string>> TextureParams(const std::string &name) const;
  std::string TextureArgs(const std::string &name) const;
  std::string SampleLevel0(const std::string &name, const std::string &uv) const;
  // What precedes the functions (Metal: metal_stdlib).
  std::string Prologue() const;

 private:
  ShaderLanguage language_;
};

}  // namespace source_text
}  // namespace lutbake
