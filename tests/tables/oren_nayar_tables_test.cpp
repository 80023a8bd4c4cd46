// The Oren-Nayar albedo tables (oren_nayar_E: qualitative A + B,
// oren_nayar_full_E: the full model): values against the independent numpy
// furnace reference (tests/data/furnace), the default rule against check's
// reference (a different integral: the BRDF over (theta_i, dphi), not the
// closed-form azimuth), the Lambert limit, and eval, bake and check through
// the command line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "lutbake/tables/table_definition.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::Lutbake;

BakeSettings WithEstimator(Estimator e) {
  BakeSettings s;
  s.estimator = e;
  return s;
}

TEST(OrenNayarTables, MatchTheIndependentFurnaceReference) {
  int compared = 0;
  for (const test::CsvRow &row : test::ReadCsv(LUTBAKE_TEST_DATA "/furnace/reference.csv")) {
    if (row.Text("model") != "oren-nayar") continue;
    const TableDefinition &table =
        TableNamed(row.Text("variant") == "full" ? "oren_nayar_full_E" : "oren_nayar_E");
    const double sigma = row.Number("parameter"), mu = row.Number("mu");
    for (Estimator e : {Estimator::kQuadrature, Estimator::kAdaptiveQuadrature}) {
      const PointValue v = table.Evaluate(WithEstimator(e), mu, sigma);
      EXPECT_NEAR(v.value[0], row.Number("value"), v.error[0] + row.Number("error"))
          << table.Name() << " mu " << mu << " sigma " << sigma;
      EXPECT_LT(v.error[0], 1e-9);
    }
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

// The two rules are different computations that agree within their bounds
// over a grid that reaches grazing views and sigma = pi/2.
TEST(OrenNayarTables, DefaultRuleAgreesWithTheReference) {
  for (const char *name : {"oren_nayar_E", "oren_nayar_full_E"}) {
    const TableDefinition &table = TableNamed(name);
    int differ = 0;
    for (double mu : {0.0, 0.01, 0.3, 0.7071, 1.0})
      for (double sigma : {0.05, 0.4, 1.0, 0.5 * kPi}) {
        const PointValue a = table.Evaluate(WithEstimator(Estimator::kQuadrature), mu, sigma);
        const PointValue b =
            table.Evaluate(WithEstimator(Estimator::kAdaptiveQuadrature), mu, sigma);
        EXPECT_NEAR(a.value[0], b.value[0], a.error[0] + b.error[0])
            << name << " mu " << mu << " sigma " << sigma;
        differ += a.value[0] != b.value[0];
      }
    EXPECT_GT(differ, 0) << name << ": the reference must not be the default rule";
  }
}

TEST(OrenNayarTables, SigmaZeroIsLambert) {
  for (const char *name : {"oren_nayar_E", "oren_nayar_full_E"})
    for (double mu : {0.0, 0.2, 1.0}) {
      const PointValue v = TableNamed(name).Evaluate(BakeSettings{}, mu, 0.0);
      EXPECT_NEAR(v.value[0], 1.0, v.error[0] + 1e-15) << name << " mu " << mu;
    }
}

TEST(OrenNayarTables, EvalBakeAndCheck) {
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

  const fs::path dir = test::Scratch("oren_nayar_bake");
  const test::CommandResult bake = Lutbake("bake --out " + dir.string() +
                                           " --tables oren_nayar_E,oren_nayar_full_E --size 8 "
                                           "--format exr,bin,header");
  ASSERT_EQ(bake.status, 0) << bake.output;
  const test::CommandResult check = Lutbake("check " + dir.string());
  EXPECT_EQ(check.status, 0) << check.output;
  for (const char *claim : {"oren_nayar_E texels", "oren_nayar_full_E texels", "oren_nayar_E limit",
                            "oren_nayar_full_E limit"})
    EXPECT_NE(check.output.find(claim), std::string::npos) << claim << "\n" << check.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
