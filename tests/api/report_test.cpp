// lutbake::Report: the three files hold what the rows say, a cancelled
// report writes nothing and removes the directory it made, unknown names
// are refused.
#include "lutbake/api/report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "lutbake/core/error.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

TEST(ReportApi, WritesTheRowsItMeasured) {
  const fs::path dir = test::Scratch("report_api_out");
  ReportRequest request;
  request.outputDirectory = dir.string();
  request.tables = std::vector<std::string>{"E"};
  request.estimators = std::vector<std::string>{"quadrature", "vndf"};
  request.size = 4;
  request.budgetSeconds = 0.05;
  int progressLines = 0;
  request.progress = [&](const std::string &) { ++progressLines; };
  const ReportOutcome outcome = Report(request);
  ASSERT_FALSE(outcome.rows.empty());
  EXPECT_GT(progressLines, 0);
  for (const ReportRow &row : outcome.rows) {
    EXPECT_EQ(row.table->Name(), "E");
    EXPECT_TRUE(row.withinBound >= 0.0 && row.withinBound <= 1.0);
  }
  EXPECT_EQ(test::FileNames(dir),
            (std::vector<std::string>{"report.csv", "report.md", "report.svg"}));
  std::ifstream in(dir / "report.csv", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), ReportCsv(outcome.rows));
  fs::remove_all(dir);
}

TEST(ReportApi, ACancelledReportLeavesNothing) {
  const fs::path dir = test::Scratch("report_api_cancelled");
  CancellationToken token;
  token.Cancel(2);
  ReportRequest request;
  request.outputDirectory = dir.string();
  request.size = 4;
  request.budgetSeconds = 0.05;
  request.cancellation = &token;
  try {
    Report(request);
    ADD_FAILURE() << "no Cancelled";
  } catch (const Cancelled &c) {
    EXPECT_EQ(c.reason(), 2);
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(ReportApi, RefusesUnknownNames) {
  ReportRequest request;
  request.outputDirectory = test::Scratch("report_api_refused").string();
  request.estimators = std::vector<std::string>{"nope"};
  EXPECT_THROW(Report(request), UsageError);
  EXPECT_FALSE(fs::exists(request.outputDirectory));
}

}  // namespace
}  // namespace lutbake
