// BuildPanels (integrators/graded_panels.h): the panels tile the points'
// range in ascending order, end to end, each graded run shrinking
// geometrically toward its point down to the scale asked for, the square
// maps on the panels beside square-root points, none longer than allowed.
#include "integrators/graded_panels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace lutbake::graded {
namespace {

TEST(GradedPanels, BuildPanelsTilesInOrderAndGradesTowardEachPoint) {
  // 0 graded above (ratio 2, to 1e-3), 0.3 graded on both sides (ratio 4, to
  // 1e-4) with square-root ends, 0.31 graded below only (to 1e-6), 1 plain.
  std::vector<Point> points = {
      {0.0, 0.0, 1e-3}, {0.3, 1e-4, 1e-4, true, true, 0.25}, {0.31, 1e-6, 0.0}, {1.0, 0.0, 0.0}};
  std::vector<Panel> panels;
  BuildPanels(points, 0.25, 0.0, &panels);
  ASSERT_FALSE(panels.empty());
  EXPECT_EQ(panels.front().a, 0.0);
  EXPECT_EQ(panels.back().b, 1.0);
  for (size_t k = 0; k < panels.size(); ++k) {
    EXPECT_LT(panels[k].a, panels[k].b) << k;
    EXPECT_LE(panels[k].b - panels[k].a, 0.25 + 1e-15) << k;
    if (k + 1 < panels.size()) {
      EXPECT_EQ(panels[k].b, panels[k + 1].a) << k;
    }
  }
  const auto at = [&](double v) {  // the panel starting at v
    for (size_t k = 0; k < panels.size(); ++k)
      if (panels[k].a == v) return static_cast<int>(k);
    return -1;
  };
  const auto ending = [&](double v) {
    for (size_t k = 0; k < panels.size(); ++k)
      if (panels[k].b == v) return static_cast<int>(k);
    return -1;
  };
  // Toward 0: the first panel within 1e-3, each next one twice as long up
  // to the halfway point of [0, 0.3] (the grading from 0.3 takes the rest).
  EXPECT_LE(panels[0].b, 1e-3);
  EXPECT_GT(panels[0].b, 0.5e-3);
  EXPECT_NEAR(panels[1].b - panels[1].a, panels[1].a, 1e-15);
  // Beside 0.3: within 1e-4 on both sides, mapped toward it, ratio 4 next.
  const int below = ending(0.3), above = at(0.3);
  ASSERT_GE(below, 1);
  ASSERT_GE(above, 0);
  EXPECT_LE(0.3 - panels[below].a, 1e-4);
  EXPECT_LE(panels[above].b - 0.3, 1e-4);
  EXPECT_EQ(panels[below].square, -1);
  EXPECT_EQ(panels[above].square, 1);
  EXPECT_NEAR(panels[below - 1].b - panels[below - 1].a, 3.0 * (0.3 - panels[below].a), 1e-15);
  EXPECT_NEAR(panels[above + 1].b - panels[above + 1].a, 3.0 * (panels[above].b - 0.3), 1e-15);
  // Toward 0.31 from below: the last panel before it within 1e-6.
  const int last = ending(0.31);
  ASSERT_GE(last, 0);
  EXPECT_LE(0.31 - panels[last].a, 1e-6);
  // Beyond 0.31 nothing is graded: equal pieces of at most 0.25.
  const int plain = at(0.31);
  ASSERT_GE(plain, 0);
  EXPECT_EQ(static_cast<int>(panels.size()) - plain, 3);
  EXPECT_NEAR(panels[plain].b - panels[plain].a, 0.23, 1e-15);
}

}  // namespace
}  // namespace lutbake::graded
