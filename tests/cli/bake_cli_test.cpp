// The command line around the library's calls: what `lutbake bake`, `plan`,
// `check` and `presets` print and the exit status they return (0 done, 1
// failed, 2 refused), and that a refused run writes nothing. What they
// compute is tested through the library beside each part (tests/plans/,
// tests/presets/, tests/validation/); here only the executable's own
// behaviour, so the sets it runs on are baked with lutbake::Bake.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "lutbake/formats/binary_format.h"
#include "lutbake/lutbake.h"
#include "lutbake/presets/preset.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::Lutbake;

const std::string kPlans = std::string(LUTBAKE_TEST_DATA) + "/plans/";

// A small complete set (sampled E, dfg, Eavg; Schlick Favg) baked once
// (bake --size 8 --samples 4096 --error-map), as tests/validation/check_test.cpp.
const fs::path &GoodBake() {
  static const fs::path dir = [] {
    const fs::path d = test::Scratch("check_cli_good");
    BakeRequest request = test::BakeRequestFor(d);
    request.size = 8;
    request.sampling.samples = 4096;
    request.errorMaps = true;
    Bake(request);
    return d;
  }();
  return dir;
}

// Rewrites value `index` of a .bin file (float32 at the data offset).
void PatchBin(const fs::path &path, size_t index, float value) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  char offset[4];
  f.seekg(12);
  f.read(offset, 4);
  uint32_t dataOffset;
  std::memcpy(&dataOffset, offset, 4);
  f.seekp(dataOffset + 4 * static_cast<std::streamoff>(index));
  f.write(reinterpret_cast<const char *>(&value), 4);
}

TEST(Check, CommandLineExitsAndNamesTheFailure) {
  test::CommandResult run = Lutbake("check " + GoodBake().string() + " --points 16");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("all checks passed"), std::string::npos);
  run = Lutbake("check " + GoodBake().string() + " --points 16 --json", true);
  ASSERT_EQ(run.status, 0);
  const nlohmann::json j = nlohmann::json::parse(run.output);
  EXPECT_EQ(j["passed"], true);
  EXPECT_GE(j["checks"].size(), 20u);

  const fs::path d = test::Scratch("check_cli");
  fs::copy(GoodBake(), d, fs::copy_options::recursive);
  for (const char *f : {"E.exr", "E.h"}) fs::remove(d / f);
  const Table e = ReadBinaryTable((d / "E.bin").string());
  PatchBin(d / "E.bin", 0, static_cast<float>(e.values[0] * 0.9));
  run = Lutbake("check " + d.string() + " --points 16");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("FAILED: E texels"), std::string::npos) << run.output;

  run = Lutbake("check " + (d / "missing").string());
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("does not exist"), std::string::npos);
  const fs::path empty = test::Scratch("check_empty");
  fs::create_directories(empty);
  run = Lutbake("check " + empty.string());
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("no table files"), std::string::npos);
  fs::remove_all(d);
  fs::remove_all(empty);
}

TEST(Presets, CommandListsEveryPreset) {
  const auto listed = Lutbake("presets");
  EXPECT_EQ(listed.status, 0);
  for (const Preset *p : AllPresets()) EXPECT_NE(listed.output.find(p->name), std::string::npos);
}

TEST(Presets, OptionsAPresetFixesAreRefused) {
  const auto dir = test::Scratch("preset_refused");
  for (const char *extra : {"--tables dfg", "--format exr", "--size 64", "--smith separable"}) {
    const auto run =
        test::Lutbake("bake --preset godot --out " + dir.string() + " " + std::string(extra));
    EXPECT_EQ(run.status, 2) << extra;
    EXPECT_NE(run.output.find("cannot be combined with --preset"), std::string::npos) << extra;
  }
  const auto unknown = test::Lutbake("bake --preset unity --out " + dir.string());
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.output.find("unity-hdrp"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "preset.json"));
}

// A plan that needs nothing is not an error: the bake says so and creates
// nothing.
TEST(PlanCli, NothingNeededSaysSo) {
  const fs::path out = test::Scratch("plan_nothing_cli");
  const auto r = Lutbake("bake --out " + out.string() + " --scene " + kPlans + "unlit.gltf");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("needs no tables"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(PlanCli, BadInputExitsWithoutOutput) {
  const fs::path out = test::Scratch("plan_bad");
  const std::string bake = "bake --out " + out.string() + " ";
  struct Case {
    std::string args;
    int status;
    std::string says;
  };
  const Case cases[] = {
      {"--scene " + kPlans + "missing.gltf", 2, "--scene " + kPlans + "missing.gltf: no such file"},
      {"--manifest " + kPlans + "missing.json", 2, "no such file"},
      {"--scene " + kPlans + "bad_roughness.gltf", 1,
       "/materials/1/pbrMetallicRoughness/roughnessFactor: 7 is outside"},
      {"--scene " + kPlans + "malformed.gltf", 1, "malformed JSON: parse error at line 3"},
      {"--scene " + kPlans + "truncated.glb", 1, "truncated"},
      {"--scene " + kPlans + "not_gltf.json", 1, "not a glTF file"},
      {"--manifest " + kPlans + "bad_key.json", 1, "unknown key \"roughnes\""},
      {"--scene " + kPlans + "listed.gltf --ndf beckmann", 2, "--ndf cannot be combined"},
  };
  for (const Case &c : cases) {
    const auto r = Lutbake(bake + c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << c.args;
    const auto plan = Lutbake("plan " + c.args);
    if (c.args.find("--tables") == std::string::npos && c.args.find("--ndf") == std::string::npos) {
      EXPECT_EQ(plan.status, c.status) << c.args;
    }
  }
  EXPECT_EQ(Lutbake("plan").status, 2);
}

}  // namespace
}  // namespace lutbake
