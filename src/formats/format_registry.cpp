// The one list of formats (format.h).
#include <algorithm>

#include "format_list.h"

namespace lutbake {

const std::vector<TableFormat> &AllFormats() {
  static const std::vector<TableFormat> formats = [] {
    std::vector<TableFormat> all;
    for (auto records : {ExrFormats, BinaryFormats, CppHeaderFormats, PngFormats, Ktx2Formats,
                         DdsFormats, IncFormats, JsFormats, ShaderArrayFormats, CArrayFormats,
                         ThreejsFormats, BabylonLtcFormats, HdrpLtcFormats, FitFormats})
      for (TableFormat &format : records()) all.push_back(std::move(format));
    return all;
  }();
  return formats;
}

const TableFormat *FindFormat(std::string_view name) {
  const std::vector<TableFormat> &all = AllFormats();
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const TableFormat &format) { return format.name == name; });
  return it == all.end() ? nullptr : &*it;
}

std::vector<std::string> BakeFormatNames() {
  std::vector<std::string> names;
  for (const TableFormat &format : AllFormats())
    if (format.bakeFormat) names.push_back(format.name);
  return names;
}

std::unique_ptr<TableWriter> MakeWriter(const std::string &formatName) {
  const TableFormat *format = FindFormat(formatName);
  return format ? format->makeWriter() : nullptr;
}

}  // namespace lutbake
