#include "lutbake/api/report.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <fstream>

#include "bake_internal.h"
#include "lutbake/api/names.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/output_transaction.h"

namespace lutbake {

namespace {

// The table whose report is a lobe error map (ltc_report.h).
constexpr const char *kLtcReportTable = "ltc_ggx";

void CheckNames(const std::string &option, const std::vector<std::string> &given,
                const std::vector<std::string> &accepted) {
  for (const std::string &name : given)
    if (std::find(accepted.begin(), accepted.end(), name) == accepted.end())
      throw UsageError("--" + option + " names '" + name +
                       "', which is not accepted; accepted: a comma-separated subset of " +
                       JoinNames(accepted));
}

ReportSettings SettingsOf(const ReportRequest &r) {
  ReportSettings settings;
  if (r.tables) {
    CheckNames("tables", *r.tables, ReportTableNames());
    settings.tables.clear();
    for (const std::string &name : *r.tables)
      if (TableNamed(name).Sampled()) settings.tables.push_back(&TableNamed(name));
  }
  if (r.estimators) {
    CheckNames("estimators", *r.estimators, EstimatorNames());
    settings.estimators.clear();
    for (const std::string &name : *r.estimators) {
      Estimator estimator = Estimator::kVisibleNormal;
      ParseEstimator(name, &estimator);
      settings.estimators.push_back(estimator);
    }
  }
  settings.ndf = r.ndf.value_or(settings.ndf);
  settings.smith = r.smith.value_or(settings.smith);
  settings.size = r.size;
  settings.budgetSeconds = r.budgetSeconds;
  settings.seed = r.seed;
  settings.cancellation = r.cancellation;
  return settings;
}

// `text` as fileName's content; a failure says "cannot write PATH".
void WriteText(OutputTransaction &output, const std::string &fileName, const std::string &text) {
  const std::string path = output.PathOf(fileName);
  output.Write(fileName, [&](const std::string &temporary) {
    std::ofstream file(temporary, std::ios::binary);
    file << text;
    file.close();
    if (!file) throw IoError("cannot write " + path);
  });
}

}  // namespace

std::vector<std::string> ReportTableNames() {
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables())
    if (table->Sampled()) names.push_back(table->Name());
  names.push_back(kLtcReportTable);
  return names;
}

ReportOutcome Report(const ReportRequest &r) {
  const ReportSettings settings = SettingsOf(r);
  const bool ltc =
      r.tables && std::find(r.tables->begin(), r.tables->end(), kLtcReportTable) != r.tables->end();
  if (!r.ltcReference.empty() && !ltc)
    throw UsageError("--ltc-reference " + r.ltcReference +
                     " measures ltc_code's table beside ltc_ggx; add ltc_ggx to --tables");
  if (!r.ltcReference.empty() && settings.ndf != NdfKind::kGgx)
    throw UsageError("--ltc-reference " + r.ltcReference +
                     ": ltc_code's table is of GGX; the report measures " +
                     std::string(ToString(settings.ndf)));
  OutputTransaction output(r.outputDirectory);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(r.threads)));
  ReportOutcome outcome;
  std::string markdown;
  if (!settings.tables.empty()) {
    outcome.rows = RunReport(settings, r.progress);
    WriteText(output, "report.csv", ReportCsv(outcome.rows));
    WriteText(output, "report.svg", ReportSvg(settings, outcome.rows));
    markdown = ReportMarkdown(settings, outcome.rows);
  }
  if (ltc) {
    if (r.progress) r.progress("ltc_ggx: fitting the table and measuring its lobe error");
    BakeSettings model;
    model.ndf = settings.ndf;
    model.smith = settings.smith;
    const Table table = BakeTable(TableNamed(kLtcReportTable), model);
    if (r.cancellation) r.cancellation->ThrowIfCancelled();
    const LtcErrorMap map = MeasureLtcErrorMap(table, settings.ndf, settings.smith, r.ltcReference);
    WriteText(output, "ltc_error.csv", LtcErrorCsv(map));
    WriteText(output, "ltc_error.svg", LtcErrorSvg(map));
    markdown += LtcErrorMarkdown(map);
  }
  WriteText(output, "report.md", markdown);
  output.Commit(r.cancellation);
  outcome.files = output.files();
  return outcome;
}

}  // namespace lutbake
