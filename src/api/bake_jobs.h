// The one loop that bakes and writes the tables of a bake (not public):
// bake.cpp makes its jobs from table names or a plan, preset_bake.cpp from a
// preset's textures, and both run them with RunBakeJobs.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/output_transaction.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table.h"

namespace lutbake {

// One table a bake writes: a registry table, a plan's table or a preset's
// texture.
struct BakeJob {
  // What progress, BakedTable::name and WrittenFile::table call it.
  std::string name;
  // Makes the table, reporting the fraction done to `progress` (empty when
  // nobody listens) and what it cost to `stats` (a maker that measures only
  // time fills stats->seconds).
  std::function<Table(const ProgressFn &progress, BakeStats *stats)> make;
  // The texels it will hold, where known (0: not known). Jobs that are all
  // known and together hold at most kTexelsMadeTogether are made at once.
  size_t texels = 0;
  // The files it is written in, each with its format.
  struct File {
    std::string name;
    const TableFormat *format;
  };
  std::vector<File> files;
  Metadata metadata;      // appended to the table's own
  bool errorMap = false;  // also NAME.err.exr, the bounds as float32 stores the values
  // BakedTable's storage and bounds are those of files[0], the one file a
  // preset's texture has; otherwise the bounds as float32 stores the values
  // (BakedTable::storage empty), what the files of a table state.
  bool summaryOfItsFile = false;
  // Called with the table and its summary once its files are written,
  // before the request's tableDone.
  std::function<void(const Table &table, const BakedTable &baked)> written;
};

// Jobs of at most this many texels in all are made at once (values and
// bounds: 16 bytes per texel and channel, at most 64 MiB for 4 channels).
inline constexpr size_t kTexelsMadeTogether = size_t{1} << 20;

// Bakes `jobs` in order, each written through `output` once it is made
// (a fitted table's fit maps, NAME.fit.exr, besides its files; jobs that
// hold few texels together are all made first, at once):
// progress, cancellation between the steps and tableDone from `request`,
// each file and table recorded in `result`. Returns "NAME (N texels)" for
// each table whose sampled texels missed the tolerance (the caller decides
// when that fails the bake).
std::vector<std::string> RunBakeJobs(const std::vector<BakeJob> &jobs, const BakeRequest &request,
                                     const WriteOptions &writeOptions, OutputTransaction &output,
                                     BakeResult *result);

// The end of every bake: commits `output` (a cancellation stops it here
// last) and records in `result` what the commit removed and left, the set's
// manifest and the seconds since `start`.
void CommitBake(OutputTransaction &output, const BakeRequest &request,
                std::chrono::steady_clock::time_point start, BakeResult *result);

}  // namespace lutbake
