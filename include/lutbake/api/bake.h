// lutbake::Bake: one call that bakes a set of files into a directory, as
// `lutbake bake` does (the command line only fills a BakeRequest from its
// options, calls Bake and prints the result).
//
//   lutbake::BakeRequest request;
//   request.tables = {"E", "dfg"};
//   request.formats = {"exr", "header"};
//   request.outputDirectory = "out";
//   lutbake::BakeResult result = lutbake::Bake(request);
//   for (const lutbake::WrittenFile &f : result.files) std::cout << f.path << ' ' << f.errorMax;
//
// A request asks for one of three things: tables by name (the default:
// E, Eavg, Favg, dfg), what scenes and manifests need (`scenes`,
// `manifests`: a bake plan), or an engine's preset (`preset`). The files
// appear all at once or not at all (OutputTransaction): Bake returns after
// the commit, or throws a lutbake::Error (UsageError for a request that
// cannot be done as asked, IoError when the work failed, Cancelled when the
// request's cancellation token was cancelled) and leaves the directory as
// it was. Unset optional fields take the command line's defaults; setting
// one that the request cannot use (a model option with a preset, say) is a
// UsageError naming it as the command line spells it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lutbake/api/sampling.h"
#include "lutbake/core/cancellation.h"
#include "lutbake/core/error.h"
#include "lutbake/tables/settings.h"

namespace lutbake {

// One file Bake wrote.
struct WrittenFile {
  std::string path;
  std::string table;   // the table (or preset texture) it holds; "" for shaders and helpers
  std::string format;  // its format name ("exr", "png16", ...; "shader", "helper", "json")
  // The largest stated bound of a value as this file stores it (rounding
  // included); 0 for files that hold no values.
  double errorMax = 0.0;
  double errorRms = 0.0;
};

// What one table's bake cost and reached.
struct BakedTable {
  std::string name;
  int width = 0, height = 0, depth = 1, channels = 0;
  std::string estimator;
  uint64_t samples = 0, maxTexelSamples = 0, quadratureTexels = 0, evaluations = 0;
  double seconds = 0.0;
  double errorMax = 0.0, errorRms = 0.0;  // as float32 stores it
  double integrationErrorMax = 0.0;       // before rounding
  std::string storage;                    // a preset texture's storage ("half", "unorm16")
  std::string closedForm;                 // a closed form written instead of a table
  std::vector<std::string> files;
};

struct BakeRequest {
  std::string outputDirectory;  // created if missing
  // Tables by name (TableNames()); unset: E, Eavg, Favg, dfg. With scenes or
  // manifests: which of the planned tables (one the plan leaves out is an
  // error).
  std::optional<std::vector<std::string>> tables;
  // Files per table (FormatNames()); unset: exr, bin, header.
  std::optional<std::vector<std::string>> formats;

  // Models (unset: GGX, height-correlated Smith, Schlick, Charlie, alpha = r).
  std::optional<NdfKind> ndf;
  std::optional<SmithForm> smith;
  std::optional<FresnelModel> fresnel;  // the Favg table's model
  std::optional<SheenVisibility> sheenVisibility;
  std::optional<SheenAlpha> sheenAlpha;

  int size = 0;     // texels per axis of every table; 0: each table's default
  int etaSize = 0;  // texels of a 3D table's eta axis; 0: its default
  SamplingRequest sampling;
  bool errorMaps = false;  // T.err.exr: the stored float32 values' bounds
  int threads = 0;         // 0: all cores; the files do not depend on it

  // C++ headers: namespace, value storage ("float", "half"); .bin storage
  // ("float", "double"). Unset: lutbake_luts, float, float.
  std::optional<std::string> headerNamespace;
  std::optional<std::string> headerType;
  std::optional<std::string> binType;
  // --format fit: the certified bound of the fits (unset: 4.9e-4).
  std::optional<double> fitTolerance;
  // Shader functions beside the tables: "glsl", "hlsl", "wgsl", "msl".
  std::vector<std::string> shaders;

  // A bake plan: glTF scenes and manifests (plan.h).
  std::vector<std::string> scenes;
  std::vector<std::string> manifests;
  bool noIbl = false;
  bool noCompensation = false;
  bool skipUnsupported = false;  // bake the plan although some features are not supported

  // An engine preset (ListPresets()), and optionally some of its files.
  std::string preset;
  std::optional<std::vector<std::string>> presetFiles;

  // Recorded in every file's metadata. Empty: the equivalent command line
  // (EquivalentCommandLine), so that a request and `lutbake bake` with the
  // same options write the same bytes.
  std::string commandLine;

  // Hooks. Polled between texels; once cancelled, Bake throws Cancelled.
  const CancellationToken *cancellation = nullptr;
  // Fraction done of the named table, from the bake's worker threads (one
  // call at a time is not guaranteed: the hook must be thread-safe).
  std::function<void(const std::string &table, double fraction)> progress;
  // Lines worth showing a person while the bake runs (estimates of large
  // requests, each table's summary as it finishes); never needed for the
  // result.
  std::function<void(const std::string &line)> note;
  // Each table's summary as soon as it is baked (BakeResult::tables holds
  // them all at the end).
  std::function<void(const BakedTable &table)> tableDone;
};

struct BakeResult {
  std::vector<WrittenFile> files;
  std::vector<BakedTable> tables;
  std::string outputDirectory;
  int threads = 0;
  double tolerance = 0.0;  // the request's, 0 if none
  double seconds = 0.0;
  // The directory holds one lutbake set (lutbake-set.json lists it): the
  // previous set's files this one does not write were removed
  // (removedFiles); files no lutbake set lists were left as they were
  // (foreignFiles). Names, not paths.
  std::vector<std::string> removedFiles;
  std::vector<std::string> foreignFiles;
  // The preset's description (preset.json's content) for a preset bake.
  std::string presetJson;
  // A plan that needed no table: nothing was written, nothing created
  // (nothingToBake: why each table was left out, "name: reason").
  bool planNeedsNothing = false;
  std::vector<std::string> nothingToBake;
  // The summary the command line prints with --json: one JSON object (for
  // a preset, preset.json's content and the time taken).
  std::string json;
};

BakeResult Bake(const BakeRequest &request);

// What the command line prints as a table finishes: one line, in columns
// (name, size, how it was integrated, seconds, the stored bounds), e.g.
//   "E             32 x 32         quadrature               0.040 s  error max
//    3.87e-08  rms 1.90e-08  (float32 as stored; integration 8.9e-09)"
// A sampled table says its estimator and samples per texel; a preset's
// texture its channels and storage; a closed form what it replaced.
std::string TableSummaryLine(const BakedTable &table);

// The end of a bake's output: with a tolerance, that it was reached; then
// the files written, "wrote 12 files to out: E.exr, E.bin, ..." (`perFile`:
// a line each, with its format and the bounds it states), plus, on their own
// lines, the previous set's files removed and the foreign files left alone.
std::string WrittenFilesText(const BakeResult &result, bool perFile = false);

// The `lutbake bake` command line that asks for what `request` asks:
// "lutbake bake --out DIR --tables E,dfg --format exr,header ...", options
// in the order of `lutbake bake --help`, only those set.
std::string EquivalentCommandLine(const BakeRequest &request);

// "" when `name` can name the generated headers' namespace (identifiers
// separated by "::", none a C++ keyword), else why not, quoting it.
std::string NamespaceProblem(const std::string &name);

}  // namespace lutbake
