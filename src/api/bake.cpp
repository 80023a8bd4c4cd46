// lutbake::Bake for tables and bake plans (the preset path is
// preset_bake.cpp). The sequence: validate the request, make the job list
// (tables by name, or a plan's tables), check the sizes and estimators,
// open the output transaction, bake and write each table (RunBakeJobs,
// bake_jobs.cpp: the loop presets run too), add the helper headers and
// shader files, commit.
#include "lutbake/api/bake.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "bake_internal.h"
#include "bake_jobs.h"
#include "lutbake/api/names.h"
#include "lutbake/api/plan.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/output_transaction.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/formats/writer.h"
#include "lutbake/plans/plan.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/storage.h"

namespace lutbake {

namespace {

constexpr int kMaxSize = 4096;

// One table to bake: its kind, settings and axes, the name of its files,
// and what the plan adds to its metadata.
struct TableJob {
  const TableDefinition *table;
  BakeSettings settings;
  Axis x, y;
  std::string name;
  Metadata metadata;
  Axis z = LinearAxis("", 0.0, 1.0, 1);  // a 3D table's third axis
};

// What the jobs share beyond their own settings.
struct JobList {
  std::vector<TableJob> jobs;
  bool schlickFavgHeader = false;  // the plan's closed-form Favg.h
  Metadata planMetadata;
  bool planNeedsNothing = false;
  std::vector<std::string> nothingToBake;  // a plan that needs no table: why
};

std::vector<std::string> DefaultTables() { return {"E", "Eavg", "Favg", "dfg"}; }

BakeSettings SettingsOf(const BakeRequest &r) {
  BakeSettings settings;
  ApplyModels(r, &settings);
  if (r.size > 0) settings.size = r.size;
  if (r.etaSize > 0) settings.depthSize = r.etaSize;
  ApplySampling(r.sampling, &settings);
  settings.commandLine = r.commandLine;
  settings.cancellation = r.cancellation;
  return settings;
}

// --tables with a plan: only the planned tables of those kinds (every
// variant of each); one the plan leaves out fails, saying why, so that a
// build that includes T.h stops here rather than at its #include.
void SelectPlannedTables(const std::vector<std::string> &wanted, BakePlan *plan) {
  const auto isWanted = [&](const TableDefinition &table) {
    return std::find(wanted.begin(), wanted.end(), table.Name()) != wanted.end();
  };
  std::string missing;
  for (const std::string &name : wanted) {
    const TableDefinition &table = TableNamed(name);
    const bool planned =
        std::any_of(plan->tables.begin(), plan->tables.end(),
                    [&](const PlannedTable &t) { return t.definition == &table; }) ||
        (table.Role() == PlanRole::kFresnelAverage && plan->schlickFavgFunction);
    if (planned) continue;
    std::string reason = "not needed by the plan";
    for (const OmittedTable &t : plan->omitted)
      if (t.name == name) reason = t.reason;
    missing += "  " + name + ": " + reason + "\n";
  }
  if (!missing.empty())
    throw Error(Error::Kind::kRuntime,
                "--tables " + JoinNames(wanted) +
                    " asks for tables the plan leaves out; nothing written:\n" + missing +
                    "Drop them from --tables, or change the scene, manifest or --no-ibl / "
                    "--no-compensation (see lutbake plan).");
  plan->tables.erase(
      std::remove_if(plan->tables.begin(), plan->tables.end(),
                     [&](const PlannedTable &t) { return !isWanted(*t.definition); }),
      plan->tables.end());
  // The closed-form F_avg header stands for the Fresnel-average table.
  if (std::none_of(wanted.begin(), wanted.end(), [](const std::string &name) {
        return TableNamed(name).Role() == PlanRole::kFresnelAverage;
      }))
    plan->schlickFavgFunction = false;
}

JobList PlanJobs(const BakeRequest &r, const BakeSettings &settings) {
  // Options that choose models, which a plan decides instead. (--tables is
  // accepted: with a plan it selects among the planned tables.)
  for (const auto &[flag, given] :
       {std::pair{"--ndf", r.ndf.has_value()}, std::pair{"--smith", r.smith.has_value()},
        std::pair{"--fresnel", r.fresnel.has_value()}})
    if (given)
      throw UsageError(std::string(flag) +
                       " cannot be combined with --scene or --manifest: the plan chooses the "
                       "models (see lutbake plan)");
  PlanRequest planRequest{r.scenes, r.manifests, r.noIbl, r.noCompensation, settings.size};
  BakePlan plan = Plan(planRequest);
  if (!plan.unsupported.empty() && !r.skipUnsupported) {
    std::string message = "the scene uses features lutbake does not bake; nothing written:\n";
    for (const UnsupportedFeature &u : plan.unsupported)
      message += "  " + u.material + ": " + u.feature + "\n";
    throw Error(Error::Kind::kRuntime,
                message + "Add --skip-unsupported to bake the rest of the plan without them.");
  }
  if (r.tables) SelectPlannedTables(*r.tables, &plan);
  JobList list;
  if (plan.empty()) {
    list.planNeedsNothing = true;
    for (const OmittedTable &t : plan.omitted)
      list.nothingToBake.push_back(t.name + ": " + t.reason);
    return list;
  }
  std::string sources;
  for (const auto *paths : {&r.scenes, &r.manifests})
    for (const std::string &path : *paths) sources += (sources.empty() ? "" : ", ") + path;
  list.planMetadata.emplace_back("planSources", sources);
  for (const PlannedTable &t : plan.tables) {
    TableJob job{t.definition, PlannedSettings(t, settings), t.x, t.y, t.name, list.planMetadata};
    // The plan's IORs, or the table's own third axis.
    job.z = t.z.name.empty() ? DefaultDepthAxis(*t.definition, job.settings) : t.z;
    job.metadata.emplace_back("planMaterials", JoinNames(t.materials));
    list.jobs.push_back(job);
  }
  list.schlickFavgHeader = plan.schlickFavgFunction;
  return list;
}

JobList MakeJobs(const BakeRequest &r, const BakeSettings &settings) {
  if (!r.scenes.empty() || !r.manifests.empty()) return PlanJobs(r, settings);
  JobList list;
  for (const std::string &name : r.tables.value_or(DefaultTables())) {
    TableJob job{&TableNamed(name), settings, {}, {}, name, {}};
    DefaultAxes(*job.table, settings, &job.x, &job.y, &job.z);
    list.jobs.push_back(job);
  }
  return list;
}

// Sizes and estimators, before any work.
void CheckJobs(const std::vector<TableJob> &jobs) {
  // A 3D table of --size N and --eta-size M has N^2 M texels: at most
  // kMaxSize^2 in all, as the largest 2D table (values and bounds in double
  // take 32 bytes a texel and channel).
  for (const TableJob &job : jobs) {
    const double texels = static_cast<double>(job.x.count) * job.y.count * job.z.count;
    if (texels > static_cast<double>(kMaxSize) * kMaxSize)
      throw UsageError(job.name + " would have " + std::to_string(job.x.count) + " x " +
                       std::to_string(job.y.count) + " x " + std::to_string(job.z.count) +
                       " texels; accepted: at most " + std::to_string(kMaxSize) + " x " +
                       std::to_string(kMaxSize) + " in all (lower --size or --eta-size)");
  }
  for (const TableJob &job : jobs)
    if (const std::string problem = job.table->EstimatorProblem(job.settings.estimator);
        !problem.empty())
      throw UsageError("--estimator " + std::string(ToString(job.settings.estimator)) + ": " +
                       problem);
}

// Large requests: before the work, an estimate of each large table's time
// and memory. The time is measured: the same table baked (twice, the second
// timed) on a sample of its axes (up to 16 texel centres on x and y, 2 on
// z, as listed axes), its wall time scaled by the texels (the cost varies
// across a table, so this is a rough figure, and says so). The memory is
// what the bake holds for one table at a time: values and bounds in double,
// the per-texel statistics and a writer's float copy, texels x (24 channels
// + 64) bytes (a 1024 x 1024 dfg: 117 MiB estimated, 103 MiB peak
// measured). Reported when a table would take over kLargeSeconds or
// kLargeBytes.
constexpr double kLargeSeconds = 10.0;
constexpr double kLargeBytes = 1024.0 * 1024.0 * 1024.0;
constexpr size_t kSmallestTimed = 4096;  // smaller tables are not timed

// Up to n of an axis's texel centres, evenly spread, as a listed axis.
Axis SampleOf(const Axis &axis, int n) {
  if (axis.count <= n) return axis;
  std::vector<double> nodes;
  for (int k = 0; k < n; ++k)
    nodes.push_back(axis.TexelCenter(static_cast<int>((static_cast<size_t>(axis.count) - 1) *
                                                      static_cast<size_t>(k) / (n - 1))));
  return ListedAxis(axis.name, nodes);
}

void EstimateLargeRequests(const std::vector<TableJob> &jobs, int threads,
                           const std::function<void(const std::string &)> &note) {
  if (!note) return;
  for (const TableJob &job : jobs) {
    const size_t texels = static_cast<size_t>(job.x.count) * job.y.count * job.z.count;
    if (texels < kSmallestTimed) continue;
    const Axis x = SampleOf(job.x, 16), y = SampleOf(job.y, 16), z = SampleOf(job.z, 2);
    const size_t sampled = static_cast<size_t>(x.count) * y.count * z.count;
    // Twice, timing the second: the first builds the rules and tables every
    // later evaluation shares. The first, which does that work besides, takes
    // at least as long as the second: when even it projects to a small table
    // (the default dfg: 3 ms for its 256 texels), the second is not run.
    const double bytes = static_cast<double>(texels) * (24.0 * job.table->Channels() + 64.0);
    const auto timeSample = [&] {
      const auto start = std::chrono::steady_clock::now();
      BakeTableOn(*job.table, job.settings, x, y, z);
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() *
             static_cast<double>(texels) / static_cast<double>(sampled);
    };
    if (timeSample() < kLargeSeconds && bytes < kLargeBytes) continue;
    const double seconds = timeSample();
    if (seconds < kLargeSeconds && bytes < kLargeBytes) continue;
    char line[300];
    std::snprintf(line, sizeof line,
                  "%s: %zu texels, about %.0f s on %d threads (%zu texels timed: a rough "
                  "figure) and about %.0f MiB of memory",
                  job.name.c_str(), texels, seconds, threads, sampled, bytes / (1024.0 * 1024.0));
    note(line);
  }
}

// The writers of the request's formats, refusing two that write one file.
std::vector<const TableFormat *> FormatsOf(const BakeRequest &r) {
  std::vector<const TableFormat *> formats;
  const std::vector<std::string> names = r.formats.value_or(DefaultFormats());
  for (const std::string &name : names) {
    const TableFormat *format = FindFormat(name);
    if (!format || !format->bakeFormat)
      throw UsageError("--format '" + name +
                       "' is not accepted; accepted: a comma-separated "
                       "subset of " +
                       JoinNames(FormatNames()));
    // png8 and png16 both write T.png, ktx2 and ktx2-half T.ktx2, ...
    for (const TableFormat *earlier : formats)
      if (earlier->extension == format->extension)
        throw UsageError("--format " + JoinList(names) + ": " + earlier->name + " and " + name +
                         " both write T" + format->extension + "; choose one");
    formats.push_back(format);
  }
  return formats;
}

WriteOptions WriteOptionsOf(const BakeRequest &r) {
  WriteOptions options;
  options.headerNamespace = r.headerNamespace.value_or(options.headerNamespace);
  options.headerStorage =
      r.headerType.value_or("float") == "half" ? HeaderStorage::kHalf : HeaderStorage::kFloat;
  options.binaryValues =
      r.binType.value_or("float") == "double" ? ValueType::kFloat64 : ValueType::kFloat32;
  options.fitTolerance = r.fitTolerance.value_or(options.fitTolerance);
  return options;
}

// The loop's job (bake_jobs.h) of one table: BakeTableOn over its axes,
// under its name, in each of `formats`, and its error map if asked; with
// `shapes`, the table without its values goes there for the shader files.
BakeJob LoopJobOf(const TableJob &job, const std::vector<const TableFormat *> &formats,
                  bool errorMap, std::vector<Table> *shapes) {
  BakeJob loopJob;
  loopJob.name = job.name;
  loopJob.make = [&job](const ProgressFn &progress, BakeStats *stats) {
    Table table = BakeTableOn(*job.table, job.settings, job.x, job.y, job.z, progress, stats);
    if (job.name != job.table->Name()) table.name = job.name;
    return table;
  };
  for (const TableFormat *format : formats)
    loopJob.files.push_back({job.name + format->extension, format});
  loopJob.metadata = job.metadata;
  loopJob.texels = static_cast<size_t>(job.x.count) * static_cast<size_t>(job.y.count) *
                   static_cast<size_t>(job.z.count);
  loopJob.errorMap = errorMap;
  if (shapes)
    loopJob.written = [shapes](const Table &table, const BakedTable &) {
      shapes->push_back(table);
      shapes->back().values.clear();
      shapes->back().errors.clear();
    };
  return loopJob;
}

// The state of one bake run while it writes its helper and shader files.
struct Run {
  const BakeRequest &request;
  const JobList &list;
  const std::vector<const TableFormat *> &formats;
  WriteOptions writeOptions;
  OutputTransaction &output;
  BakeResult &result;
  std::vector<Table> shapes;  // the baked tables without values, for the shader files
};

// The metadata of a file that holds functions and no table of its own:
// what it is, then the plan's sources, the version and the command line.
Metadata FunctionFileMetadata(const Run &run, Metadata what) {
  what.insert(what.end(), run.list.planMetadata.begin(), run.list.planMetadata.end());
  what.emplace_back("lutbakeVersion", LutbakeVersion());
  what.emplace_back("commandLine", run.request.commandLine);
  return what;
}

void WriteHelperFiles(Run &run) {
  const bool headers = std::any_of(run.formats.begin(), run.formats.end(),
                                   [](const TableFormat *f) { return f->name == "header"; });
  if (run.list.schlickFavgHeader && headers) {
    const std::string path = run.output.Write("Favg.h", [&](const std::string &temporary) {
      WriteSchlickFavgHeader(
          temporary, run.writeOptions,
          FunctionFileMetadata(
              run, {{"table", "Favg"},
                    {"content", "closed form (Schlick), no table: F_avg = 20/21 F0 + 1/21 F90"}}));
    });
    run.result.files.push_back({path, "Favg", "header", 0.0, 0.0});
    BakedTable closed;
    closed.name = "Favg";
    closed.closedForm = "F_avg = 20/21 F0 + 1/21 F90";
    closed.files = {path};
    if (run.request.tableDone) run.request.tableDone(closed);
    run.result.tables.push_back(closed);
  }
  // Kulla-Conty helpers wherever a header bake holds both a table and the
  // average that declares them (TableRelations::kullaConty) for one model:
  // E and Eavg, E_beckmann and Eavg_beckmann, ...
  for (const TableJob &job : run.list.jobs) {
    const TableRelations relations = job.table->Relations();
    if (!headers || !relations.kullaConty) continue;
    const std::string suffix = job.name.substr(std::string(job.table->Name()).size());
    const bool averaged =
        std::any_of(run.list.jobs.begin(), run.list.jobs.end(), [&](const TableJob &other) {
          return other.table->Name() == relations.averageOf &&
                 other.name == relations.averageOf + suffix;
        });
    if (!averaged) continue;
    const std::string path =
        run.output.Write("kulla_conty" + suffix + ".h", [&](const std::string &temporary) {
          WriteKullaContyHeader(
              temporary, run.writeOptions, suffix,
              FunctionFileMetadata(run, {{"helpers", "Kulla-Conty f_ms and F_ms over E" + suffix +
                                                         " and Eavg" + suffix}}));
        });
    run.result.files.push_back({path, "", "helper", 0.0, 0.0});
  }
  // Shader functions: lutbake.<ext> per language, committed with the tables.
  for (const std::string &name : run.request.shaders) {
    ShaderLanguage language = ShaderLanguage::kGlsl;
    if (!ParseShaderLanguage(name, &language))
      throw UsageError("--shader '" + name +
                       "' is not accepted; accepted: a comma-separated "
                       "subset of " +
                       JoinNames(ShaderLanguageNames()));
    const std::string path = run.output.Write(
        std::string("lutbake") + ShaderExtension(language), [&](const std::string &temporary) {
          WriteShaderCode(
              temporary, language, run.shapes,
              FunctionFileMetadata(run, {{"shader", std::string(ToString(language)) +
                                                        " functions of the baked tables"}}));
        });
    run.result.files.push_back({path, "", "shader", 0.0, 0.0});
  }
}

std::string SummaryJson(const BakeResult &result) {
  nlohmann::ordered_json summary;
  summary["lutbakeVersion"] = LutbakeVersion();
  summary["out"] = result.outputDirectory;
  summary["threads"] = result.threads;
  if (result.tolerance > 0.0) summary["tolerance"] = result.tolerance;
  summary["tables"] = nlohmann::ordered_json::array();
  for (const BakedTable &t : result.tables) {
    nlohmann::ordered_json entry;
    entry["name"] = t.name;
    if (!t.closedForm.empty()) {
      entry["closedForm"] = t.closedForm;
      entry["files"] = t.files;
      summary["tables"].push_back(entry);
      continue;
    }
    entry["width"] = t.width;
    entry["height"] = t.height;
    if (t.depth > 1) entry["depth"] = t.depth;
    entry["channels"] = t.channels;
    entry["estimator"] = t.estimator;
    entry["samples"] = t.samples;
    entry["samplesPerTexelMean"] = MeanSamples(t);
    entry["samplesPerTexelMax"] = t.maxTexelSamples;
    entry["quadratureTexels"] = t.quadratureTexels;
    entry["quadratureEvaluations"] = t.evaluations;
    entry["seconds"] = t.seconds;
    entry["errorMax"] = t.errorMax;
    entry["errorRms"] = t.errorRms;
    entry["integrationErrorMax"] = t.integrationErrorMax;
    entry["files"] = t.files;
    summary["tables"].push_back(entry);
  }
  for (const WrittenFile &f : result.files)
    if (f.format == "helper") summary["helpers"].push_back(f.path);
  for (const WrittenFile &f : result.files)
    if (f.format == "shader") summary["shaders"].push_back(f.path);
  summary["seconds"] = result.seconds;
  return summary.dump(2);
}

}  // namespace

std::vector<std::string> DefaultFormats() { return {"exr", "bin", "header"}; }

std::string JoinList(const std::vector<std::string> &items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) s += (i ? "," : "") + items[i];
  return s;
}

std::string StreamedNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

double MeanSamples(const BakedTable &t) {
  const double texels = static_cast<double>(t.width) * t.height * t.depth;
  return texels > 0 ? static_cast<double>(t.samples) / texels : 0.0;
}

int ThreadCount(int requested) {
  return requested > 0 ? requested
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

BakeResult Bake(const BakeRequest &r) {
  if (r.presetFiles && r.preset.empty())
    throw UsageError("--files chooses files of a preset; it needs --preset NAME (" +
                     JoinNames(PresetNames()) + ")");
  if (r.commandLine.empty()) {
    BakeRequest spelled = r;
    spelled.commandLine = EquivalentCommandLine(r);
    return Bake(spelled);
  }
  if (!r.preset.empty()) return BakePreset(r);
  ValidateTableNames(r);
  ValidateApplicability(r);
  const BakeSettings settings = SettingsOf(r);
  const JobList list = MakeJobs(r, settings);
  BakeResult result;
  result.outputDirectory = r.outputDirectory;
  if (list.planNeedsNothing) {
    result.planNeedsNothing = true;
    result.nothingToBake = list.nothingToBake;
    return result;
  }
  CheckJobs(list.jobs);
  const std::vector<const TableFormat *> formats = FormatsOf(r);
  OutputTransaction output(r.outputDirectory, "--out", OutputMode::kSet, r.commandLine);
  result.threads = ThreadCount(r.threads);
  result.tolerance = settings.tolerance;
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(result.threads));
  const auto start = std::chrono::steady_clock::now();
  EstimateLargeRequests(list.jobs, result.threads, r.note);
  Run run{r, list, formats, WriteOptionsOf(r), output, result, {}};
  std::vector<BakeJob> loopJobs;
  for (const TableJob &job : list.jobs)
    loopJobs.push_back(
        LoopJobOf(job, formats, r.errorMaps, r.shaders.empty() ? nullptr : &run.shapes));
  const std::vector<std::string> unreached =
      RunBakeJobs(loopJobs, r, run.writeOptions, output, &result);
  WriteHelperFiles(run);
  if (!unreached.empty())
    throw Error(Error::Kind::kRuntime,
                "--tolerance " + StreamedNumber(settings.tolerance) + " not reached within " +
                    "--max-samples " + std::to_string(settings.maxSamples) + " in " +
                    JoinNames(unreached) +
                    "; nothing written. Raise --max-samples or drop --sampling-only.");
  CommitBake(output, r, start, &result);
  result.json = SummaryJson(result);
  return result;
}

}  // namespace lutbake
