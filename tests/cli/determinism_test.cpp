// Output does not depend on the thread count: every table of the registry
// in every format (T.exr, T.bin, T.h, with its error map T.err.exr; the
// textures and source embeddings; the shader functions), and the engine
// presets, baked with --threads 1, 2, 7 and 16, is byte for byte the same
// file. The tables are small (the 3D ones at 8 x 8 x 3, their averages at
// 2 x 3) so that the whole test takes seconds; what it checks, that sample
// i of texel t depends only on (t, i, seed), does not depend on the size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/output_transaction.h"
#include "lutbake/tables/table_definition.h"
#include "support/cli_run.h"

namespace {

namespace fs = std::filesystem;

using lutbake::test::CommandResult;
using lutbake::test::Lutbake;
using lutbake::test::Scratch;

std::string ReadFile(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// A PNG's tEXt chunks end with a CRC of their text, which holds the command
// line: once the command line is blanked, their CRCs are blanked too (the
// image data's chunks keep theirs).
void BlankTextChunkCrcs(std::string *png) {
  for (size_t at = 8; at + 12 <= png->size();) {
    const auto byte = [&](size_t i) {
      return static_cast<uint32_t>(static_cast<uint8_t>((*png)[i]));
    };
    const uint32_t length = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    const size_t crc = at + 8 + length;
    if (crc + 4 > png->size()) break;
    if (png->compare(at + 4, 4, "tEXt") == 0) png->replace(crc, 4, 4, '#');
    at = crc + 4;
  }
}

// The tables of the registry, comma-separated: the sampled ones only, or
// those `slow` names (left out) or only those.
std::string TableNames(bool sampledOnly, const std::vector<std::string> &slow = {},
                       bool onlySlow = false) {
  std::string names;
  for (const lutbake::TableDefinition *table : lutbake::AllTables()) {
    const bool isSlow = std::find(slow.begin(), slow.end(), table->Name()) != slow.end();
    if ((!sampledOnly || table->Sampled()) && isSlow == onlySlow)
      names += (names.empty() ? "" : ",") + std::string(table->Name());
  }
  return names;
}

// Bakes `options` into one directory per thread count and compares every
// file with the single-threaded run's, byte for byte. The files record the
// command line, which names the directory and the thread count: the thread
// counts are written with two digits and the directories' names have one
// length, so that blanking each run's own "--out DIR ... --threads NN"
// leaves files of the same length and layout. Returns the number of files
// compared.
int ExpectSameFilesForEveryThreadCount(const std::string &tag, const std::string &options) {
  const std::vector<std::string> threadCounts = {"01", "02", "07", "16"};
  std::vector<fs::path> dirs;
  std::vector<std::string> args;
  for (const std::string &threads : threadCounts) {
    dirs.push_back(Scratch("det_" + tag + "_t" + threads));
    args.push_back(dirs.back().string() + " " + options + " --threads " + threads);
    const CommandResult r = Lutbake("bake --out " + args.back());
    EXPECT_EQ(r.status, 0) << args.back() << "\n" << r.output;
    if (r.status != 0) return 0;
  }
  int compared = 0;
  for (const auto &entry : fs::directory_iterator(dirs[0])) {
    const std::string name = entry.path().filename().string();
    EXPECT_FALSE(lutbake::IsTemporaryName(name)) << "temporary left: " << name;
    std::vector<std::string> contents;
    for (size_t k = 0; k < dirs.size(); ++k) {
      EXPECT_TRUE(fs::exists(dirs[k] / name))
          << name << " missing with --threads " << threadCounts[k];
      std::string text = ReadFile(dirs[k] / name);
      const std::string &arg = args[k];
      for (size_t at = text.find(arg); at != std::string::npos; at = text.find(arg, at))
        text.replace(at, arg.size(), std::string(arg.size(), '#'));
      if (name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0)
        BlankTextChunkCrcs(&text);
      contents.push_back(text);
    }
    for (size_t k = 1; k < contents.size(); ++k)
      EXPECT_TRUE(contents[k] == contents[0])
          << name << " differs between --threads 01 and --threads " << threadCounts[k];
    // lutbake-set.json (the set's list, with the command line) is compared
    // like the others; the counts are of the tables' and helpers' files.
    if (name != lutbake::kSetManifestName) ++compared;
  }
  EXPECT_TRUE(fs::exists(dirs[0] / lutbake::kSetManifestName));
  for (size_t k = 1; k < dirs.size(); ++k)
    EXPECT_EQ(lutbake::test::FileNames(dirs[k]), lutbake::test::FileNames(dirs[0]));
  for (const fs::path &dir : dirs) fs::remove_all(dir);
  return compared;
}

constexpr const char *kEveryFormat = " --format exr,bin,header --error-map";

// The deterministic quadrature to a tolerance, every table: 13 tables x
// (exr, bin, h, err.exr) and kulla_conty.h. The 3D tables' averages
// integrate a 3D table per texel (seconds each at 1e-6): at --size 2.
TEST(Determinism, EveryTableEveryFormatQuadrature) {
  const std::vector<std::string> slow = {"glass_Eavg", "spec_Eavg"};
  const std::string options = " --eta-size 3 --tolerance 1e-6" + std::string(kEveryFormat);
  const int files =
      ExpectSameFilesForEveryThreadCount(
          "quad", "--tables " + TableNames(false, slow) + " --size 8" + options) +
      ExpectSameFilesForEveryThreadCount(
          "quadavg", "--tables " + TableNames(false, slow, true) + " --size 2" + options);
  // A fitted table (ltc_ggx) writes its fit maps, T.fit.exr, too.
  int fitMaps = 0;
  for (const lutbake::TableDefinition *table : lutbake::AllTables())
    fitMaps += table->FitMapNames().empty() ? 0 : 1;
  EXPECT_EQ(files, static_cast<int>(4 * lutbake::AllTables().size() + 1) + fitMaps);
}

// The sampled estimators, whose points are where a thread-dependent result
// would show first: scrambled Sobol (vndf), independent random points
// (vndf-random), and a tolerance run that doubles samples per texel.
TEST(Determinism, EveryTableEveryFormatSampled) {
  const std::string tables = "--tables " + TableNames(true);
  const int sampled = static_cast<int>(std::count(tables.begin(), tables.end(), ',')) + 1;
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount(
                "vndf", tables + " --size 8 --eta-size 3 --samples 64" + kEveryFormat),
            4 * sampled + 1);
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount(
                "rand", tables + " --size 4 --eta-size 3 --samples 64 --estimator vndf-random " +
                            "--format bin --bin-type double"),
            sampled);
  EXPECT_EQ(
      ExpectSameFilesForEveryThreadCount("tol",
                                         "--tables E,dfg --size 4 --tolerance 1e-4 --sampling-only "
                                         "--format bin --bin-type double"),
      2);
}

// Favg's other Fresnel models (their own axes) and the other storages.
TEST(Determinism, FresnelModelsAndStorages) {
  for (const char *fresnel : {"dielectric", "conductor", "f82"})
    EXPECT_EQ(
        ExpectSameFilesForEveryThreadCount(
            fresnel, std::string("--tables Favg --size 8 --fresnel ") + fresnel + kEveryFormat),
        4);
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount(
                "storage",
                "--tables E,Eavg,dfg --size 8 --ndf beckmann --smith separable "
                "--header-type half --bin-type double --format bin,header"),
            7);
}

// The texture and source formats and the shader functions: tables whose
// values lie in [0, 1] (PNG holds no others), one format per file name
// (png16, ktx2, dds, inc-half, js, ts-half and the four shader arrays) and
// --shader in every language: 8 tables x 10 files and lutbake.{glsl,hlsl,
// wgsl,metal}.
TEST(Determinism, TextureAndSourceFormatsAndShaders) {
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount(
                "tex",
                "--tables E,Eavg,Favg,dfg,glass_E,sheen_E,sheen_Eavg,f82 --size 8 --eta-size 3 "
                "--tolerance 1e-6 --format png16,ktx2,dds,inc-half,js,ts-half,glsl-array,"
                "hlsl-array,wgsl-array,msl-array --shader glsl,hlsl,wgsl,msl"),
            8 * 10 + 4);
}

// The engine presets that bake in about a second (every texture and
// preset.json): each engine's format, storage and model at full size. Of
// Cycles, the 2D tables and the 3D glass_E (its glass averages take
// minutes).
TEST(Determinism, EnginePresets) {
  for (const char *preset : {"unreal", "godot", "cycles", "eevee", "threejs", "filament-mobile",
                             "babylon", "ospray", "materialx"}) {
    std::string options = std::string("--preset ") + preset;
    if (options == "--preset cycles")
      options += " --files table_ggx_E.h,table_ggx_Eavg.h,table_ggx_glass_E.h";
    // Babylon's 128^2 OpenPBR texture (RGBD and DDS) and its fuzz texture.
    if (options == "--preset babylon")
      options +=
          " --files openPBREnvironmentBRDFTexture.png,environmentFuzzBRDFTexture.png,"
          "openPBREnvironmentBRDFTexture.dds";
    if (options == "--preset ospray")
      options += " --files MicrofacetAlbedoTable_dir.ih,MicrofacetAlbedoTable_avg.ih";
    EXPECT_GE(ExpectSameFilesForEveryThreadCount(std::string("preset_") + preset, options), 2)
        << preset;
  }
}

// A preset of LTC channels (fitted over its whole grid at once) and a
// geometry-only texture: EEVEE's three arrays and preset.json (the 64^2
// fit, about 7 s on 2 threads, 14 s on one).
TEST(Determinism, EeveeLtcPreset) {
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount("preset_eevee_ltc", "--preset eevee-ltc"), 4);
}

// Unity HDRP's LTC slices, as C# doubles printed to round-trip (every bit
// shows): one slice (the grid fit and the writer are the four's) and
// preset.json.
TEST(Determinism, UnityHdrpLtcPreset) {
  EXPECT_EQ(ExpectSameFilesForEveryThreadCount(
                "preset_unity_hdrp_ltc", "--preset unity-hdrp-ltc --files LtcData.BRDF_Disney.cs"),
            2);
}

}  // namespace
