#include <gtest/gtest.h>

#include "lutbake/integrators/fresnel_average.h"
#include "support/csv.h"

namespace lutbake {
namespace {

TEST(Fresnel, SchlickAverageIsTheClosedForm) {
  // 2 int_0^1 (F0 + (1 - F0)(1 - mu)^5) mu dmu = F0 + (1 - F0) / 21. The
  // 15-point rule is exact for this polynomial; what remains is the rounding
  // of a 15-term sum, a few ulp of 1.
  for (int i = 0; i <= 20; ++i) {
    const double f0 = i / 20.0;
    EXPECT_NEAR(SchlickFresnelAverage(f0).value, 20.0 / 21.0 * f0 + 1.0 / 21.0, 1e-15);
  }
}

TEST(Fresnel, ExactAveragesMatchIndependentValues) {
  // Dielectric and conductor F_avg from 30-digit quadrature (tests/data/Favg.csv).
  int checked = 0;
  for (const test::CsvRow &row : test::ReadCsv(test::DataPath("Favg.csv"))) {
    const std::string &model = row.Text("model");
    if (model == "dielectric_exact") {
      EXPECT_NEAR(ExactFresnelAverage(row.Number("eta"), 0.0).value, row.Number("Favg"), 1e-14)
          << row.Text("param");
      ++checked;
    } else if (model == "conductor_exact") {
      EXPECT_NEAR(ExactFresnelAverage(row.Number("eta"), row.Number("k")).value, row.Number("Favg"),
                  1e-14)
          << row.Text("param");
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8);
}

TEST(Fresnel, ExactFresnelLimits) {
  // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2); grazing: 1.
  EXPECT_NEAR(ExactFresnel(1.5, 0.0, 1.0), 0.04, 1e-15);
  EXPECT_NEAR(ExactFresnel(0.2, 3.0, 1.0), (0.64 + 9.0) / (1.44 + 9.0), 1e-15);
  EXPECT_NEAR(ExactFresnel(1.5, 0.0, 0.0), 1.0, 1e-15);
  EXPECT_EQ(ExactFresnel(1.0, 0.0, 0.5), 0.0);
  // Total internal reflection for eta < 1 beyond the critical angle.
  EXPECT_EQ(ExactFresnel(1.0 / 1.5, 0.0, 0.5), 1.0);
  // Internal F_avg relates to the external one by 1 - F_int = (1 - F_ext) / eta^2.
  const double eta = 1.5;
  EXPECT_NEAR(1.0 - ExactFresnelAverage(1.0 / eta, 0.0).value,
              (1.0 - ExactFresnelAverage(eta, 0.0).value) / (eta * eta), 1e-13);
}

}  // namespace
}  // namespace lutbake
