// Panels for Gauss rules over one variable whose integrand has known
// breaks: the panels end on every break, are graded geometrically toward
// those that carry a scale (a nearby complex singularity, a boundary layer),
// and the panel beside a square-root-type point is mapped quadratically, so
// that the integrand is analytic in the rule's variable on every panel. The
// rough-dielectric albedo (over the half vector's polar angle and azimuth)
// and its average (over the half vector, o.h and the azimuth about h) lay
// their panels with these. Private to the integrators layer.
#pragma once

#include <cmath>
#include <vector>

namespace lutbake::graded {

// Grading stops at this (relative) scale whatever the scale asked for.
inline constexpr double kSmallestScale = 1e-14;

struct Point {
  double v, below, above;  // position and grading scales, in the variable
  bool sqBelow = false, sqAbove = false;
  double keep = 0.5;  // the grading toward it: each panel keeps this share of the rest
};

struct Panel {
  double a, b;
  // +1: v = a + (b - a) u^2; -1: v = b - (b - a) u^2; 0: linear;
  // +2: v = root + (s_a + (s_b - s_a) u)^2, s_a = sqrt(a - root), s_b =
  // sqrt(b - root), for a square-root branch point at root <= a just outside
  // the panel (sqrt(v - root) is then linear in u); -2: v = root - (s_a +
  // (s_b - s_a) u)^2, s = sqrt(root - v), for one at root >= b.
  int square = 0;
  double root = 0.0;
};

// Append a linear panel [a, b], or a point, with its fields written in place:
// push_back of a braced temporary built it on the stack and copied it with
// wider loads than its stores (a store-forwarding stall on every panel, 10%
// of the albedo's time). The same values either way.
inline void AppendPanel(std::vector<Panel> *out, double a, double b) {
  Panel &p = out->emplace_back();
  p.a = a;
  p.b = b;
  p.square = 0;
  p.root = 0.0;
}
inline void AppendPoint(std::vector<Point> *out, double v, double below, double above,
                        bool sqBelow = false, bool sqAbove = false, double keep = 0.5) {
  Point &p = out->emplace_back();
  p.v = v;
  p.below = below;
  p.above = above;
  p.sqBelow = sqBelow;
  p.sqAbove = sqAbove;
  p.keep = keep;
}

// Panels from a to b graded geometrically toward a (towardA) or b: each
// keeps the share `keep` of what is left (ratio 1 / keep), until the one
// next to that end is at most delta long.
void GradeToward(double a, double b, double delta, bool towardA, std::vector<Panel> *out,
                 double keep = 0.5);

// Panels between sorted points, graded toward those with a scale (above,
// below), the panel beside a point with sqAbove / sqBelow mapped
// quadratically toward it, then split so that none is longer than maxLength
// nor, when nearSingular > 0, longer than max(its start, nearSingular)
// (singularities at +-i nearSingular about 0).
void BuildPanels(const std::vector<Point> &points, double maxLength, double nearSingular,
                 std::vector<Panel> *out);

// The square-root map of a panel with square = +-2, its two roots taken
// once (a rule's nodes on one panel share them): Node(u, &v) sets v and
// returns dv/du.
struct RootMap {
  explicit RootMap(const Panel &p)
      : root(p.root),
        sa(std::sqrt(std::abs(p.a - p.root))),
        ds(std::sqrt(std::abs(p.b - p.root)) - sa),
        absDs(std::abs(ds)),
        above(p.square == 2) {}
  double Node(double u, double *v) const {
    const double t = sa + ds * u;
    *v = above ? root + t * t : root - t * t;
    return 2.0 * t * absDs;
  }
  double root, sa, ds, absDs;
  bool above;  // square = 2: the root lies below the panel
};

// The node of a panel at u in [0, 1]; returns dv/du.
inline double MapNode(const Panel &p, double u, double *v) {
  const double len = p.b - p.a;
  if (p.square == 2 || p.square == -2) return RootMap(p).Node(u, v);
  if (p.square > 0) {
    *v = p.a + len * u * u;
    return 2.0 * len * u;
  }
  if (p.square < 0) {
    *v = p.b - len * u * u;
    return 2.0 * len * u;
  }
  *v = p.a + len * u;
  return len;
}

}  // namespace lutbake::graded
