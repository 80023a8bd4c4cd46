#include "bake_command.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <mutex>

#include "cli_util.h"
#include "interrupt.h"
#include "lutbake/api/names.h"
#include "lutbake/api/progress.h"

namespace lutbake::cli {

namespace {

constexpr int kMaxSize = 4096;  // texels per axis (the library refuses larger 3D tables too)

// --format, --shader, --namespace, --header-type, --bin-type: what is
// written per table, and how.
void AddFileOptions(CLI::App &app, BakeOptions &o) {
  app.add_option("--format", o.formats,
                 "Files to write per table T (docs/formats.md): exr, bin, header (T.h), png8 / "
                 "png16 (values in [0, 1], rounded to 8 or 16 bits), ktx2, dds, and the source "
                 "embeddings inc, js, ts, glsl-array, hlsl-array, wgsl-array, msl-array; the -half "
                 "forms store binary16. Every file's errorMax covers its own storage")
      ->capture_default_str()
      ->check(ListOf(FormatNames()));
  app.add_option("--shader", o.shaders,
                 "Also write shader functions for the baked tables, one file per language: "
                 "lutbake.glsl, lutbake.hlsl, lutbake.wgsl, lutbake.metal (texture lookups at "
                 "each table's texel-centre convention; split sum, F82 term, Kulla-Conty and "
                 "sheen albedo scaling where their tables are baked)")
      ->type_name("LANGS")
      ->check(ListOf(ShaderLanguageNames()));
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
  app.add_option("--fit-tolerance", o.fitTolerance,
                 "--format fit: the certified bound (256 coefficients per channel at 4.9e-4 and "
                 "above, 4096 below)")
      ->type_name("EPS")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

}  // namespace

void SetupBakeCommand(CLI::App &app, BakeOptions &o) {
  app.add_option("-o,--out", o.outDir, "Output directory (created if missing)")
      ->required()
      ->type_name("DIR");
  app.add_option("--tables", o.tables,
                 "Tables to bake (with --scene: which of the planned tables; one the plan "
                 "leaves out is an error)")
      ->capture_default_str()
      ->check(ListOf(TableNames()));
  AddModelOptions(app, o.models);
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
  AddFileOptions(app, o);
  app.add_flag("--json", o.json, "Print the summary as one JSON object on stdout");
  app.add_flag("-q,--quiet", o.quiet, "No progress or summary lines (errors are still printed)");
  app.add_flag("-v,--verbose", o.verbose,
               "Also the equivalent command line first, and each file with its stated bounds")
      ->excludes("--quiet");
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
      "By default every texel of E, Eavg and dfg is integrated by the quadrature to a bound "
      "below 1e-8 (4e-8 with the float32 rounding as stored), in a fraction of a second; "
      "--samples N samples instead, --tolerance EPS asks for another bound.\n\n"
      "Example:\n  lutbake bake --out out\n"
      "  lutbake bake --out luts --tables E,Eavg --ndf beckmann --size 64 --format exr,header\n"
      "  lutbake bake --out luts --scene car.gltf   # only what the scene needs (lutbake plan)\n"
      "  lutbake bake --out dfg --preset filament   # Filament's dfg.inc, exact (lutbake presets)");
}

namespace {

// The request the options describe; `app` tells which options were given.
BakeRequest RequestOf(const BakeOptions &o, CLI::App &app) {
  const auto given = [&app](const char *flag) { return app.count(flag) > 0; };
  BakeRequest r;
  r.outputDirectory = o.outDir;
  if (given("--tables")) r.tables = SplitList(o.tables);
  if (given("--format")) r.formats = SplitList(o.formats);
  ModelsOf(o.models, app, &r);
  r.size = o.size;
  r.etaSize = o.etaSize;
  r.sampling = SamplingRequestOf(o.sampling, app);
  r.errorMaps = o.errorMap;
  r.threads = o.threads;
  if (given("--namespace")) r.headerNamespace = o.headerNamespace;
  if (given("--header-type")) r.headerType = o.headerType;
  if (given("--bin-type")) r.binType = o.binType;
  if (given("--fit-tolerance")) r.fitTolerance = o.fitTolerance;
  if (!o.shaders.empty()) r.shaders = SplitList(o.shaders);
  r.scenes = o.scene.scenes;
  r.manifests = o.scene.manifests;
  r.noIbl = o.scene.noIbl;
  r.noCompensation = o.scene.noCompensation;
  r.skipUnsupported = o.skipUnsupported;
  r.preset = o.preset;
  if (given("--files")) r.presetFiles = SplitList(o.presetFiles);
  // A bar on a terminal, a line every few seconds in a log; cleared for each
  // table's summary line.
  auto shown =
      std::make_shared<ProgressPrinter>("lutbake bake", ProgressPrinter::StyleFor(stderr, o.quiet));
  r.progress = [shown](const std::string &table, double f) { shown->Update(table, f); };
  r.note = [](const std::string &line) { std::cerr << "lutbake bake: " << line << "\n"; };
  if (!o.quiet)
    r.tableDone = [shown](const BakedTable &t) {
      shown->Clear();
      std::cerr << TableSummaryLine(t) << "\n";
    };
  return r;
}

void PrintResult(const BakeResult &result, bool json, bool quiet, bool verbose) {
  if (result.planNeedsNothing) {
    std::cerr << "lutbake bake: the plan needs no tables; nothing written.\n";
    for (const std::string &line : result.nothingToBake) std::cerr << "  " << line << "\n";
    return;
  }
  if (!quiet) std::cerr << WrittenFilesText(result, verbose);
  if (json) std::cout << result.json << "\n";
}

}  // namespace

int RunBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app) {
  BakeRequest request = RequestOf(o, app);
  request.commandLine = commandLine;
  if (o.verbose) std::cerr << "lutbake bake: " << EquivalentCommandLine(request) << "\n";
  const InterruptGuard interrupt;
  request.cancellation = &interrupt.token();
  return RunLibraryCall("bake", o.outDir,
                        [&] { PrintResult(Bake(request), o.json, o.quiet, o.verbose); });
}

}  // namespace lutbake::cli
