// `lutbake check DIR`: validates a baked set without trusting the baker
// (check.h says what is checked). Human output by default, --json on
// request; exit 1 when a check fails, naming it.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace lutbake::cli {

struct CheckCommandOptions {
  std::string dir;
  int points = 256;
  int furnaceGrid = 257;
  uint64_t seed = 0;
  int threads = 0;
  bool json = false;
};

void SetupCheckCommand(CLI::App &app, CheckCommandOptions &options);
int RunCheck(const CheckCommandOptions &options);

}  // namespace lutbake::cli
