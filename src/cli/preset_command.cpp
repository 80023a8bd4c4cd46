#include "preset_command.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "cli_util.h"
#include "interrupt.h"
#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/storage.h"

namespace lutbake::cli {

std::vector<std::string> PresetNames() {
  std::vector<std::string> names;
  for (const Preset *preset : AllPresets()) names.push_back(preset->name);
  return names;
}

namespace {

// Whether `file` is one of the preset's files.
bool IsFileOf(const Preset &preset, const std::string &file) {
  return std::any_of(preset.textures.begin(), preset.textures.end(),
                     [&](const PresetTexture &t) { return t.file == file; });
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

}  // namespace

int RunPresetBake(const BakeOptions &o, const std::string &commandLine, CLI::App &app) {
  // A preset fixes the tables, models, sizes, storage and formats.
  for (const char *flag :
       {"--tables",          "--format",           "--ndf",         "--smith",
        "--fresnel",         "--sheen-visibility", "--sheen-alpha", "--size",
        "--eta-size",        "--estimator",        "--samples",     "--replicates",
        "--tolerance",       "--sampling-only",    "--max-samples", "--seed",
        "--error-map",       "--namespace",        "--header-type", "--bin-type",
        "--scene",           "--manifest",         "--no-ibl",      "--no-compensation",
        "--skip-unsupported"})
    if (app.count(flag) > 0) {
      std::cerr << "lutbake bake: " << flag << " cannot be combined with --preset " << o.preset
                << ": the preset fixes the tables, models, sizes and formats (accepted with "
                   "--preset: --out, --threads, --json, --files)\n";
      return 2;
    }
  const Preset *preset = FindPreset(o.preset);
  if (!preset) {  // the option's validator already refused it
    std::cerr << "lutbake bake: --preset " << o.preset << ": accepted: " << PresetNameList()
              << "\n";
    return 2;
  }
  // --files: a subset of the preset's files, in the preset's order.
  std::vector<const PresetTexture *> textures;
  if (app.count("--files") > 0) {
    const std::vector<std::string> wanted = SplitList(o.presetFiles);
    std::string accepted;
    for (const PresetTexture &t : preset->textures)
      accepted += (accepted.empty() ? "" : ", ") + t.file;
    if (wanted.empty() || std::find(wanted.begin(), wanted.end(), "") != wanted.end()) {
      std::cerr << "lutbake bake: --files '" << o.presetFiles
                << "' is empty or has an empty name; the files of --preset " << preset->name << ": "
                << accepted << "\n";
      return 2;
    }
    for (size_t k = 0; k < wanted.size(); ++k) {
      const std::string &file = wanted[k];
      if (!IsFileOf(*preset, file)) {
        std::cerr << "lutbake bake: --files: " << file << " is not a file of --preset "
                  << preset->name << "; accepted: " << accepted << "\n";
        return 2;
      }
      if (std::find(wanted.begin(), wanted.begin() + k, file) != wanted.begin() + k) {
        std::cerr << "lutbake bake: --files '" << o.presetFiles << "' names " << file
                  << " twice; the files of --preset " << preset->name << ": " << accepted << "\n";
        return 2;
      }
    }
    for (const PresetTexture &t : preset->textures)
      if (std::find(wanted.begin(), wanted.end(), t.file) != wanted.end()) textures.push_back(&t);
  } else {
    for (const PresetTexture &t : preset->textures) textures.push_back(&t);
  }
  bool created = false;
  if (const int status = PrepareOutputOrComplain("bake", o.outDir, &created)) return status;
  RemoveStaleTemporaries(o.outDir);
  const int threads = ThreadCount(o.threads);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(threads));
  const InterruptGuard interrupt;
  const auto start = std::chrono::steady_clock::now();

  nlohmann::ordered_json manifest;
  manifest["preset"] = preset->name;
  manifest["engine"] = preset->engine;
  manifest["summary"] = preset->summary;
  manifest["lutbakeVersion"] = LutbakeVersion();
  manifest["commandLine"] = commandLine;
  manifest["files"] = nlohmann::ordered_json::array();
  try {
    AtomicOutputSet output;
    const WriteOptions writeOptions;
    for (const PresetTexture *each : textures) {
      const PresetTexture &texture = *each;
      const auto textureStart = std::chrono::steady_clock::now();
      Table table = BakePresetTexture(texture, preset->name, &interrupt.token());
      table.metadata.emplace_back("lutbakeVersion", LutbakeVersion());
      table.metadata.emplace_back("commandLine", commandLine);
      const std::unique_ptr<TableWriter> writer = MakeWriter(texture.format);
      if (!writer) throw IoError(texture.file + ": no writer for format " + texture.format);
      const std::string path = (std::filesystem::path(o.outDir) / texture.file).string();
      interrupt.token().ThrowIfCancelled();
      output.Write(path, [&](const std::string &temporary) {
        writer->Write(table, temporary, writeOptions);
      });
      const ValueType storage = PresetStorage(texture);
      const BoundSummary bounds = SummarizeStoredBounds(table, storage);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - textureStart).count();

      nlohmann::ordered_json f;
      f["file"] = texture.file;
      f["format"] = texture.format;
      f["storage"] = ToString(storage);
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
      nlohmann::ordered_json model;
      model["ndf"] = "ggx";
      model["visibility"] = ToString(texture.model.visibility);
      model["alpha"] = ToString(texture.model.alpha);
      if (texture.model.alphaMin > 0.0) model["alphaMin"] = texture.model.alphaMin;
      if (texture.model.unitEtaWindow > 0.0) model["unitEtaWindow"] = texture.model.unitEtaWindow;
      for (const PresetChannel &c : texture.channels)
        if (c.meaning == "sheen_E") {
          model["sheenVisibility"] = ToString(texture.model.sheenVisibility);
          model["sheenAlpha"] = ToString(texture.model.sheenAlpha);
          break;
        }
      f["model"] = model;
      f["errorMax"] = bounds.max;
      f["errorRms"] = bounds.rms;
      f["integrationErrorMax"] = table.MaxError();
      f["sampling"] = texture.sampling;
      f["source"] = texture.source;
      if (!texture.notes.empty()) f["notes"] = texture.notes;
      manifest["files"].push_back(f);

      char line[300];
      const std::string size = std::to_string(table.width()) + " x " +
                               std::to_string(table.height()) +
                               (table.is3D() ? " x " + std::to_string(table.depth()) : "");
      std::snprintf(line, sizeof line,
                    "%-28s %-13s %d channel(s) %-8s %7.3f s  error max %.2e (as stored)\n",
                    texture.file.c_str(), size.c_str(), table.channels, ToString(storage), seconds,
                    bounds.max);
      std::cerr << line;
    }
    const std::string path = (std::filesystem::path(o.outDir) / "preset.json").string();
    output.Write(path, [&](const std::string &temporary) {
      const std::string text = manifest.dump(2) + "\n";
      std::FILE *file = std::fopen(temporary.c_str(), "wb");
      if (!file) throw IoError(path + ": cannot write: " + std::strerror(errno));
      const bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
      if (std::fclose(file) != 0 || !ok)
        throw IoError(path + ": cannot write: " + std::strerror(errno));
    });
    interrupt.token().ThrowIfCancelled();
    output.Commit();
  } catch (const Cancelled &c) {
    RemoveCreatedDirectory(o.outDir, created);
    std::cerr << "lutbake bake: interrupted by " << SignalName(c.reason())
              << "; nothing written to " << o.outDir << "\n";
    return 128 + c.reason();
  } catch (const IoError &e) {
    std::cerr << "lutbake bake: " << e.what() << "\n";
    RemoveCreatedDirectory(o.outDir, created);
    return 1;
  }
  manifest["seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.json) std::cout << manifest.dump(2) << "\n";
  return 0;
}

namespace {

// The reader of a preset's file, by its format.
Table ReadPresetFile(const std::string &format, const std::string &path) {
  if (format == "exr") return ReadExrTable(path);
  if (format == "png8" || format == "png16") return ReadPngTable(path);
  if (format == "ktx2" || format == "ktx2-half") return ReadKtx2Table(path);
  if (format == "dds" || format == "dds-half") return ReadDdsTable(path);
  return ReadSourceTable(path);  // inc, js, c-array, threejs-dfg, ...
}

}  // namespace

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

int CheckPresetDirectory(const std::string &dir, bool json) {
  const std::string manifestPath = (std::filesystem::path(dir) / "preset.json").string();
  PresetListing listing;
  try {
    listing = ReadPresetListing(manifestPath);
  } catch (const IoError &e) {
    // The directory was given right; the file in it cannot be used.
    std::cerr << "lutbake check: " << e.what() << "\n";
    return 1;
  }
  const Preset *preset = listing.preset;
  nlohmann::ordered_json report;
  report["preset"] = preset->name;
  report["files"] = nlohmann::ordered_json::array();
  bool allPass = true;
  for (const PresetTexture &texture : preset->textures) {
    const auto listed = listing.errorMaxByFile.find(texture.file);
    if (listed == listing.errorMaxByFile.end()) continue;  // not baked (--files)
    nlohmann::ordered_json entry;
    entry["file"] = texture.file;
    std::string problem;
    double worst = 0.0, errorMax = 0.0;
    try {
      errorMax = listed->second;
      const Table stored =
          ReadPresetFile(texture.format, (std::filesystem::path(dir) / texture.file).string());
      const Table exact = BakePresetTexture(texture, preset->name);
      if (stored.width() != exact.width() ||
          stored.height() * stored.depth() != exact.height() * exact.depth() ||
          stored.values.size() != exact.values.size())
        throw IoError("holds " + std::to_string(stored.width()) + " x " +
                      std::to_string(stored.height() * stored.depth()) + " x " +
                      std::to_string(stored.channels) + " values; the preset has " +
                      std::to_string(exact.width()) + " x " +
                      std::to_string(exact.height() * exact.depth()) + " x " +
                      std::to_string(exact.channels));
      // PNG and KTX2 keep two channels as RGB / RG: compare the ones both hold.
      for (size_t i = 0; i < exact.values.size(); ++i) {
        const double d = std::abs(stored.values[i] - exact.values[i]);
        worst = std::max(worst, d);
        if (!(d <= errorMax + exact.errors[i])) {
          char text[200];
          std::snprintf(text, sizeof text,
                        "value %zu is %.9g, the integral %.9g: %.3g apart, more than errorMax "
                        "%.3g + %.3g",
                        i, stored.values[i], exact.values[i], d, errorMax, exact.errors[i]);
          throw IoError(text);
        }
      }
    } catch (const std::exception &e) {
      problem = e.what();
    }
    entry["pass"] = problem.empty();
    entry["worst"] = worst;
    entry["errorMax"] = errorMax;
    if (!problem.empty()) entry["problem"] = problem;
    allPass = allPass && problem.empty();
    if (!json) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "%-4s %-40s max |stored - integral| %.2e (errorMax %.2e)%s%s\n",
                    problem.empty() ? "pass" : "FAIL", texture.file.c_str(), worst, errorMax,
                    problem.empty() ? "" : ": ", problem.c_str());
      std::cout << line;
    }
    report["files"].push_back(entry);
  }
  report["pass"] = allPass;
  if (json) std::cout << report.dump(2) << "\n";
  return allPass ? 0 : 1;
}

void SetupPresetsCommand(CLI::App &app, bool &json) {
  app.add_flag("--json", json, "Print the presets as one JSON object");
  app.footer("Example:\n  lutbake presets\n  lutbake bake --preset filament --out dfg");
}

int RunPresets(bool json) {
  if (json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const Preset *preset : AllPresets()) {
      nlohmann::ordered_json p;
      p["name"] = preset->name;
      p["engine"] = preset->engine;
      p["summary"] = preset->summary;
      nlohmann::ordered_json files = nlohmann::ordered_json::array();
      for (const PresetTexture &t : preset->textures) files.push_back(t.file);
      p["files"] = files;
      list.push_back(p);
    }
    std::cout << nlohmann::ordered_json({{"presets", list}}).dump(2) << "\n";
    return 0;
  }
  for (const Preset *preset : AllPresets()) {
    std::printf("%-22s %s\n", preset->name.c_str(), preset->summary.c_str());
  }
  return 0;
}

}  // namespace lutbake::cli
