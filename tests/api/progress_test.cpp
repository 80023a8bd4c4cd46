// ProgressPrinter: the text of a progress line, a bar redrawn in place on a
// terminal and cleared, lines at most every few seconds in a log, nothing
// when quiet.
#include "lutbake/api/progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace lutbake {
namespace {

// What a printer of `style` writes for `updates` (fractions of table "E").
std::string Printed(ProgressPrinter::Style style, double lineSeconds,
                    std::initializer_list<double> updates) {
  char *buffer = nullptr;
  size_t size = 0;
  FILE *stream = open_memstream(&buffer, &size);
  {
    ProgressPrinter printer("lutbake bake", style, stream, lineSeconds);
    for (double f : updates) printer.Update("E", f);
  }
  std::fclose(stream);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

TEST(Progress, DescribesPercentBarAndTimeLeft) {
  EXPECT_EQ(ProgressPrinter::Describe("E", 0.2, 4.2, true),
            "E [#####                    ]  20%  about 5 s left");
  EXPECT_EQ(ProgressPrinter::Describe("dfg", 0.5, -1.0, false), "dfg  50%");
  EXPECT_EQ(ProgressPrinter::Describe("dfg", 1.0, 3.0, false), "dfg 100%");
}

TEST(Progress, ABarIsRedrawnInPlaceAndCleared) {
  const std::string text = Printed(ProgressPrinter::Style::kBar, 5.0, {0.1, 0.5});
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_NE(text.find("\r\033[Klutbake bake: E [##"), std::string::npos) << text;
  EXPECT_NE(text.find(" 50%"), std::string::npos) << text;
  // The destructor clears the line it drew.
  EXPECT_EQ(text.substr(text.size() - 4), "\r\033[K");
}

TEST(Progress, ALogGetsWholeLinesAtMostEveryFewSeconds) {
  // Within the interval: nothing (a short run adds no line).
  EXPECT_EQ(Printed(ProgressPrinter::Style::kLines, 60.0, {0.1, 0.5, 0.9}), "");
  // An interval of 0: a line per new percentage, no escape codes, no bar.
  const std::string text = Printed(ProgressPrinter::Style::kLines, 0.0, {0.1, 0.1, 0.5});
  EXPECT_EQ(text, "lutbake bake: E  10%\nlutbake bake: E  50%\n");
}

TEST(Progress, QuietPrintsNothing) {
  EXPECT_EQ(ProgressPrinter::StyleFor(stderr, true), ProgressPrinter::Style::kNone);
  EXPECT_EQ(Printed(ProgressPrinter::Style::kNone, 0.0, {0.1, 0.5}), "");
}

}  // namespace
}  // namespace lutbake
