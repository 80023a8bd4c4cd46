#include "app.h"

#include <algorithm>
#include <iostream>

#include "cli_util.h"
#include "lutbake/api/text.h"
#include "lutbake/tables/bake.h"

namespace lutbake::cli {

namespace {

constexpr size_t kHelpWidth = 80;

// The help at 80 columns, an option as "--ndf NAME  Microfacet distribution
// [one of: ggx, beckmann] (default ggx)": the type plain, what the
// validators accept and the default after the description.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option *opt) const override {
    if (opt->get_type_size() == 0) return "";
    const std::string type = opt->get_type_name();
    std::string plain = type.substr(0, type.find(':'));
    if (plain == "TEXT") plain = type.find(":comma-separated") != type.npos ? "LIST" : "NAME";
    return " " + plain + (opt->get_required() ? " (required)" : "");
  }
  std::string make_option_desc(const CLI::Option *opt) const override {
    const std::string type = opt->get_type_name();
    std::string text = opt->get_description();
    const size_t colon = type.find(':');
    if (colon != type.npos)
      text += type[colon + 1] == '[' ? " " + type.substr(colon + 1)
                                     : " [" + type.substr(colon + 1) + "]";
    if (!opt->get_default_str().empty()) text += " (default " + opt->get_default_str() + ")";
    return text;
  }
  std::string make_option(const CLI::Option *opt, bool positional) const override {
    return Entry(make_option_name(opt, positional) + make_option_opts(opt), make_option_desc(opt));
  }
  std::string make_subcommand(const CLI::App *sub) const override {
    return Entry(sub->get_name(), sub->get_description());
  }
  std::string make_description(const CLI::App *app) const override {
    return WrapText(app->get_description(), kHelpWidth, 0) + "\n";
  }
  std::string make_footer(const CLI::App *app) const override {
    return app->get_footer().empty() ? "" : WrapText(app->get_footer(), kHelpWidth, 0) + "\n";
  }

 private:
  // "  NAME   description", the description wrapped beside the name column.
  std::string Entry(const std::string &name, const std::string &description) const {
    std::string line = "  " + name;
    line += line.size() + 2 > column_width_ ? "\n" + std::string(column_width_, ' ')
                                            : std::string(column_width_ - line.size(), ' ');
    return line + WrapText(description, kHelpWidth, column_width_) + "\n";
  }
};

}  // namespace

std::unique_ptr<LutbakeApp> MakeLutbakeApp() {
  auto cli = std::make_unique<LutbakeApp>();
  CLI::App &app = cli->app;
  app.formatter(std::make_shared<HelpFormatter>());
  app.description("lutbake: microfacet lookup tables with a measured error for every texel");
  app.set_version_flag("--version", std::string("lutbake ") + LutbakeVersion());
  app.require_subcommand(1);
  app.footer(
      "Example:\n  lutbake bake --out out          # the four default tables\n"
      "  lutbake check out              # validate a bake without trusting it\n"
      "  lutbake plan --scene car.gltf   # what a scene needs, and why\n"
      "  lutbake eval --table E --mu 0.5 --roughness 0.3\n"
      "  lutbake report --out report    # error against time of every estimator\n"
      "  lutbake bake --preset filament --out dfg   # an engine's own table, exact\n"
      "Run 'lutbake help COMMAND' for a command's options.");
  cli->bake = app.add_subcommand("bake", "Bake tables into a directory (EXR, .bin, C++ header)");
  SetupBakeCommand(*cli->bake, cli->bakeOptions);
  cli->plan = app.add_subcommand(
      "plan",
      "What glTF scenes and manifests need: tables, narrowed ranges, and why the rest is "
      "left out");
  SetupPlanCommand(*cli->plan, cli->planOptions);
  cli->eval = app.add_subcommand(
      "eval", "Evaluate any table at any points, with the error bound of each value");
  SetupEvalCommand(*cli->eval, cli->evalOptions);
  cli->check = app.add_subcommand(
      "check", "Validate a baked directory against the quadrature, identities and the furnace");
  SetupCheckCommand(*cli->check, cli->checkOptions);
  cli->report = app.add_subcommand(
      "report", "Measure real error against run time for every estimator (csv, md, svg)");
  SetupReportCommand(*cli->report, cli->reportOptions);
  cli->furnace = app.add_subcommand(
      "furnace", "The white furnace of a classic reflection model: albedo, average, pictures");
  SetupFurnaceCommand(*cli->furnace, cli->furnaceOptions);
  cli->identify =
      app.add_subcommand("identify", "Name the convention of any table file, and its error");
  SetupIdentifyCommand(*cli->identify, cli->identifyOptions);
  cli->presets = app.add_subcommand(
      "presets", "The engine presets of bake --preset: each engine's textures, exact");
  SetupPresetsCommand(*cli->presets, cli->presetsJson);
  cli->help = app.add_subcommand("help", "'lutbake help bake' is 'lutbake bake --help'");
  std::vector<std::string> commands;
  for (CLI::App *sub : app.get_subcommands({})) {
    sub->set_version_flag("--version", app.version());
    if (sub != cli->help) commands.push_back(sub->get_name());
  }
  cli->help->add_option("command", cli->helpCommand)->type_name("COMMAND")->check(OneOf(commands));
  return cli;
}

namespace {

// CLI11's message for `e`, said as a person would: the argument that is no
// option (and the option it is near), the option given twice or without its
// value, what a missing required option or argument is.
std::string ParseMessage(const CLI::ParseError &e, CLI::App &app, CLI::App &command) {
  const std::string what = e.what();
  const std::string name = what.substr(0, std::min(what.find(':'), what.find(" is required")));
  const CLI::Option *option = command.get_option_no_throw(name);
  // An unknown option first: it may be why a required one is missing.
  std::vector<std::string> options;
  for (const CLI::Option *o : command.get_options())
    for (const std::string &l : o->get_lnames()) options.push_back("--" + l);
  const std::vector<std::string> extra = app.remaining(true);
  for (const std::string &arg : extra)
    if (arg.size() > 1 && arg[0] == '-')
      return "'" + arg + "' is not an option of " + command.get_name() +
             DidYouMean(arg.substr(0, arg.find('=')), options);
  if (dynamic_cast<const CLI::ExtrasError *>(&e))
    return "'" + (extra.empty() ? what : extra[0]) +
           "' follows no option that takes it (a list of values is one comma-separated word)";
  if (dynamic_cast<const CLI::ArgumentMismatch *>(&e) && what.find("At Most") != what.npos)
    return name + " is given more than once (a list of values is one comma-separated word)";
  if (dynamic_cast<const CLI::ArgumentMismatch *>(&e) && option) {
    const std::string value = HelpFormatter().make_option_opts(option);
    return name + " needs a value:" + value.substr(0, value.find(" (required)"));
  }
  if (dynamic_cast<const CLI::RequiredError *>(&e) && option)
    return (option->get_positional() ? option->get_type_name() : name) +
           " is required: " + option->get_description();
  return what;
}

}  // namespace

int ReportParseError(LutbakeApp &cli, const CLI::ParseError &e, int argc, const char *const *argv) {
  CLI::App &app = cli.app;
  if (dynamic_cast<const CLI::CallForHelp *>(&e) || dynamic_cast<const CLI::CallForAllHelp *>(&e) ||
      dynamic_cast<const CLI::CallForVersion *>(&e))
    return app.exit(e);
  // No command recognised: CLI11 says only that one is required; name
  // what was given instead and the commands there are.
  if (app.get_subcommands().empty()) {
    std::vector<std::string> commands;
    for (const CLI::App *sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    if (argc > 1)
      std::cerr << "lutbake: '" << argv[1]
                << "' is not a command; accepted: " << JoinNames(commands)
                << DidYouMean(argv[1], commands) << "\n";
    else
      std::cerr << "lutbake: a command is required; accepted: " << JoinNames(commands) << "\n";
    std::cerr << "Run 'lutbake COMMAND --help' for the accepted options.\n";
    return 2;
  }
  CLI::App &command = *app.get_subcommands().back();
  std::cerr << "lutbake " << command.get_name() << ": " << ParseMessage(e, app, command) << "\n"
            << "Run 'lutbake " << command.get_name() << " --help' for the accepted options.\n";
  return 2;
}

int RunParsedCommand(LutbakeApp &cli, const std::string &commandLine) {
  try {
    if (cli.bake->parsed()) return RunBake(cli.bakeOptions, commandLine, *cli.bake);
    if (cli.plan->parsed()) return RunPlan(cli.planOptions);
    if (cli.eval->parsed()) return RunEval(cli.evalOptions, *cli.eval);
    if (cli.check->parsed()) return RunCheck(cli.checkOptions);
    if (cli.identify->parsed()) return RunIdentify(cli.identifyOptions);
    if (cli.report->parsed()) return RunReport(cli.reportOptions);
    if (cli.furnace->parsed()) return RunFurnace(cli.furnaceOptions, *cli.furnace);
    if (cli.presets->parsed()) return RunPresets(cli.presetsJson);
    if (cli.help->parsed() && !cli.helpCommand.empty())
      std::cout << cli.app.get_subcommand(cli.helpCommand)->help(cli.app.get_name());
    else if (cli.help->parsed())
      std::cout << cli.app.get_formatter()->make_help(&cli.app, cli.app.get_name(), {});
  } catch (const std::exception &e) {
    std::cerr << "lutbake: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace lutbake::cli
