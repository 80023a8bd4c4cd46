// Helpers shared by the subcommands: list parsing, validators whose
// messages name the value and what is accepted, the shared options, and the
// mapping of a library call's failure to the exit status.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "lutbake/api/eval.h"
#include "lutbake/api/names.h"
#include "lutbake/api/numbers.h"

namespace lutbake::cli {

std::vector<std::string> SplitList(const std::string &list);

// A validator that accepts one of `names` and says which ones when it fails.
CLI::Validator OneOf(std::vector<std::string> names);
// A comma-separated list of items from `names`, none repeated.
CLI::Validator ListOf(std::vector<std::string> names);
// A real number in [lo, hi], given in decimal or exponent notation.
CLI::Validator RealInRange(double lo, double hi, const std::string &accepted);
CLI::Validator CppNamespace();  // lutbake::NamespaceProblem

// A whole number in [lo, hi] (lutbake::WholeNumberProblem).
template <typename T>
CLI::Validator InRange(T lo, T hi, const std::string &what) {
  const std::string accepted = std::to_string(lo) + " to " + std::to_string(hi) + " " + what;
  return CLI::Validator(
      [lo, hi, accepted](std::string &value) {
        return WholeNumberProblem(value, static_cast<uint64_t>(lo), static_cast<uint64_t>(hi),
                                  accepted);
      },
      "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// The model options (eval.h's ModelOptions: --ndf, --smith, --fresnel, ...),
// each bound to values[option], which starts at its default; help "MEANING;
// tables T1, T2". `only` keeps just those options, their help without the
// tables (report measures its own).
void AddModelOptions(CLI::App &app, std::map<std::string, std::string> &values,
                     const std::vector<std::string> &only = {});
// The model options given on the command line (already validated) into a
// request's models (BakeRequest, EvalRequest).
template <typename Request>
void ModelsOf(const std::map<std::string, std::string> &values, CLI::App &app, Request *r) {
  std::map<std::string, std::string> given;
  for (const auto &[option, value] : values)
    if (app.count("--" + option) > 0) given[option] = value;
  ModelsNamed(given).SetIn(r);
}

// The options that state a table file's convention (identify.h's
// ConventionOptions), each bound to values[name].
void AddConventionOptions(CLI::App &app, std::map<std::string, std::string> &values);

// --seed S (any unsigned 64-bit integer) and --threads N (1 to 1024, default
// all cores), as every subcommand spells them; `seedHelp` says what it seeds,
// `threadsHelp` is appended to the --threads help.
void AddSeedOption(CLI::App &app, uint64_t &seed, const std::string &seedHelp);
void AddThreadsOption(CLI::App &app, int &threads, const std::string &threadsHelp = "");

// Runs one library call of `command` and maps its failure to the exit
// status: a lutbake::Error prints "lutbake COMMAND: message" (2 for a
// usage error, 1 otherwise), a cancellation "interrupted by SIGINT; nothing
// written to DIR" (128 + the signal), running out of memory "out of
// memory" (1). Returns 0 when `call` returns.
int RunLibraryCall(const std::string &command, const std::string &outDir,
                   const std::function<void()> &call);

}  // namespace lutbake::cli
