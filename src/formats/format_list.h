// The records of format.h, each defined in its format's own file; listed
// once in format_registry.cpp.
#pragma once

#include <vector>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/formats/table_reader.h"

namespace lutbake {

std::vector<TableFormat> ExrFormats();          // exr_writer.cpp
std::vector<TableFormat> BinaryFormats();       // binary_writer.cpp
std::vector<TableFormat> CppHeaderFormats();    // cpp_header_writer.cpp
std::vector<TableFormat> PngFormats();          // png_table.cpp
std::vector<TableFormat> Ktx2Formats();         // ktx2_table.cpp
std::vector<TableFormat> DdsFormats();          // dds_table.cpp
std::vector<TableFormat> IncFormats();          // inc_table.cpp
std::vector<TableFormat> JsFormats();           // js_table.cpp
std::vector<TableFormat> ShaderArrayFormats();  // shader_array_table.cpp
std::vector<TableFormat> CArrayFormats();       // c_array_writer.cpp
std::vector<TableFormat> ThreejsFormats();      // threejs_module.cpp
std::vector<TableFormat> BabylonLtcFormats();   // babylon_ltc.cpp
std::vector<TableFormat> HdrpLtcFormats();      // hdrp_ltc_cs.cpp
std::vector<TableFormat> FitFormats();          // fit_format.cpp

}  // namespace lutbake
