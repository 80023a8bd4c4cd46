// Reading baked tables back, for `lutbake check` and the tests: the EXR
// images (through OpenEXR) and the values of a generated C++ header. The
// .bin reader is ReadBinaryTable (binary_format.h). All readers validate
// what they read and throw IoError (writer.h) on a malformed file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/table.h"

namespace lutbake {

// The axes (metadata axisX, axisY, axisZ) and the definition (metadata
// table, "T" or "T.err") of a table read from an image `width` texels wide
// and `height` high (a 3D table's slices stacked along y). Throws IoError,
// naming `path`, when they are missing, malformed or do not match the size.
void ShapeFromMetadata(const std::string &path, long width, long height, Table *table);

// T.exr: values (float32, widened), channel names, and the metadata (every
// string attribute; errorMax and errorRms from their double attributes).
// The axes and the table kind come from the metadata keys axisX, axisY and
// table. `errors` is left empty: an EXR carries only errorMax.
Table ReadExrTable(const std::string &path);

// T.png (png_table.cpp), T.ktx2 (ktx2_table.cpp), T.dds (dds_table.cpp):
// values as stored (q / (2^b - 1) for PNG; float32 or half, widened),
// channel names Y or R, G, and the metadata the writer put in the file
// (tEXt chunks; the KTX2 key lutbake.metadata; the DDS trailer). `errors`
// is left empty: the files carry errorMax.
Table ReadPngTable(const std::string &path);
Table ReadKtx2Table(const std::string &path);
Table ReadDdsTable(const std::string &path);

// The source embeddings (source_formats.h: T.inc, T.js, T.ts, T.glsl,
// T.hlsl, T.wgsl, T.metal): the metadata of their opening comment, and the
// literals between "// lutbake-values-begin" and "// lutbake-values-end",
// float32 or binary16 bit patterns as errorStorage says, widened.
Table ReadSourceTable(const std::string &path);

// three.js's RectAreaLightTexturesLib.js as --format threejs-ltc writes it
// (threejs_module.cpp): the metadata of its opening comment and an
// eight-channel table, channels 0 to 3 from LTC_MAT_1 and 4 to 7 from
// LTC_MAT_2.
Table ReadThreejsLtcModule(const std::string &path);
// One array `const NAME = [ ... ];` of such a module, or of three.js's own
// (ltc_code's table, no metadata): exactly `count` numbers, or IoError.
std::vector<float> ReadThreejsLtcArray(const std::string &path, const std::string &name,
                                       size_t count);

// The storage of a generated header: its sizes, kValues as written (float,
// or half bit patterns decoded), and
// the metadata repeated in its opening comment ("//   key: value" lines).
struct HeaderValues {
  int width = 0, height = 0, channels = 0;
  int depth = 1;      // kDepth of a 3D table's header
  bool half = false;  // half storage: values are the decoded halves
  std::vector<float> values;
  std::vector<std::pair<std::string, std::string>> metadata;
};
HeaderValues ReadHeaderValues(const std::string &path);

}  // namespace lutbake
