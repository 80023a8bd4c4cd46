// The quadrature reference against independent values (tests/data), the
// analytic limits of SPEC section 1, and its own identities.
#include "lutbake/integrators/reference_integrator.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "support/csv.h"
#include "support/reference_row.h"

namespace lutbake {
namespace {

// Every point of the independent tables: 290 (mu, alpha) per NDF, both Smith
// forms, E, A and B. The reference values carry error bounds ~1e-12; ours are
// ~1e-12 too, so 1e-10 leaves room for both and still catches any real
// mistake in D, Lambda, G2 or the horizon.
void CheckAgainstTable(NdfKind kind, const std::string &file) {
  const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath(file));
  ASSERT_EQ(rows.size(), 290u);
  std::vector<double> worst(rows.size(), 0.0);
  tbb::parallel_for(size_t(0), rows.size(),
                    [&](size_t i) { worst[i] = test::WorstDifferenceFromRow(rows[i], kind); });
  for (size_t i = 0; i < rows.size(); ++i)
    EXPECT_LE(worst[i], 1e-10) << file << " mu=" << rows[i].Text("mu")
                               << " alpha=" << rows[i].Text("alpha");
}

TEST(ReferenceIntegrator, MatchesIndependentGgxValues) {
  CheckAgainstTable(NdfKind::kGgx, "ggx_E_AB.csv");
}

TEST(ReferenceIntegrator, MatchesIndependentBeckmannValues) {
  CheckAgainstTable(NdfKind::kBeckmann, "beckmann_E_AB.csv");
}

TEST(ReferenceIntegrator, GrazingLimitsOfGgxAtAlphaOne) {
  // mu_o = 0 is evaluated by continuity: correlated E -> 1 with B -> 1/21,
  // separable E -> 2 - 2 ln 2 (refdata/README, limits.csv).
  const Ndf ndf{NdfKind::kGgx, 1.0};
  const ReferenceAlbedo hc = IntegrateReferenceAlbedo(ndf, SmithForm::kCorrelated, 0.0);
  EXPECT_NEAR(hc.E, 1.0, 1e-12);
  EXPECT_NEAR(hc.B, 1.0 / 21.0, 1e-12);
  const ReferenceAlbedo sep = IntegrateReferenceAlbedo(ndf, SmithForm::kSeparable, 0.0);
  EXPECT_NEAR(sep.E, 2.0 - 2.0 * std::log(2.0), 1e-12);
  // At mu = 1, alpha = 1, correlated GGX: E = 1 - ln 2.
  EXPECT_NEAR(IntegrateReferenceAlbedo(ndf, SmithForm::kCorrelated, 1.0).E, 1.0 - std::log(2.0),
              1e-12);
}

TEST(ReferenceIntegrator, MirrorIsExact) {
  for (double mu : {0.0, 0.3, 1.0}) {
    const ReferenceAlbedo r =
        IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, 0.0}, SmithForm::kCorrelated, mu);
    EXPECT_EQ(r.E, 1.0);
    EXPECT_EQ(r.B, std::pow(1.0 - mu, 5));
    // A is 1 - (1 - mu)^5 written without cancellation, rounded on its
    // own: the sum is 1 to an ulp.
    EXPECT_NEAR(r.A + r.B, 1.0, 0x1p-52);
  }
}

TEST(ReferenceIntegrator, AlbedoAverageMatchesIndependentValues) {
  // A sample of the alpha list (each value is a triple-nested integral).
  for (const auto &[kind, file] : {std::pair{NdfKind::kGgx, "ggx_Eavg.csv"},
                                   std::pair{NdfKind::kBeckmann, "beckmann_Eavg.csv"}}) {
    const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath(file));
    ASSERT_GT(rows.size(), 20u);
    std::vector<size_t> picks = {1, rows.size() / 3, rows.size() / 2, rows.size() - 1};
    std::vector<double> diff(picks.size());
    const NdfKind ndfKind = kind;  // a lambda captures no structured binding before C++20
    tbb::parallel_for(size_t(0), picks.size(), [&](size_t k) {
      const test::CsvRow &row = rows[picks[k]];
      const ReferenceAverage r = IntegrateReferenceAlbedoAverage(Ndf{ndfKind, row.Number("alpha")},
                                                                 SmithForm::kCorrelated);
      diff[k] = std::abs(r.value - row.Number("Eavg_hc"));
    });
    for (size_t k = 0; k < picks.size(); ++k)
      EXPECT_LE(diff[k], 1e-9) << file << " alpha=" << rows[picks[k]].Text("alpha");
  }
}

}  // namespace
}  // namespace lutbake
