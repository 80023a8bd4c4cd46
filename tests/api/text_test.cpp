// lutbake::WrapText: the help's layout at 80 columns.
#include "lutbake/api/text.h"

#include <gtest/gtest.h>

#include <sstream>

namespace lutbake {
namespace {

TEST(Text, WrapKeepsEveryLineWithinTheWidthAndEveryWord) {
  const std::string prose =
      "Refine every texel of E, Eavg and dfg until its integration bound is at most EPS: by the "
      "quadrature (adding orders), or with a sampled --estimator in rounds that double the "
      "samples, switching to the quadrature where that is cheaper.";
  const std::string wrapped = WrapText(prose, 80, 30);
  std::stringstream lines(wrapped);
  std::string words, line;
  int count = 0;
  for (; std::getline(lines, line); ++count) {
    // The first line follows a 30-column label; the others are indented.
    EXPECT_LE((count == 0 ? 30 : 0) + line.size(), 80u) << line;
    if (count > 0) {
      EXPECT_EQ(line.substr(0, 30), std::string(30, ' '));
    }
    words += (words.empty() ? "" : " ") + line.substr(line.find_first_not_of(' '));
  }
  EXPECT_EQ(words, prose);
  EXPECT_GE(count, 5);  // 225 characters in lines of at most 50
}

TEST(Text, WrapKeepsLineBreaksAndTheIndentOfExamples) {
  EXPECT_EQ(WrapText("Example:\n  lutbake bake --out out    # four tables", 80, 0),
            "Example:\n  lutbake bake --out out    # four tables");
  EXPECT_EQ(WrapText("a b c d", 3, 0), "a b\nc d");
  EXPECT_EQ(WrapText("a b c", 6, 2), "a b\n  c");
  // A word wider than the room is not cut.
  EXPECT_EQ(WrapText("x averyveryverylongword y", 10, 0), "x\naveryveryverylongword\ny");
  EXPECT_EQ(WrapText("", 80, 4), "");
  // A list wider than the room breaks after its commas.
  EXPECT_EQ(WrapText("(default uniform,cosine,ndf,vndf)", 12, 0),
            "(default\nuniform,\ncosine,ndf,\nvndf)");
}

}  // namespace
}  // namespace lutbake
