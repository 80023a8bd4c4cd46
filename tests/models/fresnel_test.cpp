#include <gtest/gtest.h>

#include <cmath>

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

// The F82-tint Fresnel: F(1) = F0, F(0) = 1 (Schlick's ends, the bump
// mu (1 - mu)^6 vanishes at both), F(1/7) = tint Schlick(F0, 1/7) (what a is
// chosen for), and tint = 1 is Schlick's.
TEST(Fresnel, F82TintLimits) {
  for (double f0 : {0.0, 0.04, 0.56, 0.95, 1.0})
    for (double tint : {0.0, 0.25, 0.7, 1.0}) {
      EXPECT_EQ(F82TintFresnel(f0, tint, 1.0), f0);
      EXPECT_DOUBLE_EQ(F82TintFresnel(f0, tint, 0.0), 1.0);
      const double schlickBar = f0 + (1.0 - f0) * std::pow(6.0 / 7.0, 5);
      EXPECT_NEAR(F82TintFresnel(f0, tint, 1.0 / 7.0), tint * schlickBar, 1e-15) << f0 << tint;
      for (double mu : {0.01, 0.3, 0.8})
        EXPECT_NEAR(F82TintFresnel(f0, 1.0, mu), SchlickFresnel(f0, mu), 1e-16);
    }
  // a = Schlick(F0, 1/7) (1 - tint) / (mu_bar (1 - mu_bar)^6), here for F0 = 0.5, tint = 0.2.
  EXPECT_NEAR(F82TintCoefficient(0.5, 0.2),
              (0.5 + 0.5 * std::pow(6.0 / 7.0, 5)) * 0.8 / (std::pow(6.0 / 7.0, 6) / 7.0), 1e-14);
}

}  // namespace
}  // namespace lutbake
