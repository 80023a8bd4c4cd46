// lutbake::WholeNumberProblem and RealNumberProblem: what the command
// line's number options accept, and the message for what they refuse.
#include "lutbake/api/numbers.h"

#include <gtest/gtest.h>

namespace lutbake {
namespace {

bool Says(const std::string &problem, const std::string &what) {
  return problem.find(what) != std::string::npos;
}

TEST(Numbers, WholeNumbersAreDigitsInRange) {
  EXPECT_EQ(WholeNumberProblem("1", 1, 4096, "1 to 4096"), "");
  EXPECT_EQ(WholeNumberProblem("4096", 1, 4096, "1 to 4096"), "");
  EXPECT_EQ(WholeNumberProblem("18446744073709551615", 0, UINT64_MAX, "any"), "");
  EXPECT_EQ(WholeNumberProblem("0", 1, 4096, "1 to 4096"),
            "'0' is out of range; accepted: 1 to 4096");
  EXPECT_TRUE(
      Says(WholeNumberProblem("18446744073709551616", 0, UINT64_MAX, "any"), "out of range"));
  for (const char *bad : {"", "-4", "+4", " 4", "4 ", "8.5", "1e3", "nan", "0x10"})
    EXPECT_EQ(WholeNumberProblem(bad, 1, 4096, "1 to 4096"),
              "'" + std::string(bad) + "' is not a whole number; accepted: 1 to 4096");
}

TEST(Numbers, RealNumbersAreFiniteAndInRange) {
  EXPECT_EQ(RealNumberProblem("1e-9", 1e-9, 0.1, "r"), "");
  EXPECT_EQ(RealNumberProblem("0.1", 1e-9, 0.1, "r"), "");
  EXPECT_EQ(RealNumberProblem("-0", 0, 1, "r"), "");
  EXPECT_EQ(RealNumberProblem("1", 1e-9, 0.1, "r"), "'1' is out of range; accepted: r");
  for (const char *far : {"inf", "-inf", "1e400", "1e-400", "0.10000001"})
    EXPECT_TRUE(Says(RealNumberProblem(far, 0, 0.1, "r"), "out of range")) << far;
  for (const char *bad : {"", "nan", "abc", "0.5x", "0.5 ", "1,2"})
    EXPECT_TRUE(Says(RealNumberProblem(bad, 0, 1, "r"), "is not a number")) << bad;
}

}  // namespace
}  // namespace lutbake
