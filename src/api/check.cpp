#include "lutbake/api/check.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>

#include "bake_internal.h"
#include "lutbake/core/error.h"

namespace lutbake {

namespace {

const char *StatusName(CheckStatus s) {
  switch (s) {
    case CheckStatus::kPass: return "pass";
    case CheckStatus::kFail: return "FAIL";
    case CheckStatus::kSkipped: return "skip";
  }
  return "?";
}

std::string ReportJson(const CheckReport &report, const std::vector<std::string> &failed) {
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
  return out.dump(2);
}

// printf into a string.
template <typename... Args>
std::string Printed(const char *format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);
  std::string text(static_cast<size_t>(n) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, args...);
  text.pop_back();
  return text;
}

void SummariseReport(CheckOutcome *outcome) {
  const CheckReport &report = outcome->report;
  int passed = 0, skipped = 0;
  for (const CheckResult &r : report.results) {
    if (r.status == CheckStatus::kFail) {
      outcome->failed.push_back(r.subject + " " + r.check);
      // Each failure's reason, where it names the file (a truncated or
      // foreign .bin) and what was expected.
      outcome->failureText += "  " + r.subject + " " + r.check + ": " + r.detail + "\n";
    }
    passed += r.status == CheckStatus::kPass;
    skipped += r.status == CheckStatus::kSkipped;
  }
  outcome->passed = outcome->failed.empty();
  outcome->json = ReportJson(report, outcome->failed);
  outcome->text = Printed(
      "lutbake check %s: %zu checks, %d passed, %d skipped, %zu failed (%.1f s, %llu "
      "quadrature evaluations)\n",
      report.dir.c_str(), report.results.size(), passed, skipped, outcome->failed.size(),
      report.seconds, static_cast<unsigned long long>(report.referenceEvaluations));
  for (const CheckResult &r : report.results)
    outcome->text += Printed("  %s  %-7s %-11s %s\n", StatusName(r.status), r.subject.c_str(),
                             r.check.c_str(), r.detail.c_str());
  if (outcome->passed) outcome->text += "all checks passed\n";
}

// A preset directory's check in the same shape as a set's (one JSON shape
// for `check`): each file's values held to the integral is one check,
// subject the file, check "values", worst |stored - integral| against the
// errorMax it states; "preset" names the preset.
void SummarisePreset(const std::string &dir, double seconds, CheckOutcome *outcome) {
  const PresetCheck &check = outcome->preset;
  outcome->passed = check.pass;
  nlohmann::ordered_json out;
  out["dir"] = dir;
  out["preset"] = nlohmann::ordered_json::parse(check.json).value("preset", "");
  out["passed"] = check.pass;
  out["failed"] = nlohmann::ordered_json::array();
  out["seconds"] = seconds;
  out["referenceEvaluations"] = 0;
  out["files"] = nlohmann::ordered_json::array();
  out["checks"] = nlohmann::ordered_json::array();
  for (const PresetFileCheck &f : check.files) {
    const std::string path = (std::filesystem::path(dir) / f.file).string();
    out["files"].push_back(path);
    if (!f.pass) out["failed"].push_back(f.file + " values");
    nlohmann::ordered_json c;
    c["subject"] = f.file;
    c["check"] = "values";
    c["status"] = f.pass ? "pass" : "fail";
    c["detail"] = f.pass
                      ? Printed("max |stored - integral| %.2e (errorMax %.2e)", f.worst, f.errorMax)
                      : f.problem;
    c["worst"] = f.worst;
    c["allowed"] = f.errorMax;
    c["at"] = nlohmann::ordered_json::object();
    out["checks"].push_back(c);
    if (!f.pass) outcome->failureText += "  " + f.file + " values: " + f.problem + "\n";
    outcome->text += Printed("%-4s %-40s max |stored - integral| %.2e (errorMax %.2e)%s%s\n",
                             f.pass ? "pass" : "FAIL", f.file.c_str(), f.worst, f.errorMax,
                             f.pass ? "" : ": ", f.problem.c_str());
  }
  for (const auto &failed : out["failed"]) outcome->failed.push_back(failed.get<std::string>());
  outcome->json = out.dump(2);
  outcome->text = Printed("lutbake check %s (preset %s): %zu file%s, %zu failed (%.1f s)\n",
                          dir.c_str(), out["preset"].get<std::string>().c_str(), check.files.size(),
                          check.files.size() == 1 ? "" : "s", outcome->failed.size(), seconds) +
                  outcome->text + (outcome->passed ? "all checks passed\n" : "");
}

}  // namespace

namespace {

// `check FILE --as TABLE`: one table file under a stated convention.
CheckOutcome CheckOneFile(const CheckRequest &request) {
  CheckOutcome outcome;
  outcome.isTableFile = true;
  TableFileRequest r;
  r.path = request.dir;
  r.options = request.convention;
  r.threads = request.threads;
  const auto start = std::chrono::steady_clock::now();
  outcome.tableFile = CheckTableFile(r);
  const TableFileOutcome &t = outcome.tableFile;
  outcome.passed = t.passed;
  outcome.text = t.text;
  const std::string subject = std::filesystem::path(t.path).filename().string();
  if (!t.passed) {
    outcome.failed = {subject + " values"};
    outcome.failureText =
        Printed("  %s values: %zu of %zu values above their tolerance; max error %.2e\n",
                subject.c_str(), t.valuesAboveTolerance, t.valuesCompared, t.maxError);
  }
  // The shape of a set's report (one check, "values"), the file's own
  // judgement under "tableFile".
  nlohmann::ordered_json out;
  out["dir"] = t.path;
  out["passed"] = t.passed;
  out["failed"] = outcome.failed;
  out["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out["referenceEvaluations"] = 0;
  out["files"] = {t.path};
  nlohmann::ordered_json c;
  c["subject"] = subject;
  c["check"] = "values";
  c["status"] = t.passed ? "pass" : "fail";
  c["detail"] = Printed("max error %.2e, RMS %.2e; %zu of %zu values above their tolerance",
                        t.maxError, t.rmsError, t.valuesAboveTolerance, t.valuesCompared);
  c["worst"] = t.maxError;
  c["allowed"] = t.worstTolerance;
  c["at"] = {{"x", t.worstX},
             {"y", t.worstY},
             {"channel", t.worstChannel},
             {"mu", t.worstMu},
             {"roughness", t.worstRoughness}};
  out["checks"] = nlohmann::ordered_json::array({c});
  out["tableFile"] = nlohmann::ordered_json::parse(t.json);
  outcome.json = out.dump(2);
  return outcome;
}

}  // namespace

CheckOutcome Check(const CheckRequest &request) {
  namespace fs = std::filesystem;
  std::error_code ec;
  bool conventionGiven = false;
  for (const auto &[name, value] : request.convention) conventionGiven |= !value.empty();
  if (conventionGiven && fs::is_directory(request.dir, ec))
    throw UsageError("--as, --preset and the convention options judge one table file; " +
                     request.dir + " is a directory");
  if (conventionGiven &&
      (request.points != CheckRequest{}.points ||
       request.furnaceGrid != CheckRequest{}.furnaceGrid || request.seed != CheckRequest{}.seed))
    throw UsageError(
        "--points, --furnace-grid and --seed apply to a bake's directory, not to one table file "
        "judged with --as or --preset");
  if (conventionGiven) return CheckOneFile(request);
  if (!fs::is_directory(request.dir, ec))
    throw UsageError(request.dir +
                     (fs::exists(request.dir, ec) ? " is not a directory" : " does not exist") +
                     "; accepted: the directory of a bake");
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(request.threads)));
  CheckOutcome outcome;
  if (fs::exists(fs::path(request.dir) / "preset.json", ec)) {
    outcome.isPreset = true;
    const auto start = std::chrono::steady_clock::now();
    outcome.preset = CheckPresetDirectory(request.dir);
    SummarisePreset(request.dir,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                    &outcome);
    return outcome;
  }
  CheckOptions options;
  options.randomPoints = request.points;
  options.furnaceGrid = request.furnaceGrid;
  options.seed = request.seed;
  std::mutex progressMutex;
  if (request.progress)
    options.progress = [&](double fraction) {
      std::lock_guard<std::mutex> lock(progressMutex);
      request.progress(fraction);
    };
  outcome.report = CheckBakedSet(request.dir, options);
  SummariseReport(&outcome);
  return outcome;
}

}  // namespace lutbake
