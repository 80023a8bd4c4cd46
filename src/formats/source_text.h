// What the source embeddings (inc_table.cpp, js_table.cpp,
// shader_array_table.cpp) and the shader code (shader_code.cpp) share: the
// metadata comment every file opens with, the value literals, and the
// four shading languages' spelling of the few constructs the lookups use.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/formats/source_formats.h"
#include "lutbake/tables/shader_dialect.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table.h"

namespace lutbake::source_text {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// The whole text of the file at `path`; an IoError when it cannot be opened
// or holds more than `maxBytes` ("over 256 MiB").
std::string ReadText(const std::string &path, size_t maxBytes);

// The "//   key: value" lines of the comment block that opens a source file
// lutbake wrote (WriteMetadataComment), in order.
Metadata HeaderMetadata(const std::string &text);

// The comment lines that bracket the values (ReadSourceTable looks for them).
inline constexpr const char *kValuesBegin = "// lutbake-values-begin";
inline constexpr const char *kValuesEnd = "// lutbake-values-end";

// The table's metadata as a file of `storage` states it (errorMax, errorRms
// and errorStorage of the stored values: MetadataForStorage), then width,
// height, depth, channels, channelMeanings, layout, storage and
// storageErrorMax (the most the storage moves a float32 value).
Metadata EmbeddingMetadata(const Table &table, ValueType storage);

// "// <title>\n", then "//   key: value" per pair, then "//\n". Line breaks
// in a value are written as \n and \r.
void WriteMetadataComment(std::ostream &out, const std::string &title, const Metadata &metadata);

// The axes in words, one "// " line each: quantity, range or nodes, texel
// count and where the texel centres sit.
void WriteAxisComment(std::ostream &out, const Table &table);

// The binary16 bit pattern (nearest even) as "0x3c00".
std::string HalfLiteral(double value);

// The values, `perLine` to a line, each as FloatLiteral(v, suffix) or
// HalfLiteral(v), separated by ", " and, with trailingComma, one after the
// last too; bracketed by kValuesBegin and kValuesEnd on lines of their own.
void WriteValues(std::ostream &out, const Table &table, ValueType storage, const char *suffix,
                 bool trailingComma);

// The continuous texel coordinate of axis value `v` on `axis`, clamped to
// [0, count - 1]: t = i at the centre of texel i. Linear axis:
//   t = clamp((v - min) count / (max - min) - 0.5, 0, count - 1);
// listed axis (nodes n_0 < ... < n_{count-1}): linear in v between nodes,
//   t = sum over i of clamp((v - n_i) / (n_{i+1} - n_i), 0, 1).
std::string TexelCoordinate(const Dialect &d, const Axis &axis, const std::string &v);

// The parameter names of a table's lookups: its axes' quantities.
std::vector<std::string> AxisParams(const Table &table);

// ".x", ".xy", ".xyz" or "" (all four) of a vec4 for `channels`.
std::string Swizzle(int channels);

}  // namespace lutbake::source_text
