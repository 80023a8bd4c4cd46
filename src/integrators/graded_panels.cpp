// The graded panels of graded_panels.h.
#include "integrators/graded_panels.h"

#include <algorithm>

namespace lutbake::graded {

// Panels from a to b graded geometrically toward a (each keeps the share
// `keep` of what is left: ratio 1 / keep) until the one next to a is at
// most delta long.
void GradeToward(double a, double b, double delta, bool towardA, std::vector<Panel> *out,
                 double keep) {
  delta = std::max(delta, kSmallestScale * std::max(1.0, std::abs(a) + std::abs(b)));
  if (towardA) {
    double cur = b;
    while (cur - a > delta) {
      const double mid = a + keep * (cur - a);
      AppendPanel(out, mid, cur);
      cur = mid;
    }
    AppendPanel(out, a, cur);
  } else {
    double cur = a;
    while (b - cur > delta) {
      const double mid = b - keep * (b - cur);
      AppendPanel(out, cur, mid);
      cur = mid;
    }
    AppendPanel(out, cur, b);
  }
}

// Panels between sorted points, graded toward those with a scale, then
// split so that none is longer than maxLength nor, when nearSingular > 0,
// longer than max(its start, nearSingular) (singularities at +-i nearSingular
// about 0).
void BuildPanels(const std::vector<Point> &points, double maxLength, double nearSingular,
                 std::vector<Panel> *out) {
  thread_local std::vector<Panel> graded;
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const Point &p = points[k], &q = points[k + 1];
    if (!(q.v > p.v)) continue;
    graded.clear();
    const bool gp = p.above > 0.0 && p.above < q.v - p.v;
    const bool gq = q.below > 0.0 && q.below < q.v - p.v;
    // GradeToward lays the panels toward a from b, in descending order:
    // reversed here, so that `graded`, and the pieces below, come in
    // ascending order without a sort (the same panels as sorting them).
    if (gp && gq) {
      const double mid = 0.5 * (p.v + q.v);
      GradeToward(p.v, mid, p.above, true, &graded, p.keep);
      std::reverse(graded.begin(), graded.end());
      GradeToward(mid, q.v, q.below, false, &graded, q.keep);
    } else if (gp) {
      GradeToward(p.v, q.v, p.above, true, &graded, p.keep);
      std::reverse(graded.begin(), graded.end());
    } else if (gq) {
      GradeToward(p.v, q.v, q.below, false, &graded, q.keep);
    } else if (p.sqAbove && q.sqBelow) {
      // Two square-root ends: one quadratic panel toward each.
      AppendPanel(&graded, p.v, 0.5 * (p.v + q.v));
      AppendPanel(&graded, 0.5 * (p.v + q.v), q.v);
    } else {
      AppendPanel(&graded, p.v, q.v);
    }
    const size_t start = out->size();
    for (const Panel &g : graded) {
      if (nearSingular <= 0.0) {
        // Equal pieces: a short last piece would put the piece before it
        // next to whatever singularity sits at g.b.
        const int m = std::max(1, static_cast<int>(std::ceil((g.b - g.a) / maxLength - 1e-9)));
        for (int k = 0; k < m; ++k)
          AppendPanel(out, g.a + (g.b - g.a) * k / m,
                      k + 1 == m ? g.b : g.a + (g.b - g.a) * (k + 1) / m);
        continue;
      }
      double cur = g.a;
      for (;;) {
        const double len = std::min(maxLength, std::max(cur, nearSingular));
        // The last piece is between 1/2 and 3/2 of len, for the same reason.
        if (g.b - cur <= 1.5 * len) break;
        AppendPanel(out, cur, cur + len);
        cur += len;
      }
      AppendPanel(out, cur, g.b);
    }
    if (p.sqAbove) (*out)[start].square = 1;
    if (q.sqBelow) out->back().square = -1;
  }
}

}  // namespace lutbake::graded
