// lutbake::Report: error against run time of every estimator, as `lutbake
// report` measures it (validation/report.h), written into a directory as
// report.csv, report.md and report.svg, all three or none
// (OutputTransaction).
//
//   lutbake::ReportRequest request;
//   request.outputDirectory = "report";
//   request.budgetSeconds = 10;
//   lutbake::Report(request);
//
// Throws UsageError for an unknown table or estimator name or an --out that
// is not a directory, IoError when the files cannot be written, Cancelled
// when the request's token is cancelled (then nothing is written, and a
// directory this call created is removed).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lutbake/core/cancellation.h"
#include "lutbake/validation/ltc_report.h"
#include "lutbake/validation/report.h"

namespace lutbake {

struct ReportRequest {
  std::string outputDirectory;  // created if missing
  // The sampled tables to measure (unset: E, dfg) and the estimators to
  // compare (EstimatorNames(); unset: all).
  std::optional<std::vector<std::string>> tables;
  std::optional<std::vector<std::string>> estimators;
  std::optional<NdfKind> ndf;      // unset: GGX
  std::optional<SmithForm> smith;  // unset: height-correlated
  int size = 32;                   // texels per axis of every measured table
  double budgetSeconds = 60;       // in total, split evenly over table x estimator
  uint64_t seed = 0;
  int threads = 0;  // 0: all cores
  // With "ltc_ggx" among the tables: ltc_code's table (three.js's
  // RectAreaLightTexturesLib.js) to measure beside it (ltc_report.h); empty:
  // lutbake's table alone.
  std::string ltcReference;
  // Polled between texels and runs.
  const CancellationToken *cancellation = nullptr;
  // A line saying what is being measured, for a terminal; may be empty.
  std::function<void(const std::string &line)> progress;
};

struct ReportOutcome {
  std::vector<ReportRow> rows;
  std::vector<std::string> files;  // report.csv, report.md, report.svg (, ltc_error.csv, .svg)
};

// The tables a report can measure: those with sampled estimators, and
// ltc_ggx (its lobe error map, not an estimator comparison).
std::vector<std::string> ReportTableNames();

ReportOutcome Report(const ReportRequest &request);

}  // namespace lutbake
