// The bake loop that tables, plans and presets share (bake_jobs.h): make a
// table, write its files, summarise the bounds they state, record it.
#include "bake_jobs.h"

#include <tbb/parallel_for.h>

#include <map>
#include <memory>
#include <utility>

#include "lutbake/tables/storage.h"

namespace lutbake {

namespace {

// The state of one run of the jobs.
struct JobRunner {
  const BakeRequest &request;
  const WriteOptions &writeOptions;
  OutputTransaction &output;
  BakeResult &result;
  std::vector<std::string> unreached;  // "NAME (N texels)"

  void ThrowIfCancelled() const {
    if (request.cancellation) request.cancellation->ThrowIfCancelled();
  }

  // Writes map(table) (ErrorMapOf, FitMapOf) as NAME<suffix>, an OpenEXR
  // file recorded under `format`, stating no bound of its own.
  void WriteMap(const BakeJob &job, const Table &table, Table (*map)(const Table &),
                const char *suffix, const char *format, BakedTable *baked) {
    ThrowIfCancelled();
    const std::string path = output.Write(job.name + suffix, [&](const std::string &temporary) {
      MakeExrWriter()->Write(map(table), temporary, writeOptions);
    });
    result.files.push_back({path, job.name, format, 0.0, 0.0});
    baked->files.push_back(path);
  }

  // A job's table, made and not yet written.
  struct Made {
    Table table;
    BakeStats stats;
  };

  Made Make(const BakeJob &job) const {
    const BakeRequest &r = request;
    Made made;
    ProgressFn progress;
    if (r.progress) progress = [&r, &job](double fraction) { r.progress(job.name, fraction); };
    made.table = job.make(progress, &made.stats);
    made.table.metadata.insert(made.table.metadata.end(), job.metadata.begin(), job.metadata.end());
    return made;
  }

  void Write(const BakeJob &job, Made &&made) {
    const BakeRequest &r = request;
    const Table &table = made.table;
    const BakeStats &stats = made.stats;
    BakedTable baked;
    // The table's files, written at once (the writers only read the table).
    ThrowIfCancelled();
    std::vector<std::pair<std::string, std::function<void(const std::string &)>>> writes;
    for (const BakeJob::File &file : job.files)
      writes.emplace_back(file.name, [&](const std::string &temporary) {
        file.format->makeWriter()->Write(table, temporary, writeOptions);
      });
    const std::vector<std::string> paths = output.WriteEach(writes);
    // Once per storage type (a table's exr, bin and header all state the
    // float32 bounds).
    std::map<ValueType, BoundSummary> summaries;
    const auto summaryOf = [&](ValueType type) -> const BoundSummary & {
      auto found = summaries.find(type);
      if (found == summaries.end())
        found = summaries.emplace(type, SummarizeStoredBounds(table, type)).first;
      return found->second;
    };
    std::vector<BoundSummary> fileBounds;
    for (size_t k = 0; k < job.files.size(); ++k) {
      const TableFormat &format = *job.files[k].format;
      fileBounds.push_back(summaryOf(format.storage(writeOptions)));
      result.files.push_back(
          {paths[k], job.name, format.name, fileBounds.back().max, fileBounds.back().rms});
      baked.files.push_back(paths[k]);
    }
    if (job.errorMap) WriteMap(job, table, ErrorMapOf, ".err.exr", "error-map", &baked);
    // A fitted table's per-texel measures (ltc_ggx: lobe error, polygon
    // error, leakage), always: they are what its values are worth.
    if (!table.fitMaps.empty()) WriteMap(job, table, FitMapOf, ".fit.exr", "fit-map", &baked);
    BoundSummary stated;
    if (job.summaryOfItsFile) {
      stated = fileBounds.at(0);
      baked.storage = ToString(job.files[0].format->storage(writeOptions));
    } else {
      // The bound as the float32 files state it (rounding included).
      stated = summaryOf(ValueType::kFloat32);
    }
    baked.name = job.name;
    baked.width = table.width();
    baked.height = table.height();
    baked.depth = table.is3D() ? table.depth() : 1;
    baked.channels = table.channels;
    if (const std::string *estimator = table.FindMetadata("estimator"))
      baked.estimator = *estimator;
    baked.samples = stats.samples;
    baked.maxTexelSamples = stats.maxTexelSamples;
    baked.quadratureTexels = stats.quadratureTexels;
    baked.evaluations = stats.evaluations;
    baked.seconds = stats.seconds;
    baked.errorMax = stated.max;
    baked.errorRms = stated.rms;
    baked.integrationErrorMax = table.MaxError();
    if (stats.unconverged > 0)
      unreached.push_back(job.name + " (" + std::to_string(stats.unconverged) + " texels)");
    if (job.written) job.written(table, baked);
    if (r.tableDone) r.tableDone(baked);
    result.tables.push_back(baked);
  }
};

}  // namespace

std::vector<std::string> RunBakeJobs(const std::vector<BakeJob> &jobs, const BakeRequest &request,
                                     const WriteOptions &writeOptions, OutputTransaction &output,
                                     BakeResult *result) {
  JobRunner runner{request, writeOptions, output, *result, {}};
  // Tables that fit together in memory are made at once: their texels share
  // the threads, so no table waits while the last texels of the one before
  // finish on one thread (the default set: E's 1024 texels, Eavg's 32
  // values of very different cost, then dfg's 16384). Each texel is computed
  // alone, so the values are the same. Then they are written in order, as
  // one at a time would be.
  size_t texels = 0;
  bool known = jobs.size() > 1;
  for (const BakeJob &job : jobs) {
    known = known && job.texels > 0;
    texels += job.texels;
  }
  if (known && texels <= kTexelsMadeTogether) {
    std::vector<JobRunner::Made> made(jobs.size());
    tbb::parallel_for(size_t{0}, jobs.size(), [&](size_t k) { made[k] = runner.Make(jobs[k]); });
    for (size_t k = 0; k < jobs.size(); ++k) runner.Write(jobs[k], std::move(made[k]));
  } else {
    for (const BakeJob &job : jobs) runner.Write(job, runner.Make(job));
  }
  return runner.unreached;
}

void CommitBake(OutputTransaction &output, const BakeRequest &request,
                std::chrono::steady_clock::time_point start, BakeResult *result) {
  output.Commit(request.cancellation);
  result->foreignFiles = output.foreignFiles();
  result->removedFiles = output.removedFiles();
  result->files.push_back({output.PathOf(kSetManifestName), "", "set", 0.0, 0.0});
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lutbake
