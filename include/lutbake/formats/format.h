// The file formats, one record each: its name (what --format and a preset's
// texture say), the extension of its files, how it stores the values, its
// writer and, where lutbake can read it back as a table, its reader. Each
// record is defined beside its writer (exr_writer.cpp, png_table.cpp, ...)
// and listed once, in format_registry.cpp; everything else (bake, presets,
// check, the command line's --format) asks this list and spells no format
// name. (OpenImageIO keeps its image formats the same way: one plugin
// each, listed once.)
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lutbake/formats/writer.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table.h"

namespace lutbake {

struct TableFormat {
  std::string name;       // "exr", "png16", "inc-half", ...
  std::string extension;  // ".exr", including the dot
  // The storage of the values in the file, under the write options (the
  // header's and .bin's storage are options; the others are fixed).
  std::function<ValueType(const WriteOptions &)> storage;
  std::function<std::unique_ptr<TableWriter>()> makeWriter;
  // Reads a file of this format back as a table (values widened to double,
  // metadata where the file has it); empty where lutbake cannot (the C++
  // header is read by ReadHeaderValues, which returns its own structure).
  std::function<Table(const std::string &path)> read;
  // Offered by `bake --format`; the engine-specific layouts (c-array,
  // threejs-dfg) serve presets only.
  bool bakeFormat = true;
  // Source text that embeds the values (.inc, JS/TS modules, shader
  // arrays), read back by ReadSourceTable.
  bool sourceText = false;
  // The most channels a table in it may have (exr, bin, header: any table's,
  // kMaxTableChannels; the image textures and the shader arrays: two).
  int maxChannels = 2;
  // A closed form fitted to the table (the fit formats), not its texels:
  // for 1D and 2D integrated tables only.
  bool fittedForm = false;
};

// Every format, in the order `bake --format` lists them.
const std::vector<TableFormat> &AllFormats();
// The record of a format name, or nullptr.
const TableFormat *FindFormat(std::string_view name);
// The names `bake --format` accepts.
std::vector<std::string> BakeFormatNames();

// A fixed storage, for the records.
inline std::function<ValueType(const WriteOptions &)> FixedStorage(ValueType type) {
  return [type](const WriteOptions &) { return type; };
}

}  // namespace lutbake
