// The preset path of lutbake::Bake (bake.h): a job per texture for the
// loop tables run too (bake_jobs.h), and preset.json; and checking what it
// wrote.
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bake_internal.h"
#include "bake_jobs.h"
#include "lutbake/api/names.h"
#include "lutbake/api/presets.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/output_transaction.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

// Whether `file` is one of the preset's files.
bool IsFileOf(const Preset &preset, const std::string &file) {
  return std::any_of(preset.textures.begin(), preset.textures.end(),
                     [&](const PresetTexture &t) { return t.file == file; });
}

// A preset fixes the tables, models, sizes, storage and formats: the
// request's options that choose them, as the command line spells them.
void RefuseFixedOptions(const BakeRequest &r) {
  const SamplingRequest &s = r.sampling;
  const std::pair<const char *, bool> fixed[] = {
      {"--tables", r.tables.has_value()},
      {"--format", r.formats.has_value()},
      {"--ndf", r.ndf.has_value()},
      {"--smith", r.smith.has_value()},
      {"--fresnel", r.fresnel.has_value()},
      {"--sheen-visibility", r.sheenVisibility.has_value()},
      {"--sheen-alpha", r.sheenAlpha.has_value()},
      {"--size", r.size > 0},
      {"--eta-size", r.etaSize > 0},
      {"--estimator", s.estimator.has_value()},
      {"--samples", s.samples > 0},
      {"--replicates", s.replicates > 0},
      {"--tolerance", s.tolerance > 0.0},
      {"--sampling-only", s.samplingOnly},
      {"--max-samples", s.maxSamples.has_value()},
      {"--seed", s.seed.has_value()},
      {"--error-map", r.errorMaps},
      {"--namespace", r.headerNamespace.has_value()},
      {"--header-type", r.headerType.has_value()},
      {"--bin-type", r.binType.has_value()},
      {"--scene", !r.scenes.empty()},
      {"--manifest", !r.manifests.empty()},
      {"--no-ibl", r.noIbl},
      {"--no-compensation", r.noCompensation},
      {"--skip-unsupported", r.skipUnsupported},
      {"--shader", !r.shaders.empty()}};
  for (const auto &[flag, given] : fixed)
    if (given)
      throw UsageError(std::string(flag) + " cannot be combined with --preset " + r.preset +
                       ": the preset fixes the tables, models, sizes and formats (accepted with "
                       "--preset: --out, --threads, --json, --files)");
}

// --files: a subset of the preset's files, in the preset's order.
std::vector<const PresetTexture *> ChosenTextures(const BakeRequest &r, const Preset &preset) {
  std::vector<const PresetTexture *> textures;
  if (!r.presetFiles) {
    for (const PresetTexture &t : preset.textures) textures.push_back(&t);
    return textures;
  }
  const std::vector<std::string> &wanted = *r.presetFiles;
  std::string accepted;
  for (const PresetTexture &t : preset.textures)
    accepted += (accepted.empty() ? "" : ", ") + t.file;
  const std::string given = JoinList(wanted);
  if (wanted.empty() || std::find(wanted.begin(), wanted.end(), "") != wanted.end())
    throw UsageError("--files '" + given +
                     "' is empty or has an empty name; the files of --preset " + preset.name +
                     ": " + accepted);
  for (size_t k = 0; k < wanted.size(); ++k) {
    const std::string &file = wanted[k];
    if (!IsFileOf(preset, file))
      throw UsageError("--files: " + file + " is not a file of --preset " + preset.name +
                       "; accepted: " + accepted);
    if (std::find(wanted.begin(), wanted.begin() + k, file) != wanted.begin() + k)
      throw UsageError("--files '" + given + "' names " + file + " twice; the files of --preset " +
                       preset.name + ": " + accepted);
  }
  for (const PresetTexture &t : preset.textures)
    if (std::find(wanted.begin(), wanted.end(), t.file) != wanted.end()) textures.push_back(&t);
  return textures;
}

// What preset.json says of one axis.
nlohmann::ordered_json AxisJson(const PresetAxis &axis, const char *which) {
  nlohmann::ordered_json j;
  j["axis"] = which;
  j["quantity"] = axis.quantity;
  j["mapping"] = std::string(axis.quantity) + " = " + ToString(axis.mapping);
  j["placement"] = ToString(axis.placement);
  j["texelCoordinate"] =
      axis.placement == TexelPlacement::kCentres ? "u = (i + 0.5) / N" : "u = i / (N - 1)";
  j["texels"] = axis.count;
  j["firstTexel"] = axis.reversed ? "u = 1" : "u = 0";
  if (axis.lowest != 0.0 || axis.highest != 1.0)
    j["clamp"] = nlohmann::ordered_json::array({axis.lowest, axis.highest});
  return j;
}

nlohmann::ordered_json ModelJson(const PresetTexture &texture) {
  nlohmann::ordered_json model;
  model["ndf"] = "ggx";
  model["visibility"] = DescribeVisibility(texture.model);
  model["alpha"] = DescribeAlpha(texture.model.alpha);
  if (texture.model.alphaMin > 0.0) model["alphaMin"] = texture.model.alphaMin;
  if (texture.model.unitEtaWindow > 0.0) model["unitEtaWindow"] = texture.model.unitEtaWindow;
  for (const PresetChannel &c : texture.channels)
    if (const PresetChannelSource source = SourceOf(c); source.fitted) {
      // The lobe of the fitted table, and the entry of M^-1 that is 1.
      model["ltcLobe"] = source.lobe;
      model["ltcScale"] =
          (c.over.empty() ? "m11" : SourceOf({c.over, c.table}).channel) + std::string(" = 1");
      break;
    }
  for (const PresetChannel &c : texture.channels)
    if (c.meaning == "sheen_E") {
      model["sheenVisibility"] = ToString(texture.model.sheenVisibility);
      model["sheenAlpha"] = DescribeAlpha(texture.model.sheenAlpha);
      if (texture.model.sheenAlphaMin > 0.0) model["sheenAlphaMin"] = texture.model.sheenAlphaMin;
      break;
    }
  return model;
}

// preset.json's entry of one written texture (`baked`: its summary, which
// states its file's storage and bounds).
nlohmann::ordered_json FileJson(const PresetTexture &texture, const Table &table,
                                const BakedTable &baked) {
  nlohmann::ordered_json f;
  f["file"] = texture.file;
  f["format"] = texture.format;
  f["storage"] = baked.storage;
  f["width"] = table.width();
  f["height"] = table.height();
  if (table.is3D()) f["depth"] = table.depth();
  f["channelCount"] = table.channels;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  static const char *const kWhich[] = {"x", "y", "z"};
  for (size_t a = 0; a < texture.axes.size(); ++a)
    axes.push_back(AxisJson(texture.axes[a], kWhich[a]));
  f["axes"] = axes;
  f["memoryOrder"] = table.is3D()   ? "rows of x, then y, slices of z outermost; channels "
                                      "interleaved"
                     : table.is2D() ? "rows of x, y outer; channels interleaved"
                                    : "x; channels interleaved";
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (size_t c = 0; c < texture.channels.size(); ++c) {
    nlohmann::ordered_json ch;
    ch["channel"] = table.channelNames[c];
    ch["meaning"] = texture.channels[c].meaning;
    if (texture.channels[c].scale != 1.0) ch["scale"] = texture.channels[c].scale;
    if (texture.channels[c].offset != 0.0) ch["offset"] = texture.channels[c].offset;
    channels.push_back(ch);
  }
  f["channels"] = channels;
  f["model"] = ModelJson(texture);
  f["errorMax"] = baked.errorMax;
  f["errorRms"] = baked.errorRms;
  f["integrationErrorMax"] = table.MaxError();
  f["sampling"] = texture.sampling;
  f["source"] = texture.source;
  if (!texture.notes.empty()) f["notes"] = texture.notes;
  return f;
}

const TableFormat &FormatOf(const PresetTexture &texture) {
  const TableFormat *format = FindFormat(texture.format);
  if (!format) throw IoError(texture.file + ": no writer for format " + texture.format);
  return *format;
}

// The bake loop's job (bake_jobs.h) of one texture: BakePresetTexture,
// timed, in its one file and format, its entry appended to the files of
// preset.json (`manifest`) once written.
BakeJob TextureJob(const PresetTexture &texture, const Preset &preset, const BakeRequest &r,
                   nlohmann::ordered_json *manifest) {
  BakeJob job;
  job.name = texture.file;
  job.make = [&texture, &preset, &r](const ProgressFn &progress, BakeStats *stats) {
    const auto start = std::chrono::steady_clock::now();
    Table table = BakePresetTexture(texture, preset.name, r.cancellation, progress);
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return table;
  };
  job.files = {{texture.file, &FormatOf(texture)}};
  job.metadata = {{"lutbakeVersion", LutbakeVersion()}, {"commandLine", r.commandLine}};
  job.summaryOfItsFile = true;
  job.written = [&texture, manifest](const Table &table, const BakedTable &baked) {
    (*manifest)["files"].push_back(FileJson(texture, table, baked));
  };
  return job;
}

}  // namespace

BakeResult BakePreset(const BakeRequest &r) {
  RefuseFixedOptions(r);
  const Preset *preset = FindPreset(r.preset);
  if (!preset) throw UsageError("--preset " + r.preset + ": accepted: " + PresetNameList());
  nlohmann::ordered_json manifest;
  manifest["preset"] = preset->name;
  manifest["engine"] = preset->engine;
  manifest["summary"] = preset->summary;
  manifest["lutbakeVersion"] = LutbakeVersion();
  manifest["commandLine"] = r.commandLine;
  manifest["files"] = nlohmann::ordered_json::array();
  std::vector<BakeJob> jobs;
  for (const PresetTexture *texture : ChosenTextures(r, *preset))
    jobs.push_back(TextureJob(*texture, *preset, r, &manifest));
  OutputTransaction output(r.outputDirectory, "--out", OutputMode::kSet, r.commandLine);
  BakeResult result;
  result.outputDirectory = r.outputDirectory;
  result.threads = ThreadCount(r.threads);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(result.threads));
  const auto start = std::chrono::steady_clock::now();
  RunBakeJobs(jobs, r, WriteOptions(), output, &result);
  const std::string path = output.WriteText("preset.json", manifest.dump(2) + "\n");
  result.files.push_back({path, "", "json", 0.0, 0.0});
  CommitBake(output, r, start, &result);
  manifest["seconds"] = result.seconds;
  result.presetJson = manifest.dump(2);
  result.json = result.presetJson;
  return result;
}

void ValidateTableNames(const BakeRequest &r) {
  if (!r.tables) return;
  const std::vector<std::string> names = TableNames();
  for (size_t i = 0; i < r.tables->size(); ++i) {
    const std::string &name = (*r.tables)[i];
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw UsageError((r.tables->size() == 1 ? "--tables '" + name + "' is not accepted"
                                              : "--tables '" + JoinList(*r.tables) + "' names '" +
                                                    name + "', which is not accepted") +
                       "; accepted: a comma-separated subset of " + JoinNames(names));
    if (std::find(r.tables->begin(), r.tables->begin() + i, name) != r.tables->begin() + i)
      throw UsageError("--tables '" + JoinList(*r.tables) + "' names '" + name + "' twice");
  }
}

std::string PresetListText(bool estimate) {
  std::string text;
  for (const Preset *preset : AllPresets()) {
    char name[32];
    std::snprintf(name, sizeof name, "%-22s ", preset->name.c_str());
    text += name + preset->summary + "\n";
    if (estimate)
      text +=
          std::string(23, ' ') + "bake: " + DescribeEstimate(EstimatePresetBake(*preset)) + "\n";
  }
  return text;
}

std::string PresetListJson(bool estimate) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Preset *preset : AllPresets()) {
    nlohmann::ordered_json p;
    p["name"] = preset->name;
    p["engine"] = preset->engine;
    p["summary"] = preset->summary;
    nlohmann::ordered_json files = nlohmann::ordered_json::array();
    for (const PresetTexture &t : preset->textures) files.push_back(t.file);
    p["files"] = files;
    if (estimate) {
      const BakeEstimate e = EstimatePresetBake(*preset);
      p["estimate"] = {{"seconds", e.seconds},
                       {"cpuSeconds", e.cpuSeconds},
                       {"threads", e.threads},
                       {"texels", e.texels},
                       {"timedTexels", e.timedTexels}};
    }
    list.push_back(p);
  }
  return nlohmann::ordered_json({{"presets", list}}).dump(2);
}

PresetListing ReadPresetListing(const std::string &manifestPath) {
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t{16} << 20;
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(manifestPath, error);
  if (error) throw IoError(manifestPath + ": cannot read (" + error.message() + ")");
  if (bytes > kMaxBytes)
    throw IoError(manifestPath + ": " + std::to_string(bytes) +
                  " bytes; a preset.json is accepted up to 16 MiB");
  nlohmann::json manifest;
  try {
    std::ifstream in(manifestPath, std::ios::binary);
    if (!in) throw IoError("cannot open");
    manifest = nlohmann::json::parse(in);
  } catch (const std::exception &e) {
    throw IoError(manifestPath + ": not JSON (" + e.what() + ")");
  }
  PresetListing listing;
  if (manifest.is_object() && manifest.contains("preset") && manifest["preset"].is_string())
    listing.preset = FindPreset(manifest["preset"].get<std::string>());
  if (!listing.preset || !manifest.contains("files") || !manifest["files"].is_array())
    throw IoError(manifestPath + ": 'preset' must name one of " + PresetNameList() +
                  " and 'files' list its files");
  for (const nlohmann::json &f : manifest["files"]) {
    if (!f.is_object() || !f.contains("file") || !f["file"].is_string() ||
        !f.contains("errorMax") || !f["errorMax"].is_number())
      throw IoError(manifestPath +
                    ": every entry of 'files' must be an object with a string 'file' and a "
                    "number 'errorMax'");
    const double errorMax = f["errorMax"].get<double>();
    if (!(errorMax >= 0.0 && errorMax <= 1.0))
      throw IoError(manifestPath + ": errorMax of " + f["file"].get<std::string>() +
                    " is not in [0, 1]");
    // preset.json lists what the bake wrote: every file of the preset, or
    // those --files chose.
    const std::string file = f["file"].get<std::string>();
    if (!IsFileOf(*listing.preset, file))
      throw IoError(manifestPath + " lists " + file + ", which is not a file of preset " +
                    listing.preset->name);
    listing.errorMaxByFile[file] = errorMax;
  }
  if (listing.errorMaxByFile.empty()) throw IoError(manifestPath + " lists no file");
  return listing;
}

namespace {

// Holds one stored file to the preset's texels integrated again; throws
// IoError saying why it fails.
void HoldToIntegral(const std::string &dir, const PresetTexture &texture, const std::string &preset,
                    PresetFileCheck *check) {
  const TableFormat &format = FormatOf(texture);
  const Table stored = format.read((std::filesystem::path(dir) / texture.file).string());
  const Table exact = BakePresetTexture(texture, preset);
  if (stored.width() != exact.width() ||
      stored.height() * stored.depth() != exact.height() * exact.depth() ||
      stored.values.size() != exact.values.size())
    throw IoError(
        "holds " + std::to_string(stored.width()) + " x " +
        std::to_string(stored.height() * stored.depth()) + " x " + std::to_string(stored.channels) +
        " values; the preset has " + std::to_string(exact.width()) + " x " +
        std::to_string(exact.height() * exact.depth()) + " x " + std::to_string(exact.channels));
  // PNG and KTX2 keep two channels as RGB / RG: compare the ones both hold.
  for (size_t i = 0; i < exact.values.size(); ++i) {
    const double d = std::abs(stored.values[i] - exact.values[i]);
    check->worst = std::max(check->worst, d);
    if (!(d <= check->errorMax + exact.errors[i])) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "value %zu is %.9g, the integral %.9g: %.3g apart, more than errorMax "
                    "%.3g + %.3g",
                    i, stored.values[i], exact.values[i], d, check->errorMax, exact.errors[i]);
      throw IoError(text);
    }
  }
}

}  // namespace

PresetCheck CheckPresetDirectory(const std::string &dir) {
  const PresetListing listing =
      ReadPresetListing((std::filesystem::path(dir) / "preset.json").string());
  PresetCheck result;
  result.preset = listing.preset->name;
  result.pass = true;
  nlohmann::ordered_json report;
  report["preset"] = result.preset;
  report["files"] = nlohmann::ordered_json::array();
  for (const PresetTexture &texture : listing.preset->textures) {
    const auto listed = listing.errorMaxByFile.find(texture.file);
    if (listed == listing.errorMaxByFile.end()) continue;  // not baked (--files)
    PresetFileCheck check;
    check.file = texture.file;
    check.errorMax = listed->second;
    try {
      HoldToIntegral(dir, texture, result.preset, &check);
    } catch (const std::exception &e) {
      check.problem = e.what();
    }
    check.pass = check.problem.empty();
    result.pass = result.pass && check.pass;
    nlohmann::ordered_json entry;
    entry["file"] = check.file;
    entry["pass"] = check.pass;
    entry["worst"] = check.worst;
    entry["errorMax"] = check.errorMax;
    if (!check.pass) entry["problem"] = check.problem;
    report["files"].push_back(entry);
    result.files.push_back(check);
  }
  report["pass"] = result.pass;
  result.json = report.dump(2);
  return result;
}

}  // namespace lutbake
