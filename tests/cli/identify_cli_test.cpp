// `lutbake check FILE --as TABLE` and `lutbake identify FILE` as a user runs
// them: the exit status says pass (0), fail (1), usage (2) or unreadable
// input (3), and a file that cannot be read prints nothing on stdout.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using lutbake::test::Lutbake;
using lutbake::test::Scratch;

TEST(CliIdentify, ExitStatusesSayPassFailUsageAndUnreadable) {
  const fs::path dir = Scratch("cli_identify");
  fs::create_directories(dir);
  // A table lutbake baked, as a foreign engine would ship it: one 8-bit PNG.
  ASSERT_EQ(
      Lutbake("bake --out " + (dir / "set").string() + " --tables dfg --size 24 --format png8 -q")
          .status,
      0);
  const std::string png = (dir / "set" / "dfg.png").string();
  EXPECT_EQ(Lutbake("check " + png + " --as dfg").status, 0);
  // --json: the shape of a set's report, the judgement under tableFile.
  const auto checked = Lutbake("check " + png + " --as dfg --json", true);
  const nlohmann::json report = nlohmann::json::parse(checked.output);
  EXPECT_EQ(report["passed"], true);
  ASSERT_EQ(report["checks"].size(), 1u);
  EXPECT_EQ(report["checks"][0]["check"], "values");
  EXPECT_LE(report["checks"][0]["worst"].get<double>(), 0.5 / 255 + 1e-7);
  EXPECT_EQ(report["tableFile"]["table"], "dfg");
  // Checked as flipped, every row is wrong: fail, with the error picture.
  const std::string picture = (dir / "error.png").string();
  const auto flipped = Lutbake("check " + png + " --as dfg --flip y --error-image " + picture);
  EXPECT_EQ(flipped.status, 1) << flipped.output;
  EXPECT_NE(flipped.output.find("FAILED"), std::string::npos) << flipped.output;
  EXPECT_TRUE(fs::is_regular_file(picture));

  const auto identified = Lutbake("identify " + png + " --json", true);
  EXPECT_EQ(identified.status, 0) << identified.output;
  const nlohmann::json j = nlohmann::json::parse(identified.output);
  for (const char *key : {"table", "preset", "transposed", "flipX", "flipY", "offsetX", "offsetY",
                          "encoding", "smith", "maxError", "rmsError"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["table"], "dfg");
  EXPECT_EQ(j["flipY"], false);

  // Usage: a file without a convention, a table that is none, a directory
  // with --as.
  EXPECT_EQ(Lutbake("check " + png).status, 2);
  EXPECT_EQ(Lutbake("check " + png + " --as DFG").status, 2);
  EXPECT_EQ(Lutbake("check " + dir.string() + " --as dfg").status, 2);
  // Unreadable: 3, and nothing on stdout.
  std::ofstream(dir / "cut.png", std::ios::binary) << "\x89PNG\r\n\x1a\n\x00\x00";
  for (const std::string &bad : {(dir / "missing.png").string(), (dir / "cut.png").string()}) {
    EXPECT_EQ(Lutbake("identify " + bad).status, 3) << bad;
    EXPECT_EQ(Lutbake("identify " + bad + " --json", true).output, "") << bad;
    EXPECT_EQ(Lutbake("check " + bad + " --as dfg").status, 3) << bad;
    EXPECT_EQ(Lutbake("check " + bad + " --as dfg --json", true).output, "") << bad;
  }
}

TEST(CliIdentify, NoConventionMatchesAPictureExitsOne) {
  const fs::path dir = Scratch("cli_identify_picture");
  fs::create_directories(dir);
  // A grey ramp across the rows: monotonic along y only, unlike any A or B.
  std::ofstream out(dir / "ramp.js");
  out << "const ramp = [";
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) out << (x % 2 ? 0.9 : 0.1) << ", " << y / 15.0 << ", ";
  out << "];\n";
  out.close();
  const auto result = Lutbake("identify " + (dir / "ramp.js").string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("no known convention matches"), std::string::npos) << result.output;
}

}  // namespace
