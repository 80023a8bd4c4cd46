// The Oren-Nayar albedo tables (oren_nayar_E: qualitative A + B,
// oren_nayar_full_E: the full model): values against the independent numpy
// furnace reference (tests/data/furnace), the default rule against check's
// reference (a different integral: the BRDF over (theta_i, dphi), not the
// closed-form azimuth), the Lambert limit, and bake and check through the
// library (eval's options for these tables: tests/cli/eval_tables_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "lutbake/lutbake.h"
#include "lutbake/tables/table_definition.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

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

TEST(OrenNayarTables, BakeAndCheck) {
  const fs::path dir = test::Scratch("oren_nayar_bake");
  BakeRequest request = test::BakeRequestFor(dir);
  request.tables = {"oren_nayar_E", "oren_nayar_full_E"};
  request.size = 8;
  request.formats = {"exr", "bin", "header"};
  Bake(request);
  const CheckReport check = CheckBakedSet(dir.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  const std::map<std::string, std::string> status = test::CheckStatuses(check);
  for (const char *claim : {"oren_nayar_E texels", "oren_nayar_full_E texels", "oren_nayar_E limit",
                            "oren_nayar_full_E limit"})
    EXPECT_EQ(status.count(claim), 1u) << claim << "\n" << test::Describe(check);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
