// lutbake::Check: validates a baked directory without trusting the baker,
// as `lutbake check DIR` does: a bake's tables against the quadrature,
// identities and the furnace (validation/check.h), or, where DIR holds a
// preset.json, a preset's files against their integrals
// (CheckPresetDirectory, presets.h).
//
//   lutbake::CheckRequest request;
//   request.dir = "out";
//   const lutbake::CheckOutcome outcome = lutbake::Check(request);
//   std::cout << outcome.text;
//
// With a convention (CheckRequest::convention: --as TABLE, --preset NAME
// and the options of identify.h's ConventionOptions), DIR is one table file
// of any origin, judged by CheckTableFile (identify.h).
//
// Throws UsageError when DIR is not a directory (and no convention is given),
// UnreadableError when a table file cannot be read, IoError when its files
// cannot be read at all (an unusable preset.json); a table found wrong is a
// failed check instead.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "lutbake/api/identify.h"
#include "lutbake/api/presets.h"
#include "lutbake/validation/check.h"

namespace lutbake {

struct CheckRequest {
  std::string dir;
  int points = 256;       // random points per table through the bilinear lookup
  int furnaceGrid = 257;  // points per axis of the white furnace's (mu, r) grid
  uint64_t seed = 0;      // of the random points
  int threads = 0;        // 0: all cores
  // Fraction of the quadrature reference done (a bake's directory only),
  // from the checking threads one at a time.
  std::function<void(double fraction)> progress;
  // The convention a single table file is judged under, by option name
  // ("as", "preset", ...: ConventionOptions); empty values are not given.
  std::map<std::string, std::string> convention;
};

struct CheckOutcome {
  // Which of the two: a preset's directory (preset.json) or a bake's.
  bool isPreset = false;
  PresetCheck preset;  // isPreset
  bool isTableFile = false;
  TableFileOutcome tableFile;  // isTableFile
  CheckReport report;          // !isPreset
  bool passed = false;
  // `check --json`'s object.
  std::string json;
  // The summary as `check` prints it on stdout: for a bake, the count line
  // and one line per check (and "all checks passed" when all did); for a
  // preset, one line per file.
  std::string text;
  // A bake's failed checks as "subject check", and each one's reason as
  // `check` prints it on stderr after the list ("  subject check: detail").
  std::vector<std::string> failed;
  std::string failureText;
};

CheckOutcome Check(const CheckRequest &request);

}  // namespace lutbake
