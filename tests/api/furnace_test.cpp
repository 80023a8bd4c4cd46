// lutbake::Furnace: Lambert's albedo is 1, the files are written all at
// once through the output transaction, and the refusals name the option.
#include "lutbake/api/furnace.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "lutbake/core/error.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

std::string UsageMessage(const FurnaceRequest &request) {
  try {
    Furnace(request);
  } catch (const UsageError &e) {
    return e.what();
  }
  return "(no UsageError)";
}

TEST(FurnaceApi, LambertReflectsEverything) {
  FurnaceRequest request;
  request.model = "lambert";
  request.mus = "0,0.5,1";
  const FurnaceOutcome outcome = Furnace(request);
  ASSERT_EQ(outcome.result.albedo.size(), 3u);
  for (const FurnaceEntry &e : outcome.result.albedo)
    EXPECT_NEAR(e.point.albedo.value, 1.0, e.point.albedo.error + 1e-15);
  EXPECT_EQ(outcome.text.rfind("white furnace of lambert\n", 0), 0u) << outcome.text;
  EXPECT_TRUE(outcome.files.empty());
}

TEST(FurnaceApi, WritesTheFilesThroughOneTransaction) {
  const fs::path dir = test::Scratch("furnace_api_out");
  FurnaceRequest request;
  request.model = "microfacet";
  request.parameters = "0.5";
  request.mus = "0.5,1";
  request.f0 = "0.04";
  request.compensation = true;
  request.outputDirectory = dir.string();
  const FurnaceOutcome outcome = Furnace(request);
  EXPECT_EQ(
      test::FileNames(dir),
      (std::vector<std::string>{"furnace.csv", "furnace.json", "furnace_plot.png",
                                "furnace_plot.svg", "furnace_spheres.exr", "furnace_spheres.png"}));
  EXPECT_EQ(outcome.files.size(), 6u);
  std::ifstream in(dir / "furnace.json", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), outcome.json);
  fs::remove_all(dir);
}

TEST(FurnaceApi, RefusesWhatTheModelDoesNotTake) {
  FurnaceRequest request;
  request.model = "lambert";
  request.ndf = "ggx";
  EXPECT_EQ(UsageMessage(request),
            "--ndf does not apply to --model lambert; it applies only to --model microfacet");
  request.ndf.reset();
  request.parameters = "1";
  EXPECT_EQ(UsageMessage(request), "--parameter does not apply to --model lambert (it has none)");
  request.model = "microfacet";
  request.f0 = "1.5";
  EXPECT_EQ(UsageMessage(request), "--f0 '1.5': accepted: one number in [0, 1]");
  request.f0 = "0.5";
  request.eta = "1.5";
  EXPECT_EQ(UsageMessage(request), "--f0 (Schlick) and --eta (exact Fresnel) exclude each other");
  request.f0.reset();
  request.eta.reset();
  request.mus = "0.5,2";
  EXPECT_EQ(UsageMessage(request),
            "--mu: '2' is out of range; accepted: view cosines in [0, 1], comma-separated");
  request.mus = "";
  const fs::path file = test::Scratch("furnace_api_file");
  std::ofstream(file) << "x";
  request.outputDirectory = file.string();
  EXPECT_EQ(UsageMessage(request).rfind("--out " + file.string() + ": exists and is not a", 0), 0u);
  fs::remove(file);
}

}  // namespace
}  // namespace lutbake
