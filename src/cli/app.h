// The lutbake command line as an object: the CLI11 app with its seven
// subcommands and their options, built without running anything, so that
// main() and the option-parsing fuzzer (tests/fuzz/cli_fuzzer.cpp) parse
// exactly the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "bake_command.h"
#include "check_command.h"
#include "eval_command.h"
#include "furnace_command.h"
#include "plan_command.h"
#include "preset_command.h"
#include "report_command.h"

namespace lutbake::cli {

struct LutbakeApp {
  CLI::App app{"", "lutbake"};
  BakeOptions bakeOptions;
  PlanCommandOptions planOptions;
  EvalOptions evalOptions;
  CheckCommandOptions checkOptions;
  IdentifyCommandOptions identifyOptions;
  ReportOptions reportOptions;
  FurnaceOptions furnaceOptions;
  bool presetsJson = false;
  std::string helpCommand;  // lutbake help COMMAND
  CLI::App *bake = nullptr, *plan = nullptr, *eval = nullptr, *check = nullptr, *identify = nullptr,
           *report = nullptr, *furnace = nullptr, *presets = nullptr, *help = nullptr;
};

// The app with every subcommand set up; parsing it (app.parse) validates the
// options and runs nothing. Not movable: the options are bound by address.
std::unique_ptr<LutbakeApp> MakeLutbakeApp();

// The exit status for a parse failure, after printing CLI11's help or
// version, or lutbake's message naming what was wrong (2 for usage errors).
int ReportParseError(LutbakeApp &cli, const CLI::ParseError &e, int argc, const char *const *argv);

// Runs the subcommand that was parsed; `commandLine` is recorded in the
// tables' metadata. Returns the exit status (1 for a runtime failure).
int RunParsedCommand(LutbakeApp &cli, const std::string &commandLine);

}  // namespace lutbake::cli
