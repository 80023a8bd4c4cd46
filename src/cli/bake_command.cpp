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

namespace lutbake::cli {

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
  AddFileOptions(app, o);
  app.add_flag("--json", o.json, "Print the summary as one JSON object on stdout");
  app.add_flag("-q,--quiet", o.quiet, "No progress or summary lines (errors are still printed)");
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

// On a terminal, a table's progress as one line rewritten in place. The
// bake reports from its worker threads: one at a time draws.
std::function<void(const std::string &, double)> TerminalProgress() {
  if (!::isatty(STDERR_FILENO)) return {};
  struct Shown {
    std::mutex mutex;
    std::string name;
    int percent = -1;
  };
  auto shown = std::make_shared<Shown>();
  return [shown](const std::string &name, double fraction) {
    const int percent = std::clamp(static_cast<int>(fraction * 100.0), 0, 100);
    std::lock_guard<std::mutex> lock(shown->mutex);
    if (name != shown->name) shown->percent = -1;
    shown->name = name;
    if (percent <= shown->percent) return;
    shown->percent = percent;
    const int filled = percent / 4;
    std::fprintf(stderr, "\r%-12s [%s%s] %3d%%", name.c_str(), std::string(filled, '#').c_str(),
                 std::string(25 - filled, ' ').c_str(), percent);
    if (percent >= 100) std::fprintf(stderr, "\r%60s\r", "");
    std::fflush(stderr);
  };
}

// The request the options describe; `app` tells which options were given.
BakeRequest RequestOf(const BakeOptions &o, CLI::App &app) {
  const auto given = [&app](const char *flag) { return app.count(flag) > 0; };
  BakeRequest r;
  r.outputDirectory = o.outDir;
  if (given("--tables")) r.tables = SplitList(o.tables);
  if (given("--format")) r.formats = SplitList(o.formats);
  ModelsOf(o, app, &r);
  r.size = o.size;
  r.etaSize = o.etaSize;
  r.sampling = SamplingRequestOf(o.sampling, app);
  r.errorMaps = o.errorMap;
  r.threads = o.threads;
  if (given("--namespace")) r.headerNamespace = o.headerNamespace;
  if (given("--header-type")) r.headerType = o.headerType;
  if (given("--bin-type")) r.binType = o.binType;
  if (!o.shaders.empty()) r.shaders = SplitList(o.shaders);
  r.scenes = o.scene.scenes;
  r.manifests = o.scene.manifests;
  r.noIbl = o.scene.noIbl;
  r.noCompensation = o.scene.noCompensation;
  r.skipUnsupported = o.skipUnsupported;
  r.preset = o.preset;
  if (given("--files")) r.presetFiles = SplitList(o.presetFiles);
  r.progress = o.quiet ? nullptr : TerminalProgress();
  r.note = [](const std::string &line) { std::cerr << "lutbake bake: " << line << "\n"; };
  if (!o.quiet) r.tableDone = [](const BakedTable &t) { std::cerr << TableSummaryLine(t) << "\n"; };
  return r;
}

void PrintResult(const BakeResult &result, bool json, bool quiet) {
  if (result.planNeedsNothing) {
    std::cerr << "lutbake bake: the plan needs no tables; nothing written.\n";
    for (const std::string &line : result.nothingToBake) std::cerr << "  " << line << "\n";
    return;
  }
  if (result.tolerance > 0.0 && !quiet) std::cerr << ToleranceLine(result);
  if (!quiet) std::cerr << WrittenFilesText(result);
  if (json) std::cout << result.json << "\n";
}

}  // namespace

int RunBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app) {
  BakeRequest request = RequestOf(o, app);
  request.commandLine = commandLine;
  const InterruptGuard interrupt;
  request.cancellation = &interrupt.token();
  return RunLibraryCall("bake", o.outDir, [&] { PrintResult(Bake(request), o.json, o.quiet); });
}

}  // namespace lutbake::cli
