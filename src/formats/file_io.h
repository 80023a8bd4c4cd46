// Writing a whole file with every error checked: open, each write, close.
// The writers that build their bytes in memory (.bin, headers) use it, so
// that a full disk or a file size limit is reported with its reason.
#pragma once

#include <string>

namespace lutbake {

// Writes `bytes` to `path` (created or truncated). Throws IoError
// "cannot write PATH: REASON" (strerror) on any failure.
void WriteWholeFile(const std::string &path, const std::string &bytes);

}  // namespace lutbake
