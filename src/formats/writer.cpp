#include "lutbake/formats/writer.h"

namespace lutbake {

std::unique_ptr<TableWriter> MakeWriter(const std::string &formatName) {
  if (formatName == "exr") return MakeExrWriter();
  if (formatName == "bin") return MakeBinaryWriter();
  if (formatName == "header") return MakeCppHeaderWriter();
  return nullptr;
}

}  // namespace lutbake
