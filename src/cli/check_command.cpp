#include "check_command.h"

#include <cstdio>
#include <iostream>

#include "cli_util.h"
#include "lutbake/api/progress.h"

namespace lutbake::cli {

void SetupCheckCommand(CLI::App &app, CheckCommandOptions &o) {
  app.add_option("dir", o.request.dir,
                 "Directory of a bake (T.exr, T.bin, T.h, T.err.exr), or with --as or --preset "
                 "one table file")
      ->required()
      ->type_name("DIR");
  AddConventionOptions(app, o.request.convention);
  app.add_option("--points", o.request.points,
                 "Random points per table at which the bilinear lookup is compared with the "
                 "quadrature")
      ->capture_default_str()
      ->type_name("N")
      ->check(InRange(0, 100000, "points"));
  app.add_option("--furnace-grid", o.request.furnaceGrid,
                 "Points per axis of the (mu, r) grid of the white-furnace test")
      ->capture_default_str()
      ->type_name("N")
      ->check(InRange(2, 4097, "points per axis"));
  AddSeedOption(app, o.request.seed, "Seed of the random points");
  AddThreadsOption(app, o.request.threads);
  app.add_flag("--json", o.json, "Print the results as one JSON object on stdout");
  app.add_flag("-q,--quiet", o.quiet, "No progress line (errors are still printed)");
  app.footer(
      "Checks metadata, formats, NaN/Inf, ranges, every texel against the quadrature, random\n"
      "points through the bilinear lookup, A + B = E, E_avg against E, monotonicity, Schlick's\n"
      "closed form and the Kulla-Conty white furnace. Exit 0 when all pass, 1 when one fails.\n"
      "A FILE with --as or --preset: every texel against the exact value; exit 3 when it cannot\n"
      "be read.\nExample:\n  lutbake bake --out out && lutbake check out\n"
      "  lutbake check brdf.png --as dfg --flip y --error-image error.png");
}

int RunCheck(const CheckCommandOptions &o) {
  CheckRequest request = o.request;
  ProgressPrinter shown("lutbake check", ProgressPrinter::StyleFor(stderr, o.quiet));
  request.progress = [&shown](double f) { shown.Update("quadrature reference", f); };
  bool passed = false;
  const int status = RunLibraryCall("check", o.request.dir, [&] {
    const CheckOutcome outcome = Check(request);
    shown.Clear();
    std::cout << (o.json ? outcome.json + "\n" : outcome.text);
    if (!outcome.failed.empty())
      std::cerr << "lutbake check: FAILED: " << JoinNames(outcome.failed) << "\n"
                << outcome.failureText;
    passed = outcome.passed;
  });
  return status != 0 ? status : passed ? 0 : 1;
}

void SetupIdentifyCommand(CLI::App &app, IdentifyCommandOptions &o) {
  app.add_option("file", o.request.path,
                 "Any table file (PNG, EXR, DDS, KTX2, HDR, C/C++/JS array)")
      ->required()
      ->type_name("FILE");
  app.add_option("--preset", o.request.options["preset"], "Try only this preset's textures")
      ->type_name("NAME")
      ->check(OneOf(PresetNames()));
  AddThreadsOption(app, o.request.threads);
  app.add_flag("--json", o.json, "Print the match as one JSON object on stdout");
  app.footer(
      "Exit 0 when a convention matches, 1 when none does, 3 when FILE cannot be read.\n"
      "Example:\n  lutbake identify brdf_lut.png");
}

int RunIdentify(const IdentifyCommandOptions &o) {
  bool matched = false;
  const int status = RunLibraryCall("identify", o.request.path, [&] {
    const TableFileOutcome outcome = IdentifyTable(o.request);
    std::cout << (o.json ? outcome.json + "\n" : outcome.text);
    matched = outcome.matched;
  });
  return status != 0 ? status : matched ? 0 : 1;
}

}  // namespace lutbake::cli
