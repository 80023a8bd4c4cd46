// lutbake: the command-line shell around the library. Parses options, calls
// the library, maps failures to exit codes (2 usage, 1 runtime, 0 success).
#include <CLI/CLI.hpp>
#include <iostream>

#include "bake_command.h"
#include "check_command.h"
#include "eval_command.h"
#include "furnace_command.h"
#include "interrupt.h"
#include "lutbake/tables/bake.h"
#include "plan_command.h"
#include "preset_command.h"
#include "report_command.h"

namespace {

std::string QuoteArgument(const std::string &arg) {
  if (!arg.empty() && arg.find_first_of(" \t\n'\"\\$") == std::string::npos) return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

int main(int argc, char **argv) {
  CLI::App app{
      "lutbake: bakes microfacet lookup tables (Kulla-Conty E, E_avg, F_avg and the "
      "split-sum DFG) with a measured error for every texel."};
  app.set_version_flag("--version", std::string("lutbake ") + lutbake::LutbakeVersion());
  app.require_subcommand(1);
  app.footer(
      "Example:\n  lutbake bake --out out          # the four default tables\n"
      "  lutbake check out              # validate a bake without trusting it\n"
      "  lutbake plan --scene car.gltf   # what a scene needs, and why\n"
      "  lutbake eval --table E --mu 0.5 --roughness 0.3\n"
      "  lutbake report --out report    # error against time of every estimator\n"
      "  lutbake bake --preset filament --out dfg   # an engine's own table, exact\n"
      "Run 'lutbake COMMAND --help' (bake, plan, check, eval, report, furnace, presets) for "
      "their options.");
  lutbake::cli::BakeOptions bakeOptions;
  CLI::App *bake =
      app.add_subcommand("bake", "Bake tables into a directory (EXR, .bin, C++ header)");
  lutbake::cli::SetupBakeCommand(*bake, bakeOptions);
  lutbake::cli::PlanCommandOptions planOptions;
  CLI::App *plan = app.add_subcommand(
      "plan",
      "What glTF scenes and manifests need: tables, narrowed ranges, and why the rest is "
      "left out");
  lutbake::cli::SetupPlanCommand(*plan, planOptions);
  lutbake::cli::EvalOptions evalOptions;
  CLI::App *eval = app.add_subcommand(
      "eval", "Evaluate any table at any points, with the error bound of each value");
  lutbake::cli::SetupEvalCommand(*eval, evalOptions);
  lutbake::cli::CheckCommandOptions checkOptions;
  CLI::App *check = app.add_subcommand(
      "check", "Validate a baked directory against the quadrature, identities and the furnace");
  lutbake::cli::SetupCheckCommand(*check, checkOptions);
  lutbake::cli::ReportOptions reportOptions;
  CLI::App *report = app.add_subcommand(
      "report", "Measure real error against run time for every estimator (csv, md, svg)");
  lutbake::cli::SetupReportCommand(*report, reportOptions);

  lutbake::cli::FurnaceOptions furnaceOptions;
  CLI::App *furnace = app.add_subcommand(
      "furnace", "The white furnace of a classic reflection model: albedo, average, pictures");
  lutbake::cli::SetupFurnaceCommand(*furnace, furnaceOptions);

  bool presetsJson = false;
  CLI::App *presets = app.add_subcommand(
      "presets", "The engine presets of bake --preset: each engine's textures, exact");
  lutbake::cli::SetupPresetsCommand(*presets, presetsJson);

  lutbake::cli::IgnoreFileSizeSignal();
  std::string commandLine = "lutbake";
  for (int i = 1; i < argc; ++i) commandLine += " " + QuoteArgument(argv[i]);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp &e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion &e) {
    return app.exit(e);
  } catch (const CLI::ParseError &e) {
    // No command recognised: CLI11 says only that one is required; name
    // what was given instead and the commands there are.
    if (app.get_subcommands().empty()) {
      std::string commands;
      for (const CLI::App *sub : app.get_subcommands({}))
        commands += (commands.empty() ? "" : ", ") + sub->get_name();
      if (argc > 1)
        std::cerr << "lutbake: '" << argv[1] << "' is not a command; accepted: " << commands
                  << "\n";
      else
        std::cerr << "lutbake: a command is required; accepted: " << commands << "\n";
      std::cerr << "Run 'lutbake COMMAND --help' for the accepted options.\n";
      return 2;
    }
    std::cerr << "lutbake: " << e.what() << "\n";
    // Name the subcommand being parsed, if any, in the pointer to its help.
    std::string command = "COMMAND";
    for (const CLI::App *sub : app.get_subcommands({}))
      for (int i = 1; i < argc; ++i)
        if (argv[i] == sub->get_name()) command = sub->get_name();
    std::cerr << "Run 'lutbake " << command << " --help' for the accepted options.\n";
    return 2;
  }
  try {
    if (bake->parsed()) return lutbake::cli::RunBake(bakeOptions, commandLine, *bake);
    if (plan->parsed()) return lutbake::cli::RunPlan(planOptions);
    if (eval->parsed()) return lutbake::cli::RunEval(evalOptions, *eval);
    if (check->parsed()) return lutbake::cli::RunCheck(checkOptions);
    if (report->parsed()) return lutbake::cli::RunReport(reportOptions);
    if (furnace->parsed()) return lutbake::cli::RunFurnace(furnaceOptions, *furnace);
    if (presets->parsed()) return lutbake::cli::RunPresets(presetsJson);
  } catch (const std::exception &e) {
    std::cerr << "lutbake: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
