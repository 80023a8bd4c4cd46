// `lutbake report`: error against run time for every estimator.
//
// For each table and estimator, bakes the table at 2^2, 2^3, ... samples per
// texel (the quadrature: at tolerances 1e-3, 1e-4, ...) until that
// estimator's share of the time budget is spent, and measures the real error
// of every texel against the quadrature at 1e-12 (1e-11 for E_avg): max,
// RMS, the worst of the grazing column (x = 0) and of the smoothest row
// (y = 0), and how often the bound the bake reports holds.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lutbake/core/cancellation.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

struct ReportSettings {
  std::vector<const TableDefinition *> tables{&TableNamed("E"), &TableNamed("dfg")};
  std::vector<Estimator> estimators{std::begin(kAllEstimators), std::end(kAllEstimators)};
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  SheenVisibility sheenVisibility = SheenVisibility::kCharlie;  // the sheen tables' model
  SheenAlpha sheenAlpha = SheenAlpha::kLinear;
  int size = 32;              // texels per axis of every table
  int depthSize = 0;          // slices of a 3D table's eta axis (0: its default)
  double budgetSeconds = 60;  // in total, split evenly over table x estimator
  uint64_t seed = 0;
  // Polled between texels and runs: RunReport throws Cancelled once it is.
  const CancellationToken *cancellation = nullptr;
};

struct ReportRow {
  const TableDefinition *table = nullptr;
  Estimator estimator = Estimator::kVisibleNormal;
  double samplesPerTexel = 0;  // sampled: samples; quadrature: evaluations (mean)
  double tolerance = 0;        // quadrature rows: the tolerance asked
  double seconds = 0;          // wall time of the bake
  double maxError = 0, rmsError = 0;
  double grazingColumnMax = 0, smoothestRowMax = 0;
  double maxBound = 0;
  double withinBound = 0;  // fraction of texels whose real error is within the bound
};

// Progress: a line of text for the terminal; may be empty.
using ReportProgressFn = std::function<void(const std::string &)>;

std::vector<ReportRow> RunReport(const ReportSettings &settings,
                                 const ReportProgressFn &progress = {});

// The files: report.csv (one row per table x estimator x samples),
// report.md (the rows and, per estimator, the time to reach 1e-3 ... 1e-6),
// report.svg (max error against time, log-log, one line per estimator, one
// panel per table).
std::string ReportCsv(const std::vector<ReportRow> &rows);
std::string ReportMarkdown(const ReportSettings &settings, const std::vector<ReportRow> &rows);
std::string ReportSvg(const ReportSettings &settings, const std::vector<ReportRow> &rows);

}  // namespace lutbake
