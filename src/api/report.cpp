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
    for (const std::string &name : *r.tables) settings.tables.push_back(&TableNamed(name));
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
  return names;
}

ReportOutcome Report(const ReportRequest &r) {
  const ReportSettings settings = SettingsOf(r);
  OutputTransaction output(r.outputDirectory);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(r.threads)));
  ReportOutcome outcome;
  outcome.rows = RunReport(settings, r.progress);
  WriteText(output, "report.csv", ReportCsv(outcome.rows));
  WriteText(output, "report.md", ReportMarkdown(settings, outcome.rows));
  WriteText(output, "report.svg", ReportSvg(settings, outcome.rows));
  output.Commit(r.cancellation);
  outcome.files = output.files();
  return outcome;
}

}  // namespace lutbake
