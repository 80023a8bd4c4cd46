#include "report_command.h"

#include <iostream>

#include "cli_util.h"
#include "interrupt.h"
#include "lutbake/api/progress.h"
#include "lutbake/api/report.h"

namespace lutbake::cli {

void SetupReportCommand(CLI::App &app, ReportOptions &o) {
  app.add_option("-o,--out", o.outDir, "Output directory for report.csv, report.md, report.svg")
      ->required()
      ->type_name("DIR");
  app.add_option("--tables", o.tables,
                 "Tables to measure (Favg has no sampled estimator: it is always quadrature; "
                 "ltc_ggx: its lobe error map, ltc_error.csv and .svg)")
      ->capture_default_str()
      ->check(ListOf(ReportTableNames()));
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
  app.add_option("--ltc-reference", o.ltcReference,
                 "ltc_code's table as three.js ships it (RectAreaLightTexturesLib.js), measured "
                 "beside ltc_ggx")
      ->type_name("FILE");
  AddModelOptions(app, o.models, {"ndf", "smith"});
  AddSeedOption(app, o.seed, "Seed of the point sets");
  AddThreadsOption(app, o.threads);
  app.add_flag("-q,--quiet", o.quiet, "No progress or summary lines (errors are still printed)");
  app.footer("Example:\n  lutbake report --out report --budget 60");
}

int RunReport(const ReportOptions &o) {
  ReportRequest r;
  r.outputDirectory = o.outDir;
  r.tables = SplitList(o.tables);
  r.estimators = SplitList(o.estimators);
  const ModelChoice models = ModelsNamed(o.models);
  r.ndf = models.ndf;
  r.smith = models.smith;
  r.size = o.size;
  r.budgetSeconds = o.budget;
  r.seed = o.seed;
  r.threads = o.threads;
  r.ltcReference = o.ltcReference;
  // SIGINT and SIGTERM end the report as they end a bake: 130 / 143, one
  // line, nothing written and the directory removed if this run made it.
  const InterruptGuard interrupt;
  r.cancellation = &interrupt.token();
  // A progress line, rewritten in place on a terminal, every few seconds in a
  // log; cleared when the measuring ends, however it ends.
  ProgressPrinter shown("lutbake report", ProgressPrinter::StyleFor(stderr, o.quiet));
  r.progress = [&shown](const std::string &line) { shown.Status(line); };
  return RunLibraryCall("report", o.outDir, [&] {
    const ReportOutcome outcome = Report(r);
    shown.Clear();
    if (!o.quiet)
      std::cerr << "lutbake report: " << outcome.rows.size() << " runs; wrote "
                << JoinNames(outcome.files) << "\n";
  });
}

}  // namespace lutbake::cli
