#include "report_command.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "bake_command.h"
#include "cli_util.h"
#include "interrupt.h"
#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/writer.h"
#include "lutbake/validation/report.h"
#include "sampling_options.h"

namespace lutbake::cli {

namespace {

void WriteText(AtomicOutputSet &output, const std::string &path, const std::string &text) {
  const std::string temporary = output.Add(path);
  std::ofstream file(temporary, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw IoError("cannot write " + path);
}

// The tables that take the sampled estimators: the ones a report compares.
std::vector<std::string> SampledTableNames() {
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables())
    if (table->Sampled()) names.push_back(table->Name());
  return names;
}

}  // namespace

void SetupReportCommand(CLI::App &app, ReportOptions &o) {
  app.add_option("--out", o.outDir, "Output directory for report.csv, report.md, report.svg")
      ->required()
      ->type_name("DIR");
  app.add_option("--tables", o.tables,
                 "Tables to measure (Favg has no sampled estimator: it is always quadrature)")
      ->capture_default_str()
      ->check(ListOf(SampledTableNames()));
  app.add_option("--estimators", o.estimators, "Estimators to compare")
      ->capture_default_str()
      ->check(ListOf(EstimatorNames()));
  app.add_option("--budget", o.budget,
                 "Seconds in total (split evenly over table x estimator); each estimator doubles "
                 "its samples from 4 while its share lasts")
      ->capture_default_str()
      ->type_name("SECONDS")
      ->check(RealInRange(0.01, 86400, "seconds from 0.01 to 86400"));
  app.add_option("--size", o.size, "Texels per axis of every measured table")
      ->capture_default_str()
      ->type_name("N")
      ->check(InRange(1, 256, "texels per axis"));
  AddModelOptions(app, o.ndf, o.smith);
  AddSeedOption(app, o.seed, "Seed of the point sets");
  AddThreadsOption(app, o.threads);
  app.footer("Example:\n  lutbake report --out report --budget 60");
}

int RunReport(const ReportOptions &o) {
  ReportSettings settings;
  settings.tables.clear();
  for (const std::string &name : SplitList(o.tables)) settings.tables.push_back(&TableNamed(name));
  settings.estimators.clear();
  for (const std::string &name : SplitList(o.estimators))
    settings.estimators.push_back(EstimatorNamed(name));
  settings.ndf = ParseNdf(o.ndf);
  settings.smith = ParseSmith(o.smith);
  settings.size = o.size;
  settings.budgetSeconds = o.budget;
  settings.seed = o.seed;

  bool created = false;
  if (const int status = PrepareOutputOrComplain("report", o.outDir, &created)) return status;
  RemoveStaleTemporaries(o.outDir);
  const int threads = ThreadCount(o.threads);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(threads));
  // SIGINT and SIGTERM end the report as they end a bake: 130 / 143, one
  // line, nothing written and the directory removed if this run made it.
  const InterruptGuard interrupt;
  settings.cancellation = &interrupt.token();
  // A progress line, rewritten in place, only when stderr is a terminal.
  ReportProgressFn progress;
  if (::isatty(STDERR_FILENO))
    progress = [](const std::string &line) { std::cerr << "\r\033[K" << line << std::flush; };
  std::vector<ReportRow> rows;
  namespace fs = std::filesystem;
  try {
    rows = RunReport(settings, progress);
    if (progress) std::cerr << "\r\033[K";
    AtomicOutputSet output;
    WriteText(output, (fs::path(o.outDir) / "report.csv").string(), ReportCsv(rows));
    WriteText(output, (fs::path(o.outDir) / "report.md").string(), ReportMarkdown(settings, rows));
    WriteText(output, (fs::path(o.outDir) / "report.svg").string(), ReportSvg(settings, rows));
    interrupt.token().ThrowIfCancelled();
    output.Commit();
  } catch (const Cancelled &c) {
    if (progress) std::cerr << "\r\033[K";
    RemoveCreatedDirectory(o.outDir, created);
    std::cerr << "lutbake report: interrupted by " << SignalName(c.reason())
              << "; nothing written to " << o.outDir << "\n";
    return 128 + c.reason();
  } catch (const IoError &e) {
    std::cerr << "lutbake report: " << e.what() << "\n";
    RemoveCreatedDirectory(o.outDir, created);
    return 1;
  }
  std::cerr << "lutbake report: " << rows.size() << " runs; wrote report.csv, report.md, "
            << "report.svg in " << o.outDir << "\n";
  return 0;
}

}  // namespace lutbake::cli
