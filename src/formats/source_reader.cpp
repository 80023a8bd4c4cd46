// ReadSourceTable (table_reader.h): the values of a source embedding
// (inc_table.cpp, js_table.cpp, shader_array_table.cpp) read back for
// `lutbake check` and the tests. Every embedding opens with
// "//   key: value" lines up to a lone "//", and brackets its literals with
// the lines "// lutbake-values-begin" and "// lutbake-values-end": float32
// literals ("0.5", "0.5f", "1e-05") or binary16 bit patterns ("0x3800"),
// separated by commas and white space.
#include <Imath/half.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "source_text.h"

namespace lutbake {

namespace {

long PositiveMetadata(const Table &table, const std::string &path, const char *key) {
  const std::string *text = table.FindMetadata(key);
  char *end = nullptr;
  const long v = text ? std::strtol(text->c_str(), &end, 10) : 0;
  if (!text || *end != '\0' || v < 1 || v > (1 << 16))
    throw IoError(path + ": metadata '" + key + "' missing or not a count in [1, 65536]");
  return v;
}

}  // namespace

Table ReadSourceTable(const std::string &path) {
  const std::string text = source_text::ReadText(path, size_t{1} << 30);
  Table table;
  table.metadata = source_text::HeaderMetadata(text);
  const std::string *storage = table.FindMetadata("errorStorage");
  if (!storage || (*storage != "float32" && *storage != "half"))
    throw IoError(path + ": metadata errorStorage missing or not float32 or half");
  const bool half = *storage == "half";
  const long width = PositiveMetadata(table, path, "width");
  const long height = PositiveMetadata(table, path, "height");
  const long depth = PositiveMetadata(table, path, "depth");
  const long channels = PositiveMetadata(table, path, "channels");
  if (channels > 4) throw IoError(path + ": more than 4 channels");
  table.channels = static_cast<int>(channels);
  table.channelNames =
      channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B", "A"};
  table.channelNames.resize(static_cast<size_t>(channels));
  ShapeFromMetadata(path, width, height * depth, &table);
  const size_t begin = text.find(std::string(source_text::kValuesBegin) + "\n");
  const size_t end = text.find(source_text::kValuesEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw IoError(path + ": no '" + source_text::kValuesBegin + "' ... '" +
                  source_text::kValuesEnd + "' block");
  const size_t expected = static_cast<size_t>(width) * height * depth * channels;
  const char *p = text.c_str() + begin + std::string(source_text::kValuesBegin).size() + 1;
  const char *last = text.c_str() + end;
  // The metadata's sizes are the file's claim: reserve no more than the
  // block can hold (a value and its separator take at least two characters).
  table.values.reserve(std::min(expected, static_cast<size_t>(last - p) / 2 + 1));
  while (p < last) {
    while (p < last && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t' || *p == ',')) ++p;
    if (p >= last) break;
    if (table.values.size() == expected)
      throw IoError(path + ": more than the " + std::to_string(expected) + " values expected");
    char *after = nullptr;
    if (half) {
      if (last - p < 3 || p[0] != '0' || (p[1] != 'x' && p[1] != 'X'))
        throw IoError(path + ": a value is not a binary16 bit pattern 0x....");
      const unsigned long bits = std::strtoul(p, &after, 16);
      if (after == p || bits > 0xffffu) throw IoError(path + ": a value is not a binary16 pattern");
      Imath::half h;
      h.setBits(static_cast<unsigned short>(bits));
      table.values.push_back(static_cast<float>(h));
    } else {
      const float v = std::strtof(p, &after);
      if (after == p) throw IoError(path + ": a value is not a float literal");
      if (*after == 'f' || *after == 'F') ++after;
      table.values.push_back(v);
    }
    p = after;
  }
  if (table.values.size() != expected)
    throw IoError(path + ": " + std::to_string(table.values.size()) + " values, " +
                  std::to_string(expected) + " expected");
  return table;
}

}  // namespace lutbake
