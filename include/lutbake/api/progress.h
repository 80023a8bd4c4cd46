// Long work, shown as it goes: on a terminal one line redrawn in place (a
// bar, the percentage and the time left), in a log a line every few seconds
// (so that a run under a build system or CI is never silent for long, and a
// short one adds nothing). Every command that can take over a second (bake,
// a preset bake, check, report) reports through one of these.
#pragma once

#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

namespace lutbake {

class ProgressPrinter {
 public:
  enum class Style { kNone, kBar, kLines };
  // kNone when quiet, kBar when `stream` is a terminal, else kLines.
  static Style StyleFor(FILE *stream, bool quiet);

  // `command` starts each line ("lutbake bake"); in kLines style a line is
  // printed at most every `lineSeconds`.
  ProgressPrinter(std::string command, Style style, FILE *stream = stderr,
                  double lineSeconds = 5.0);
  ~ProgressPrinter();  // clears the bar

  // `fraction` in [0, 1] of the part `what` (a table's name); callable from
  // any thread. The time left is estimated from the part's own pace.
  void Update(const std::string &what, double fraction);
  // A finished status line of its own (report's "estimator 3 of 7: ..."):
  // redrawn in place on a terminal, printed every `lineSeconds` in a log.
  void Status(const std::string &text);
  // Clears the bar line, so that what follows starts at column 0.
  void Clear();

  // The text Update shows: "glass_E [#######           ]  30%  about 4 s
  // left" (`bar` false: without the bar). Seconds left < 0: not yet known.
  static std::string Describe(const std::string &what, double fraction, double secondsLeft,
                              bool bar);

 private:
  void Show(const std::string &text, bool finished);

  std::string command_;
  Style style_;
  FILE *stream_;
  double lineSeconds_;
  std::mutex mutex_;
  std::string what_;
  int percent_ = -1;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point partStart_, lastLine_;
};

}  // namespace lutbake
