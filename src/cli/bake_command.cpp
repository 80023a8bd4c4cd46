#include "bake_command.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli_util.h"
#include "interrupt.h"
#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/formats/writer.h"
#include "lutbake/plans/plan.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/storage.h"
#include "preset_command.h"

namespace lutbake::cli {

namespace {

constexpr int kMaxSize = 4096;

}  // namespace

NdfKind ParseNdf(const std::string &s) {
  return s == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
}
SmithForm ParseSmith(const std::string &s) {
  return s == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
}
FresnelModel ParseFresnel(const std::string &s) {
  if (s == "dielectric") return FresnelModel::kDielectric;
  if (s == "conductor") return FresnelModel::kConductor;
  if (s == "f82") return FresnelModel::kF82;
  return FresnelModel::kSchlick;
}

std::vector<std::string> TableNames() {
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables()) names.push_back(table->Name());
  return names;
}

void SetupBakeCommand(CLI::App &app, BakeOptions &o) {
  app.add_option("--out", o.outDir, "Output directory (created if missing)")
      ->required()
      ->type_name("DIR");
  app.add_option("--tables", o.tables,
                 "Tables to bake (with --scene: which of the planned tables; one the plan "
                 "leaves out is an error)")
      ->capture_default_str()
      ->check(ListOf(TableNames()));
  AddModelOptions(app, o.ndf, o.smith);
  AddSheenOptions(app, o.sheenVisibility, o.sheenAlpha);
  app.add_option("--fresnel", o.fresnel,
                 "Fresnel model of the Favg table: schlick (axis F0 in [0,1]), dielectric (exact, "
                 "axis eta in [1,3]), conductor (exact, axes eta in [0,4] x k in [0,10]), f82 (F82 "
                 "tint, closed form, axes F0 in [0,1] x tint in [0,1])")
      ->capture_default_str()
      ->check(OneOf({"schlick", "dielectric", "conductor", "f82"}));
  app.add_option("--size", o.size,
                 "Texels per axis for every table (default: 32 for E, Eavg, Favg; 128 for dfg)")
      ->type_name("N")
      ->check(InRange(1, kMaxSize, "texels per axis"));
  app.add_option("--eta-size", o.etaSize,
                 "Texels of the eta axis of the 3D tables (their own default otherwise)")
      ->type_name("N")
      ->check(InRange(1, kMaxSize, "texels of the eta axis"));
  AddSamplingOptions(app, o.sampling, "texel");
  app.add_flag("--error-map", o.errorMap,
               "Also write T.err.exr: the per-texel bound of T.exr's float32 values (their "
               "rounding included), same layout and channels as T");
  AddThreadsOption(app, o.threads, "; output does not depend on it");
  app.add_option("--format", o.formats,
                 "Files to write per table: exr (T.exr), bin (T.bin), header (T.h), png8 / png16 "
                 "(T.png, 8 or 16 bits rounded to nearest: adds at most half a step, 1/510 or "
                 "1/131070; values must lie in [0, 1]), ktx2 / ktx2-half (T.ktx2, float32 or "
                 "binary16), dds / dds-half (T.dds with the DX10 header, float32 or binary16); "
                 "source embeddings: inc / inc-half (T.inc, Filament-style literals for an array "
                 "initialiser), js / js-half and ts / ts-half (T.js, T.ts: ES or TypeScript "
                 "module, Float32Array or binary16 Uint16Array), glsl-array, hlsl-array, "
                 "wgsl-array, msl-array (T.glsl, T.hlsl, T.wgsl, T.metal: a constant float32 "
                 "array and its bilinear lookup); every file's errorMax covers its own storage")
      ->capture_default_str()
      ->check(ListOf({"exr", "bin", "header", "png8", "png16", "ktx2", "ktx2-half", "dds",
                      "dds-half", "inc", "inc-half", "js", "js-half", "ts", "ts-half", "glsl-array",
                      "hlsl-array", "wgsl-array", "msl-array"}));
  app.add_option("--shader", o.shaders,
                 "Also write shader functions for the baked tables, one file per language: "
                 "lutbake.glsl, lutbake.hlsl, lutbake.wgsl, lutbake.metal (texture lookups at "
                 "each table's texel-centre convention; split sum, F82 term, Kulla-Conty and "
                 "sheen albedo scaling where their tables are baked)")
      ->type_name("LANGS")
      ->check(ListOf({"glsl", "hlsl", "wgsl", "msl"}));
  app.add_option("--namespace", o.headerNamespace, "Namespace of the generated C++ headers")
      ->capture_default_str()
      ->check(CppNamespace());
  app.add_option("--header-type", o.headerType,
                 "Storage of the values in T.h: float (exact float32) or half (IEEE binary16 in "
                 "uint16_t: half the bytes, adds at most 2^-12 for values in [0, 1]; kErrorMax "
                 "includes it)")
      ->capture_default_str()
      ->check(OneOf({"float", "half"}));
  app.add_option("--bin-type", o.binType,
                 "Storage of the values and bounds in T.bin: float (float32, as the EXR) or "
                 "double (float64: keeps bounds below float32's rounding of up to 3e-8, for "
                 "--tolerance under 1e-7)")
      ->capture_default_str()
      ->check(OneOf({"float", "double"}));
  app.add_flag("--json", o.json, "Print the summary as one JSON object on stdout");
  AddSceneOptions(app, o.scene);
  app.add_flag("--skip-unsupported", o.skipUnsupported,
               "With --scene: bake the plan although some materials use features lutbake does "
               "not bake (they get no table)");
  app.add_option("--preset", o.preset,
                 "Write exactly the textures an engine samples, in its layout, model and "
                 "format, and DIR/preset.json describing them (lutbake presets lists them)")
      ->type_name("NAME")
      ->check(OneOf(PresetNames()));
  app.add_option("--files", o.presetFiles,
                 "With --preset: bake only these of its files, comma-separated (lutbake "
                 "presets --json lists each preset's files)")
      ->type_name("FILE,...");
  app.footer(
      "With no option beyond --out, every texel of E, Eavg and dfg is integrated by the "
      "quadrature until its bound is below 1e-8; with the float32 rounding of the stored "
      "value, every stated bound is below 4e-8 (float32-exact), in a fraction of a second. "
      "--samples N samples instead (visible normals, scrambled Sobol points), --tolerance EPS "
      "asks for another bound.\n\n"
      "Example:\n  lutbake bake --out out\n"
      "  lutbake bake --out luts --tables E,Eavg --ndf beckmann --size 64 --format exr,header\n"
      "  lutbake bake --out luts --scene car.gltf   # only what the scene needs (lutbake plan)\n"
      "  lutbake bake --out dfg --preset filament   # Filament's dfg.inc, exact (lutbake presets)");
}

namespace {

// One table to bake: its kind, settings and axes, the name of its files,
// and what the plan adds to its metadata.
struct BakeJob {
  const TableDefinition *table;
  BakeSettings settings;
  Axis x, y;
  std::string name;
  std::vector<std::pair<std::string, std::string>> metadata;
  Axis z = LinearAxis("", 0.0, 1.0, 1);  // a 3D table's third axis
};

// Options that choose models, which a plan decides instead. (--tables is
// accepted: with a plan it selects among the planned tables.)
int PlanConflicts(CLI::App &app) {
  for (const char *flag : {"--ndf", "--smith", "--fresnel"})
    if (app.count(flag) > 0) {
      std::cerr << "lutbake bake: " << flag
                << " cannot be combined with --scene or --manifest: the plan chooses the "
                   "models (see lutbake plan)\n";
      return 2;
    }
  return 0;
}

// Large requests: before the work, an estimate of each large table's time
// and memory on stderr. The time is measured: the same table baked (twice,
// the second timed) on a sample of its axes (up to 16 texel centres on x and y, 2 on z, as listed
// axes), its wall time scaled by the texels (the cost varies across a
// table, so this is a rough figure, and says so). The memory is what the
// bake holds for one table at a time: values and bounds in double, the
// per-texel statistics and a writer's float copy, texels x (24 channels +
// 64) bytes (a 1024 x 1024 dfg: 117 MiB estimated, 103 MiB peak measured).
// Printed when a table would take over kLargeSeconds or kLargeBytes.
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

void EstimateLargeRequests(const std::vector<BakeJob> &jobs, int threads) {
  for (const BakeJob &job : jobs) {
    const size_t texels = static_cast<size_t>(job.x.count) * job.y.count * job.z.count;
    if (texels < kSmallestTimed) continue;
    const Axis x = SampleOf(job.x, 16), y = SampleOf(job.y, 16), z = SampleOf(job.z, 2);
    const size_t sampled = static_cast<size_t>(x.count) * y.count * z.count;
    // Twice, timing the second: the first builds the rules and tables every
    // later evaluation shares.
    BakeTableOn(*job.table, job.settings, x, y, z);
    const auto start = std::chrono::steady_clock::now();
    BakeTableOn(*job.table, job.settings, x, y, z);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() *
        static_cast<double>(texels) / static_cast<double>(sampled);
    const double bytes = static_cast<double>(texels) * (24.0 * job.table->Channels() + 64.0);
    if (seconds < kLargeSeconds && bytes < kLargeBytes) continue;
    std::fprintf(stderr,
                 "lutbake bake: %s: %zu texels, about %.0f s on %d threads (%zu texels timed: "
                 "a rough figure) and about %.0f MiB of memory\n",
                 job.name.c_str(), texels, seconds, threads, sampled, bytes / (1024.0 * 1024.0));
  }
}

// On a terminal, the bake's progress as one line rewritten in place. The
// bake reports from its worker threads: one at a time draws.
ProgressFn TerminalProgress(const std::string &name) {
  if (!::isatty(STDERR_FILENO)) return {};
  struct Shown {
    std::mutex mutex;
    int percent = -1;
  };
  auto shown = std::make_shared<Shown>();
  return [name, shown](double fraction) {
    const int percent = std::clamp(static_cast<int>(fraction * 100.0), 0, 100);
    std::lock_guard<std::mutex> lock(shown->mutex);
    if (percent <= shown->percent) return;
    shown->percent = percent;
    const int filled = percent / 4;
    std::fprintf(stderr, "\r%-12s [%s%s] %3d%%", name.c_str(), std::string(filled, '#').c_str(),
                 std::string(25 - filled, ' ').c_str(), percent);
    if (percent >= 100) std::fprintf(stderr, "\r%60s\r", "");
    std::fflush(stderr);
  };
}

}  // namespace

int RunBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app) {
  if (app.count("--files") > 0 && o.preset.empty()) {
    std::cerr << "lutbake bake: --files chooses files of a preset; it needs --preset NAME ("
              << PresetNameList() << ")\n";
    return 2;
  }
  if (!o.preset.empty()) return RunPresetBake(o, commandLine, app);
  BakeSettings settings;
  settings.ndf = ParseNdf(o.ndf);
  settings.smith = ParseSmith(o.smith);
  settings.fresnel = ParseFresnel(o.fresnel);
  ParseSheenVisibility(o.sheenVisibility, &settings.sheenVisibility);
  ParseSheenAlpha(o.sheenAlpha, &settings.sheenAlpha);
  if (o.size > 0) settings.size = o.size;
  if (o.etaSize > 0) settings.depthSize = o.etaSize;
  if (const int status = ApplySamplingOptions("bake", o.sampling, &settings)) return status;
  const bool tolerance = settings.tolerance > 0.0;
  settings.commandLine = commandLine;
  const InterruptGuard interrupt;
  settings.cancellation = &interrupt.token();

  std::vector<BakeJob> jobs;
  bool schlickFavgHeader = false;
  std::vector<std::pair<std::string, std::string>> planMetadata;
  if (o.scene.used()) {
    if (const int status = PlanConflicts(app)) return status;
    PlanOptions planOptions;
    planOptions.size = settings.size;
    BakePlan plan;
    if (const int status = MakePlanOrComplain("bake", o.scene, planOptions, &plan)) return status;
    if (!plan.unsupported.empty() && !o.skipUnsupported) {
      std::cerr << "lutbake bake: the scene uses features lutbake does not bake; nothing "
                   "written:\n";
      for (const UnsupportedFeature &u : plan.unsupported)
        std::cerr << "  " << u.material << ": " << u.feature << "\n";
      std::cerr << "Add --skip-unsupported to bake the rest of the plan without them.\n";
      return 1;
    }
    // --tables with a plan: bake only the planned tables of those kinds (every
    // variant of each), and fail, saying why, if the plan leaves one out, so
    // that a build that includes T.h stops here rather than at its #include.
    if (app.count("--tables") > 0) {
      const std::vector<std::string> wanted = SplitList(o.tables);
      const auto isWanted = [&](const TableDefinition &table) {
        return std::find(wanted.begin(), wanted.end(), table.Name()) != wanted.end();
      };
      std::vector<std::string> missing;
      for (const std::string &name : wanted) {
        const TableDefinition &table = TableNamed(name);
        const bool planned =
            std::any_of(plan.tables.begin(), plan.tables.end(),
                        [&](const PlannedTable &t) { return t.definition == &table; }) ||
            (table.Role() == PlanRole::kFresnelAverage && plan.schlickFavgFunction);
        if (planned) continue;
        std::string reason = "not needed by the plan";
        for (const OmittedTable &t : plan.omitted)
          if (t.name == name) reason = t.reason;
        missing.push_back(name + ": " + reason);
      }
      if (!missing.empty()) {
        std::cerr << "lutbake bake: --tables " << o.tables
                  << " asks for tables the plan leaves out; nothing written:\n";
        for (const std::string &m : missing) std::cerr << "  " << m << "\n";
        std::cerr << "Drop them from --tables, or change the scene, manifest or --no-ibl / "
                     "--no-compensation (see lutbake plan).\n";
        return 1;
      }
      plan.tables.erase(
          std::remove_if(plan.tables.begin(), plan.tables.end(),
                         [&](const PlannedTable &t) { return !isWanted(*t.definition); }),
          plan.tables.end());
      // The closed-form F_avg header stands for the Fresnel-average table.
      if (std::none_of(wanted.begin(), wanted.end(), [](const std::string &name) {
            return TableNamed(name).Role() == PlanRole::kFresnelAverage;
          }))
        plan.schlickFavgFunction = false;
    }
    if (plan.empty()) {
      std::cerr << "lutbake bake: the plan needs no tables; nothing written.\n";
      for (const OmittedTable &t : plan.omitted)
        std::cerr << "  " << t.name << ": " << t.reason << "\n";
      return 0;
    }
    std::string sources;
    for (const auto *list : {&o.scene.scenes, &o.scene.manifests})
      for (const std::string &path : *list) sources += (sources.empty() ? "" : ", ") + path;
    planMetadata.emplace_back("planSources", sources);
    for (const PlannedTable &t : plan.tables) {
      BakeJob job{t.definition, PlannedSettings(t, settings), t.x, t.y, t.name, planMetadata};
      // The plan's IORs, or the table's own third axis.
      job.z = t.z.name.empty() ? DefaultDepthAxis(*t.definition, job.settings) : t.z;
      job.metadata.emplace_back("planMaterials", JoinNames(t.materials));
      jobs.push_back(job);
    }
    schlickFavgHeader = plan.schlickFavgFunction;
  } else {
    for (const std::string &name : SplitList(o.tables)) {
      BakeJob job{&TableNamed(name), settings, {}, {}, name, {}};
      DefaultAxes(*job.table, settings, &job.x, &job.y, &job.z);
      jobs.push_back(job);
    }
  }
  // A 3D table of --size N and --eta-size M has N^2 M texels: at most
  // kMaxSize^2 in all, as the largest 2D table (values and bounds in double
  // take 32 bytes a texel and channel).
  for (const BakeJob &job : jobs) {
    const double texels = static_cast<double>(job.x.count) * job.y.count * job.z.count;
    if (texels > static_cast<double>(kMaxSize) * kMaxSize) {
      std::cerr << "lutbake bake: " << job.name << " would have " << job.x.count << " x "
                << job.y.count << " x " << job.z.count << " texels; accepted: at most " << kMaxSize
                << " x " << kMaxSize << " in all (lower --size or --eta-size)\n";
      return 2;
    }
  }
  // An estimator a table has no sampler for is a usage error, before any work.
  for (const BakeJob &job : jobs)
    if (const std::string problem = job.table->EstimatorProblem(job.settings.estimator);
        !problem.empty()) {
      std::cerr << "lutbake bake: --estimator " << ToString(job.settings.estimator) << ": "
                << problem << "\n";
      return 2;
    }
  std::vector<std::unique_ptr<TableWriter>> writers;
  for (const std::string &name : SplitList(o.formats)) {
    writers.push_back(MakeWriter(name));
    // png8 and png16 both write T.png, ktx2 and ktx2-half T.ktx2, ...
    for (size_t i = 0; i + 1 < writers.size(); ++i)
      if (std::string(writers[i]->extension()) == writers.back()->extension()) {
        std::cerr << "lutbake bake: --format " << o.formats << ": " << writers[i]->formatName()
                  << " and " << name << " both write T" << writers.back()->extension()
                  << "; choose one\n";
        return 2;
      }
  }

  bool created = false;
  if (const int status = PrepareOutputOrComplain("bake", o.outDir, &created)) return status;
  // What earlier runs killed here left: temporaries no live process owns.
  RemoveStaleTemporaries(o.outDir);

  const int threads = ThreadCount(o.threads);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(threads));

  nlohmann::ordered_json summary;
  summary["lutbakeVersion"] = LutbakeVersion();
  summary["out"] = o.outDir;
  summary["threads"] = threads;
  if (tolerance) summary["tolerance"] = settings.tolerance;
  const auto bakeStart = std::chrono::steady_clock::now();
  summary["tables"] = nlohmann::ordered_json::array();
  try {
    // Inside the try: a signal during the estimate ends the run as any other.
    EstimateLargeRequests(jobs, threads);
    AtomicOutputSet output;
    WriteOptions writeOptions;
    writeOptions.headerNamespace = o.headerNamespace;
    writeOptions.headerStorage =
        o.headerType == "half" ? HeaderStorage::kHalf : HeaderStorage::kFloat;
    writeOptions.binaryValues = o.binType == "double" ? ValueType::kFloat64 : ValueType::kFloat32;
    std::vector<std::string> unreached;
    std::vector<Table> shapes;  // the baked tables without values, for --shader
    for (const BakeJob &job : jobs) {
      BakeStats stats;
      Table table = BakeTableOn(*job.table, job.settings, job.x, job.y, job.z,
                                TerminalProgress(job.name), &stats);
      if (job.name != job.table->Name()) table.name = job.name;
      table.metadata.insert(table.metadata.end(), job.metadata.begin(), job.metadata.end());
      nlohmann::ordered_json files = nlohmann::ordered_json::array();
      const std::filesystem::path base = std::filesystem::path(o.outDir) / job.name;
      for (const auto &writer : writers) {
        const std::string path = base.string() + writer->extension();
        interrupt.token().ThrowIfCancelled();
        output.Write(path, [&](const std::string &temporary) {
          writer->Write(table, temporary, writeOptions);
        });
        files.push_back(path);
      }
      if (!o.shaders.empty()) {
        shapes.push_back(table);
        shapes.back().values.clear();
        shapes.back().errors.clear();
      }
      if (o.errorMap) {
        const std::string path = base.string() + ".err.exr";
        interrupt.token().ThrowIfCancelled();
        output.Write(path, [&](const std::string &temporary) {
          MakeExrWriter()->Write(ErrorMapOf(table), temporary, writeOptions);
        });
        files.push_back(path);
      }
      const size_t texels = table.texelCount();
      const double meanSamples = static_cast<double>(stats.samples) / static_cast<double>(texels);
      // The bound as the float32 files state it (rounding included).
      const BoundSummary stored = SummarizeStoredBounds(table, ValueType::kFloat32);
      char line[320];
      const std::string depth = table.is3D() ? " x " + std::to_string(table.depth()) : "";
      std::snprintf(
          line, sizeof line,
          "%-5s %4d x %-4d%s samples/texel mean %-9.4g max %-9llu quadrature texels %-6llu"
          " %7.3f s  error max %.2e  rms %.2e (float32 as stored; integration %.1e)\n",
          job.name.c_str(), table.width(), table.height(), depth.c_str(), meanSamples,
          static_cast<unsigned long long>(stats.maxTexelSamples),
          static_cast<unsigned long long>(stats.quadratureTexels), stats.seconds, stored.max,
          stored.rms, table.MaxError());
      std::cerr << line;
      if (stats.unconverged > 0)
        unreached.push_back(job.name + " (" + std::to_string(stats.unconverged) + " texels)");
      nlohmann::ordered_json entry;
      entry["name"] = job.name;
      entry["width"] = table.width();
      entry["height"] = table.height();
      if (table.is3D()) entry["depth"] = table.depth();
      entry["channels"] = table.channels;
      entry["estimator"] = *table.FindMetadata("estimator");
      entry["samples"] = stats.samples;
      entry["samplesPerTexelMean"] = meanSamples;
      entry["samplesPerTexelMax"] = stats.maxTexelSamples;
      entry["quadratureTexels"] = stats.quadratureTexels;
      entry["quadratureEvaluations"] = stats.evaluations;
      entry["seconds"] = stats.seconds;
      entry["errorMax"] = stored.max;
      entry["errorRms"] = stored.rms;
      entry["integrationErrorMax"] = table.MaxError();
      entry["files"] = files;
      summary["tables"].push_back(entry);
    }
    const bool headers = std::any_of(writers.begin(), writers.end(), [](const auto &w) {
      return std::string(w->formatName()) == "header";
    });
    // The metadata of a header that holds functions and no table of its own:
    // what it is, then the plan's sources, the version and the command line.
    const auto functionHeaderMetadata = [&](std::vector<std::pair<std::string, std::string>> what) {
      what.insert(what.end(), planMetadata.begin(), planMetadata.end());
      what.emplace_back("lutbakeVersion", LutbakeVersion());
      what.emplace_back("commandLine", commandLine);
      return what;
    };
    if (schlickFavgHeader && headers) {
      const std::string path = (std::filesystem::path(o.outDir) / "Favg.h").string();
      output.Write(path, [&](const std::string &temporary) {
        WriteSchlickFavgHeader(
            temporary, writeOptions,
            functionHeaderMetadata(
                {{"table", "Favg"},
                 {"content", "closed form (Schlick), no table: F_avg = 20/21 F0 + 1/21 F90"}}));
      });
      nlohmann::ordered_json entry;
      entry["name"] = "Favg";
      entry["closedForm"] = "F_avg = 20/21 F0 + 1/21 F90";
      entry["files"] = {path};
      summary["tables"].push_back(entry);
      std::cerr << "Favg  closed form (every compensated material uses Schlick): Favg.h\n";
    }
    // Kulla-Conty helpers wherever a header bake holds both a table and the
    // average that declares them (TableRelations::kullaConty) for one model:
    // E and Eavg, E_beckmann and Eavg_beckmann, ...
    for (const BakeJob &job : jobs) {
      const TableRelations relations = job.table->Relations();
      if (!headers || !relations.kullaConty) continue;
      const std::string suffix = job.name.substr(std::string(job.table->Name()).size());
      const bool averaged = std::any_of(jobs.begin(), jobs.end(), [&](const BakeJob &other) {
        return other.table->Name() == relations.averageOf &&
               other.name == relations.averageOf + suffix;
      });
      if (!averaged) continue;
      const std::string path =
          (std::filesystem::path(o.outDir) / ("kulla_conty" + suffix + ".h")).string();
      output.Write(path, [&](const std::string &temporary) {
        WriteKullaContyHeader(
            temporary, writeOptions, suffix,
            functionHeaderMetadata(
                {{"helpers", "Kulla-Conty f_ms and F_ms over E" + suffix + " and Eavg" + suffix}}));
      });
      summary["helpers"].push_back(path);
    }
    // --shader: lutbake.<ext> per language, committed with the tables.
    for (const std::string &name : SplitList(o.shaders)) {
      ShaderLanguage language = ShaderLanguage::kGlsl;
      ParseShaderLanguage(name, &language);  // checked by ListOf
      const std::string path =
          (std::filesystem::path(o.outDir) / (std::string("lutbake") + ShaderExtension(language)))
              .string();
      output.Write(path, [&](const std::string &temporary) {
        WriteShaderCode(temporary, language, shapes,
                        functionHeaderMetadata({{"shader", std::string(ToString(language)) +
                                                               " functions of the baked tables"}}));
      });
      summary["shaders"].push_back(path);
    }
    if (!unreached.empty()) {
      std::cerr << "lutbake bake: --tolerance " << settings.tolerance << " not reached within "
                << "--max-samples " << settings.maxSamples << " in " << JoinNames(unreached)
                << "; nothing written. Raise --max-samples or drop --sampling-only.\n";
      output.Discard();  // removes the temporaries, so that the directory is empty again
      RemoveCreatedDirectory(o.outDir, created);
      return 1;
    }
    // The last moment a signal stops the run; one that arrives during the
    // commit (milliseconds: renames) lets it finish.
    interrupt.token().ThrowIfCancelled();
    output.Commit();
  } catch (const Cancelled &c) {
    // `output` is gone: its temporaries with it.
    RemoveCreatedDirectory(o.outDir, created);
    std::cerr << "lutbake bake: interrupted by " << SignalName(c.reason())
              << "; nothing written to " << o.outDir << "\n";
    return 128 + c.reason();
  } catch (const IoError &e) {
    std::cerr << "lutbake bake: " << e.what() << "\n";
    RemoveCreatedDirectory(o.outDir, created);
    return 1;
  } catch (const std::bad_alloc &) {
    std::cerr << "lutbake bake: out of memory\n";
    return 1;
  }
  const double totalSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - bakeStart).count();
  summary["seconds"] = totalSeconds;
  if (tolerance) {
    double worst = 0.0;
    for (const auto &t : summary["tables"])
      if (t.contains("integrationErrorMax"))
        worst = std::max(worst, t["integrationErrorMax"].get<double>());
    char line[200];
    std::snprintf(line, sizeof line,
                  "tolerance %.3g reached on every texel: max integration bound %.2e, %.2f s in "
                  "all (the files add the rounding of their storage)\n",
                  settings.tolerance, worst, totalSeconds);
    std::cerr << line;
  }
  if (o.json) std::cout << summary.dump(2) << "\n";
  return 0;
}

}  // namespace lutbake::cli
