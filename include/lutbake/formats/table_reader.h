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

// T.exr: values (float32, widened), channel names, and the metadata (every
// string attribute; errorMax and errorRms from their double attributes).
// The axes and the table kind come from the metadata keys axisX, axisY and
// table. `errors` is left empty: an EXR carries only errorMax.
Table ReadExrTable(const std::string &path);

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
