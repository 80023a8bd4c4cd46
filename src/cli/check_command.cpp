#include "check_command.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>

#include "cli_util.h"
#include "lutbake/formats/writer.h"
#include "lutbake/validation/check.h"
#include "preset_command.h"

namespace lutbake::cli {

namespace {

const char *StatusName(CheckStatus s) {
  switch (s) {
    case CheckStatus::kPass: return "pass";
    case CheckStatus::kFail: return "FAIL";
    case CheckStatus::kSkipped: return "skip";
  }
  return "?";
}

}  // namespace

void SetupCheckCommand(CLI::App &app, CheckCommandOptions &o) {
  app.add_option("dir", o.dir, "Directory of a bake (T.exr, T.bin, T.h, T.err.exr)")
      ->required()
      ->type_name("DIR");
  app.add_option("--points", o.points,
                 "Random points per table at which the bilinear lookup is compared with the "
                 "quadrature")
      ->capture_default_str()
      ->type_name("N")
      ->check(InRange(0, 100000, "points"));
  app.add_option("--furnace-grid", o.furnaceGrid,
                 "Points per axis of the (mu, r) grid of the white-furnace test")
      ->capture_default_str()
      ->type_name("N")
      ->check(InRange(2, 4097, "points per axis"));
  AddSeedOption(app, o.seed, "Seed of the random points");
  AddThreadsOption(app, o.threads);
  app.add_flag("--json", o.json, "Print the results as one JSON object on stdout");
  app.footer(
      "Checks metadata, formats, NaN/Inf, ranges, every texel against the quadrature, random\n"
      "points through the bilinear lookup, A + B = E, E_avg against E, monotonicity, Schlick's\n"
      "closed form and the Kulla-Conty white furnace. Exit 0 when all pass, 1 when one fails.\n"
      "Example:\n  lutbake bake --out out && lutbake check out");
}

int RunCheck(const CheckCommandOptions &o) {
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec)) {
    std::cerr << "lutbake check: " << o.dir
              << (std::filesystem::exists(o.dir, ec) ? " is not a directory" : " does not exist")
              << "; accepted: the directory of a bake\n";
    return 2;
  }
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(o.threads)));
  // A preset's directory: its files against the preset (preset_command.h).
  if (std::filesystem::exists(std::filesystem::path(o.dir) / "preset.json", ec))
    return RunPresetCheck(o.dir, o.json);
  CheckOptions options;
  options.randomPoints = o.points;
  options.furnaceGrid = o.furnaceGrid;
  options.seed = o.seed;
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  std::mutex progressMutex;
  if (tty)
    options.progress = [&](double fraction) {
      std::lock_guard<std::mutex> lock(progressMutex);
      std::fprintf(stderr, "\rlutbake check: quadrature reference %3.0f%%", 100.0 * fraction);
    };
  CheckReport report;
  try {
    report = CheckBakedSet(o.dir, options);
  } catch (const IoError &e) {
    std::cerr << "lutbake check: " << e.what() << "\n";
    return 1;
  }
  if (tty) std::fprintf(stderr, "\r%60s\r", "");
  std::vector<std::string> failed;
  int passed = 0, skipped = 0;
  for (const CheckResult &r : report.results) {
    if (r.status == CheckStatus::kFail) failed.push_back(r.subject + " " + r.check);
    passed += r.status == CheckStatus::kPass;
    skipped += r.status == CheckStatus::kSkipped;
  }
  if (o.json) {
    nlohmann::ordered_json out;
    out["dir"] = report.dir;
    out["passed"] = report.passed();
    out["failed"] = failed;
    out["seconds"] = report.seconds;
    out["referenceEvaluations"] = report.referenceEvaluations;
    out["files"] = report.files;
    out["checks"] = nlohmann::ordered_json::array();
    for (const CheckResult &r : report.results) {
      nlohmann::ordered_json c;
      c["subject"] = r.subject;
      c["check"] = r.check;
      c["status"] = r.status == CheckStatus::kPass   ? "pass"
                    : r.status == CheckStatus::kFail ? "fail"
                                                     : "skipped";
      c["detail"] = r.detail;
      c["worst"] = r.worst;
      if (r.allowed > 0.0) c["allowed"] = r.allowed;
      nlohmann::ordered_json at = nlohmann::ordered_json::object();
      for (const auto &[name, value] : r.at) at[name] = value;
      c["at"] = at;
      out["checks"].push_back(c);
    }
    std::cout << out.dump(2) << "\n";
  } else {
    std::printf(
        "lutbake check %s: %zu checks, %d passed, %d skipped, %zu failed (%.1f s, %llu "
        "quadrature evaluations)\n",
        report.dir.c_str(), report.results.size(), passed, skipped, failed.size(), report.seconds,
        static_cast<unsigned long long>(report.referenceEvaluations));
    for (const CheckResult &r : report.results)
      std::printf("  %s  %-7s %-11s %s\n", StatusName(r.status), r.subject.c_str(), r.check.c_str(),
                  r.detail.c_str());
  }
  if (!failed.empty()) {
    std::cerr << "lutbake check: FAILED: " << JoinNames(failed) << "\n";
    // Each failure's reason on stderr too, where it names the file (a
    // truncated or foreign .bin) and what was expected.
    for (const CheckResult &r : report.results)
      if (r.status == CheckStatus::kFail)
        std::cerr << "  " << r.subject << " " << r.check << ": " << r.detail << "\n";
    return 1;
  }
  if (!o.json) std::printf("all checks passed\n");
  return 0;
}

}  // namespace lutbake::cli
