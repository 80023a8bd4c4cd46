// The report's measurements: real errors fall as samples rise for the
// visible-normal estimators, and the quadrature rows agree with the
// independent reference values (tests/data) at the same points.
#include "lutbake/validation/report.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "lutbake/integrators/reference_integrator.h"
#include "support/csv.h"

namespace lutbake {
namespace {

TEST(Report, VisibleNormalErrorsFallAndQuadratureIsAccurate) {
  ReportSettings s;
  s.tables = {&TableNamed("E")};
  s.estimators = {Estimator::kVisibleNormal, Estimator::kVisibleNormalRandom,
                  Estimator::kQuadrature};
  s.size = 8;
  s.budgetSeconds = 3;
  const std::vector<ReportRow> rows = RunReport(s);
  for (Estimator e : s.estimators) {
    std::vector<ReportRow> mine;
    for (const ReportRow &r : rows)
      if (r.estimator == e) mine.push_back(r);
    ASSERT_GE(mine.size(), 4u) << ToString(e);
    // From the first to the last run the samples grow by at least 8x; the
    // max error must drop by 2x at least (1/sqrt(N) would give 2.8x), the
    // RMS error too.
    EXPECT_LT(mine.back().maxError, 0.5 * mine.front().maxError) << ToString(e);
    EXPECT_LT(mine.back().rmsError, 0.5 * mine.front().rmsError) << ToString(e);
  }
  // The quadrature's last row (tolerance <= 1e-5) is within 1e-5 everywhere.
  double bestQuadrature = 1;
  for (const ReportRow &r : rows)
    if (r.estimator == Estimator::kQuadrature) bestQuadrature = r.maxError;
  EXPECT_LE(bestQuadrature, 1e-5);
  const std::string csv = ReportCsv(rows);
  EXPECT_EQ(static_cast<size_t>(std::count(csv.begin(), csv.end(), '\n')), rows.size() + 1);
  EXPECT_NE(ReportSvg(s, rows).find("<polyline"), std::string::npos);
  EXPECT_NE(ReportMarkdown(s, rows).find("| vndf |"), std::string::npos);
}

// A sheen table in a report: the estimator it refuses (cosine) is left out
// and the Markdown says why; the sampler's error falls with N; the panel rule
// meets the adaptive reference, in the model asked for (ashikhmin, alpha =
// r^2, which the header line records).
TEST(Report, SheenTableSkipsWhatItRefusesAndConverges) {
  ReportSettings s;
  s.tables = {&TableNamed("sheen_E")};
  s.estimators = {Estimator::kCosine, Estimator::kVisibleNormal, Estimator::kQuadrature};
  s.sheenVisibility = SheenVisibility::kAshikhmin;
  s.sheenAlpha = SheenAlpha::kSquared;
  s.size = 4;
  s.budgetSeconds = 2;
  const std::vector<ReportRow> rows = RunReport(s);
  std::vector<ReportRow> sampled, quadrature;
  for (const ReportRow &r : rows) {
    EXPECT_NE(r.estimator, Estimator::kCosine);
    if (r.estimator == Estimator::kVisibleNormal) sampled.push_back(r);
    if (r.estimator == Estimator::kQuadrature) quadrature.push_back(r);
  }
  ASSERT_GE(sampled.size(), 4u);
  EXPECT_LT(sampled.back().rmsError, 0.5 * sampled.front().rmsError);
  ASSERT_FALSE(quadrature.empty());
  EXPECT_LE(quadrature.back().maxError, 1e-9);
  EXPECT_EQ(quadrature.back().withinBound, 1.0);
  const std::string md = ReportMarkdown(s, rows);
  EXPECT_NE(md.find("| cosine | not offered: sheen_E has no cosine-weighted sampler"),
            std::string::npos);
  EXPECT_NE(md.find("sheen visibility ashikhmin, sheen alpha squared"), std::string::npos);
}

// A 3D table: every slice's texels against references at their own eta
// (the quadrature's rows within their bounds everywhere).
TEST(Report, ThreeDTableIsMeasuredOnEverySlice) {
  ReportSettings s;
  s.tables = {&TableNamed("glass_E")};
  s.estimators = {Estimator::kQuadrature};
  s.size = 4;
  s.depthSize = 2;  // eta = 1/3 and 3: both sides
  s.budgetSeconds = 0.5;
  const std::vector<ReportRow> rows = RunReport(s);
  ASSERT_FALSE(rows.empty());
  for (const ReportRow &r : rows) {
    EXPECT_EQ(r.withinBound, 1.0) << r.tolerance;
    // A slice measured against another slice's references would be off by
    // ~0.1; the references themselves hold ~1e-9 on the inside (eta = 1/3).
    EXPECT_LE(r.maxError, std::max(r.tolerance, 1e-8)) << r.tolerance;
  }
}

TEST(Report, ReferenceAgreesWithIndependentValuesAtTexelPoints) {
  // The report measures against IntegrateReferenceAlbedo at 1e-12; at the
  // independent points of tests/data it must agree to 1e-10 there too.
  const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath("ggx_E_AB.csv"));
  for (size_t i = 0; i < rows.size(); i += 29) {
    const ReferenceAlbedo a =
        IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, rows[i].Number("alpha")},
                                 SmithForm::kCorrelated, rows[i].Number("mu"), 1e-12);
    EXPECT_NEAR(a.E, rows[i].Number("E_hc"), 1e-10) << rows[i].Text("mu");
  }
}

}  // namespace
}  // namespace lutbake
