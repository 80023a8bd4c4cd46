// lutbake::Check: a fresh bake passes and says so, a directory that is not
// there or not a directory is a UsageError, a preset's directory is checked
// as one.
#include "lutbake/api/check.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace lutbake
