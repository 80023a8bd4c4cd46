// Table writers: one small interface, one file per format (exr_writer.cpp,
// binary_writer.cpp, cpp_header_writer.cpp). A writer writes exactly the
// path it is given; AtomicOutputSet (atomic_output.h) chooses temporary names
// and renames them only when every file of a bake has been written.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lutbake/table.h"

namespace lutbake {

// A file could not be read or written: a runtime failure, not a bug.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct WriteOptions {
  std::string headerNamespace = "lutbake_luts";
};

class TableWriter {
 public:
  virtual ~TableWriter() = default;
  // "exr", "bin" or "header": the name used by --format.
  virtual const char *formatName() const = 0;
  // File extension including the dot: ".exr", ".bin", ".h".
  virtual const char *extension() const = 0;
  virtual void Write(const Table &table, const std::string &path,
                     const WriteOptions &options) const = 0;
};

std::unique_ptr<TableWriter> MakeExrWriter();
std::unique_ptr<TableWriter> MakeBinaryWriter();
std::unique_ptr<TableWriter> MakeCppHeaderWriter();

// Favg.h for a bake plan whose compensated materials all use Schlick's
// Fresnel: F_avg = 20/21 F0 + 1/21 F90 as inline functions (lookup_Favg(F0)
// and favg_schlick(F0, F90)), no table. `metadata` goes into its comment.
void WriteSchlickFavgHeader(const std::string &path, const WriteOptions &options,
                            const std::vector<std::pair<std::string, std::string>> &metadata);

// The writer for a --format name, or nullptr.
std::unique_ptr<TableWriter> MakeWriter(const std::string &formatName);

}  // namespace lutbake
