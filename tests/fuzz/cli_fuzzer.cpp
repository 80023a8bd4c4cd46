// libFuzzer target for the option parsing of every subcommand (scripts/
// fuzz.sh runs it). The input is a command line, one argument per line
// (cli_input.h); it is parsed by the app main() builds (src/cli/app.h), and
// nothing is run. Every input must parse or be refused with CLI11's
// ParseError (help and version requests included); anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/app.h"
#include "cli_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::vector<std::string> args =
      lutbake::fuzz::CommandLineOf(reinterpret_cast<const char *>(data), size);
  std::vector<const char *> argv;
  for (const std::string &arg : args) argv.push_back(arg.c_str());
  const auto cli = lutbake::cli::MakeLutbakeApp();
  try {
    cli->app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError &) {
  }
  return 0;
}
