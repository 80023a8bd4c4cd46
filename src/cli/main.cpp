// lutbake: the command-line shell around the library. Parses options, calls
// the library, maps failures to exit codes (2 usage, 1 runtime, 0 success).
// The app itself (subcommands, options) is built in app.cpp.
#include <string>

#include "app.h"
#include "interrupt.h"

namespace {

std::string QuoteArgument(const std::string &arg) {
  if (!arg.empty() && arg.find_first_of(" \t\n'\"\\$") == std::string::npos) return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

int main(int argc, char **argv) {
  const auto cli = lutbake::cli::MakeLutbakeApp();
  lutbake::cli::IgnoreFileSizeSignal();
  std::string commandLine = "lutbake";
  for (int i = 1; i < argc; ++i) commandLine += " " + QuoteArgument(argv[i]);
  try {
    cli->app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    return lutbake::cli::ReportParseError(*cli, e, argc, argv);
  }
  return lutbake::cli::RunParsedCommand(*cli, commandLine);
}
