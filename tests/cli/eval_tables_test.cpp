// `lutbake eval` with the coordinates of the f82, Favg (F82 tint),
// oren_nayar and sheen tables: what it prints (--json echoes the coordinates
// given) and what it refuses (exit status 2, and the message naming why).
// The values themselves are the tables' tests (tests/tables/), which call
// the library.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lutbake/integrators/fresnel_average.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

using test::Lutbake;

// f82 takes --mu and --roughness; --eta is another table's coordinate.
TEST(F82Table, EvalTakesMuAndRoughnessOnly) {
  EXPECT_EQ(Lutbake("eval --table f82 --mu 0.5 --roughness 0.5 --eta 1.5").status, 2);
}

TEST(F82Favg, EvalTakesF0AndTint) {
  const test::CommandResult eval =
      Lutbake("eval --table Favg --fresnel f82 --f0 0.9 --tint 0.6 --json", true);
  ASSERT_EQ(eval.status, 0) << eval.output;
  const nlohmann::json j = nlohmann::json::parse(eval.output);
  EXPECT_EQ(double(j["value"]), F82TintFresnelAverage(0.9, 0.6).value);
  EXPECT_EQ(double(j["tint"]), 0.6);
  EXPECT_EQ(Lutbake("eval --table Favg --fresnel f82 --f0 0.9").status, 2);  // needs --tint
  EXPECT_EQ(Lutbake("eval --table Favg --fresnel schlick --f0 0.9 --tint 0.5").status, 2);
}

TEST(OrenNayarTables, EvalTakesSigmaInItsRange) {
  test::CommandResult eval = Lutbake("eval --table oren_nayar_E --mu 0.5 --sigma 1 --json", true);
  ASSERT_EQ(eval.status, 0) << eval.output;
  EXPECT_NE(eval.output.find("\"sigma\":1"), std::string::npos) << eval.output;
  // Out of range, and an option the table does not take.
  eval = Lutbake("eval --table oren_nayar_E --mu 0.5 --sigma 1.6");
  EXPECT_EQ(eval.status, 2);
  EXPECT_NE(eval.output.find("[0, pi/2]"), std::string::npos) << eval.output;
  eval = Lutbake("eval --table oren_nayar_E --mu 0.5 --roughness 0.5");
  EXPECT_EQ(eval.status, 2) << eval.output;
  eval = Lutbake("eval --table E --mu 0.5 --sigma 0.5 --roughness 0.5");
  EXPECT_EQ(eval.status, 2) << eval.output;
}

TEST(SheenTables, EvalRefusesWhatHasNoFiniteValueOrDoesNotApply) {
  struct Bad {
    std::string args, mentions;
  };
  for (const Bad &bad : std::vector<Bad>{
           {"--table sheen_E --mu 0 --roughness 0.5", "infinite at mu = 0"},
           {"--table sheen_E --mu 0 --roughness 0 --sheen-visibility ashikhmin", "infinite"},
           {"--table sheen_E --mu 0.5 --roughness 1.5", "[0, 1]"},
           {"--table sheen_E --mu 0.5 --roughness 0.5 --ndf beckmann", "--ndf does not apply"},
           {"--table E --mu 0.5 --roughness 0.5 --sheen-visibility ashikhmin",
            "--sheen-visibility does not apply"},
           {"--table sheen_E --mu 0.5 --roughness 0.5 --estimator cosine", "no cosine"},
           {"--table sheen_Eavg --mu 0.5 --roughness 0.5", "--mu does not apply"},
           {"--table sheen_E --mu 0.5 --roughness 0.5 --sheen-alpha cubed", "linear"},
       }) {
    const test::CommandResult run = Lutbake("eval " + bad.args);
    EXPECT_EQ(run.status, 2) << bad.args << "\n" << run.output;
    EXPECT_NE(run.output.find(bad.mentions), std::string::npos) << bad.args << "\n" << run.output;
  }
}

}  // namespace
}  // namespace lutbake
