// `lutbake check DIR`: validates a baked set without trusting the baker
// (check.h says what is checked). Human output by default, --json on
// request; exit 1 when a check fails, naming it.
#pragma once

#include <CLI/CLI.hpp>

#include "lutbake/api/check.h"

namespace lutbake::cli {

struct CheckCommandOptions {
  CheckRequest request;  // the options bind to its fields
  bool json = false, quiet = false;
};

void SetupCheckCommand(CLI::App &app, CheckCommandOptions &options);
int RunCheck(const CheckCommandOptions &options);

// `lutbake identify FILE`: the known convention FILE is closest to (identify.h).
struct IdentifyCommandOptions {
  TableFileRequest request;
  bool json = false;
};
void SetupIdentifyCommand(CLI::App &app, IdentifyCommandOptions &options);
int RunIdentify(const IdentifyCommandOptions &options);

}  // namespace lutbake::cli
