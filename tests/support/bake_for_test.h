// Baking, planning and checking from a test through the library (lutbake.h)
// rather than the executable: a request for a scratch directory that the
// test fills as the command line would fill it from its options, the error a
// refused request throws, and a check report's statuses by name.
//
//   BakeRequest request = test::BakeRequestFor(dir);  // bake --out DIR
//   request.tables = {"E", "dfg"};                      //   --tables E,dfg
//   request.size = 16;                                  //   --size 16
//   Bake(request);
//
// A Bake that throws fails the test with the error's message (GoogleTest
// reports the exception), as a non-zero exit status of `lutbake bake` did.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "lutbake/lutbake.h"
#include "lutbake/validation/check.h"

namespace lutbake::test {

// `lutbake bake --out dir` with no other option. commandLine is left empty:
// the files record EquivalentCommandLine(request), as `lutbake bake` with the
// same options would write them.
inline BakeRequest BakeRequestFor(const std::filesystem::path &dir) {
  BakeRequest request;
  request.outputDirectory = dir.string();
  return request;
}

// The error Bake(request) throws, or nothing when it bakes. Its kind is what
// the command line turns into its exit status (kUsage: 2, kRuntime: 1), its
// message what it prints after "lutbake bake: ".
inline std::optional<Error> BakeError(const BakeRequest &request) {
  try {
    Bake(request);
  } catch (const Error &e) {
    return e;
  }
  return std::nullopt;
}

// The statuses of a check report, keyed "subject check" ("f82 texels",
// "f82+dfg at most"): "pass", "fail" or "skipped", as `lutbake check --json`
// spells them (check_json.h reads the same map from that JSON).
inline std::map<std::string, std::string> CheckStatuses(const CheckReport &report) {
  std::map<std::string, std::string> status;
  for (const CheckResult &r : report.results)
    status[r.subject + " " + r.check] = r.status == CheckStatus::kPass   ? "pass"
                                        : r.status == CheckStatus::kFail ? "fail"
                                                                         : "skipped";
  return status;
}

// A check report's results, one per line ("subject check: status: detail"),
// for a failure's message (what `lutbake check` printed).
inline std::string Describe(const CheckReport &report) {
  std::string text;
  for (const CheckResult &r : report.results)
    text += r.subject + " " + r.check + ": " +
            (r.status == CheckStatus::kPass   ? "pass"
             : r.status == CheckStatus::kFail ? "fail"
                                              : "skipped") +
            ": " + r.detail + "\n";
  return text;
}

}  // namespace lutbake::test
