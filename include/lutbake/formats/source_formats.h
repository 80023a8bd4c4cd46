// Tables as source code an engine compiles in, and the shader functions that
// read them (issue 16, "Formats" and "Shader code").
//
// Source embeddings (--format), each generic over any table (1D, 2D, 3D,
// any channel count) and each opening with a comment that states the table,
// its axes (quantity, range, texel centres), the layout, what each channel
// holds, the storage and errorMax of the values as stored (storage.h: the
// integration bound plus the rounding to that storage):
//   inc, inc-half    T.inc: Filament-style comma-separated literals, to be
//                    #included inside an array initialiser (float literals
//                    "0.5f," or binary16 bit patterns "0x3800,");
//   js, js-half      T.js: an ES module exporting the values as a
//                    Float32Array or, half, a Uint16Array of binary16 bits
//                    (three.js DataTexture with HalfFloatType takes those),
//                    with width, height, depth, channels, axes, errorMax;
//   ts, ts-half      T.ts: the same module with TypeScript types;
//   glsl-array, hlsl-array, wgsl-array, msl-array
//                    T.glsl, T.hlsl, T.wgsl, T.metal: a constant float32
//                    array and lookup_T(...), bilinear (trilinear for 3D)
//                    between texel centres, clamped at the edges.
// Every embedding brackets its values with the comment lines
// "// lutbake-values-begin" and "// lutbake-values-end", which is how
// ReadSourceTable (table_reader.h) finds them for `lutbake check`.
//
// Shader code (--shader): lutbake.glsl, lutbake.hlsl, lutbake.wgsl and
// lutbake.metal hold, for the tables of one bake, the texture lookups with
// each table's exact convention and the functions an engine needs of them
// (split sum, F82 term, Kulla-Conty, sheen albedo scaling), only those whose
// tables were baked.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/formats/writer.h"
#include "lutbake/tables/shader_dialect.h"

namespace lutbake {

// "glsl", "hlsl", "wgsl", "msl".
const char *ToString(ShaderLanguage language);
// The language of "glsl", "hlsl", "wgsl" or "msl"; false for anything else.
bool ParseShaderLanguage(const std::string &name, ShaderLanguage *language);
// ".glsl", ".hlsl", ".wgsl", ".metal".
const char *ShaderExtension(ShaderLanguage language);

// --format inc / inc-half (storage kFloat32 or kHalf).
std::unique_ptr<TableWriter> MakeIncWriter(ValueType storage);
// --format js / js-half / ts / ts-half.
std::unique_ptr<TableWriter> MakeJsWriter(ValueType storage, bool typescript);
// --format glsl-array / hlsl-array / wgsl-array / msl-array.
std::unique_ptr<TableWriter> MakeShaderArrayWriter(ShaderLanguage language);

// lutbake<ext> for `tables` (their axes, names and definitions; the values
// are not used): every table's texture lookup, and the helpers whose tables
// are all among them. `metadata` (version, command line) opens its comment.
void WriteShaderCode(const std::string &path, ShaderLanguage language,
                     const std::vector<Table> &tables,
                     const std::vector<std::pair<std::string, std::string>> &metadata);

}  // namespace lutbake
