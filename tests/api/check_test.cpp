// lutbake::Check: a fresh bake passes and says so, a directory that is not
// there or not a directory is a UsageError, a preset's directory is checked
// as one.
#include "lutbake/api/check.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "lutbake/api/bake.h"
#include "lutbake/core/error.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

std::string UsageMessage(const CheckRequest &request) {
  try {
    Check(request);
  } catch (const UsageError &e) {
    return e.what();
  }
  return "(no UsageError)";
}

TEST(CheckApi, AFreshBakePasses) {
  const fs::path dir = test::Scratch("check_api_bake");
  BakeRequest bake;
  bake.tables = {"E", "Eavg"};
  bake.formats = {"exr", "bin"};
  bake.size = 8;
  bake.outputDirectory = dir.string();
  Bake(bake);
  CheckRequest request;
  request.dir = dir.string();
  request.points = 16;
  request.furnaceGrid = 9;
  int progressCalls = 0;
  request.progress = [&](double fraction) {
    EXPECT_TRUE(fraction >= 0.0 && fraction <= 1.0);
    ++progressCalls;
  };
  const CheckOutcome outcome = Check(request);
  EXPECT_FALSE(outcome.isPreset);
  EXPECT_TRUE(outcome.passed) << outcome.text << outcome.failureText;
  EXPECT_TRUE(outcome.failed.empty());
  EXPECT_GT(progressCalls, 0);
  EXPECT_GT(outcome.report.results.size(), 5u);
  const std::string last = "all checks passed\n";
  ASSERT_GE(outcome.text.size(), last.size());
  EXPECT_EQ(outcome.text.substr(outcome.text.size() - last.size()), last);
  const nlohmann::json json = nlohmann::json::parse(outcome.json);
  EXPECT_EQ(json["passed"], true);
  EXPECT_EQ(json["checks"].size(), outcome.report.results.size());
  fs::remove_all(dir);
}

TEST(CheckApi, RefusesWhatIsNotADirectory) {
  CheckRequest request;
  request.dir = test::Scratch("check_api_missing").string();
  EXPECT_EQ(UsageMessage(request),
            request.dir + " does not exist; accepted: the directory of a bake");
  std::ofstream(request.dir) << "not a directory";
  EXPECT_EQ(UsageMessage(request),
            request.dir + " is not a directory; accepted: the directory of a bake");
  fs::remove(request.dir);
}

TEST(CheckApi, APresetDirectoryIsCheckedAsOne) {
  const fs::path dir = test::Scratch("check_api_preset");
  fs::create_directories(dir);
  std::ofstream(dir / "preset.json") << "{\"preset\": \"no such preset\", \"files\": []}";
  CheckRequest request;
  request.dir = dir.string();
  EXPECT_THROW(Check(request), IoError);  // preset.json names no preset
  fs::remove_all(dir);
}

// One JSON shape for check: a preset directory's report has the keys of a
// set's (and "preset"), and its checks the keys of a set's checks.
TEST(CheckApi, APresetDirectoryReportsInTheShapeOfASet) {
  const fs::path set = test::Scratch("check_api_shape_set"),
                 preset = test::Scratch("check_api_shape_preset");
  BakeRequest bake;
  bake.tables = {"E"};
  bake.formats = {"exr"};
  bake.size = 8;
  bake.outputDirectory = set.string();
  Bake(bake);
  BakeRequest presetBake;
  presetBake.preset = "threejs";
  presetBake.outputDirectory = preset.string();
  Bake(presetBake);
  CheckRequest request;
  request.points = 8;
  request.furnaceGrid = 5;
  request.dir = set.string();
  const nlohmann::json a = nlohmann::json::parse(Check(request).json);
  request.dir = preset.string();
  const CheckOutcome presetOutcome = Check(request);
  EXPECT_TRUE(presetOutcome.passed) << presetOutcome.text;
  const nlohmann::json b = nlohmann::json::parse(presetOutcome.json);
  const auto keys = [](const nlohmann::json &object) {
    std::set<std::string> names;
    for (const auto &item : object.items())
      if (item.key() != "preset") names.insert(item.key());
    return names;
  };
  EXPECT_EQ(keys(a), keys(b)) << b.dump(1);
  EXPECT_EQ(b["preset"], "threejs");
  EXPECT_EQ(b["passed"], true);
  ASSERT_EQ(b["checks"].size(), 1u);
  std::set<std::string> checkKeys = keys(a["checks"][0]), presetCheckKeys = keys(b["checks"][0]);
  checkKeys.erase("allowed");  // a set's checks without a numeric limit leave it out
  presetCheckKeys.erase("allowed");
  EXPECT_EQ(checkKeys, presetCheckKeys);
  EXPECT_EQ(b["checks"][0]["status"], "pass");
  EXPECT_LE(b["checks"][0]["worst"].get<double>(), b["checks"][0]["allowed"].get<double>());
  EXPECT_GT(b["checks"][0]["worst"].get<double>(), 0.0);  // half floats: never exact
  fs::remove_all(set);
  fs::remove_all(preset);
}

}  // namespace
}  // namespace lutbake
