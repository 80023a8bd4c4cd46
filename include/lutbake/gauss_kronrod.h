// Globally adaptive Gauss-Kronrod (7/15-point) quadrature in one dimension.
//
// Each interval is integrated with the 15-point Kronrod rule; the difference
// to the embedded 7-point Gauss rule is its error estimate. The interval with
// the largest estimate is bisected until the sum of estimates is at most
// max(absTolerance, relTolerance |I|) or the interval budget is spent.
// Nested calls give the multidimensional reference integrals.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace lutbake {

struct QuadratureResult {
  double value = 0.0;
  double error = 0.0;  // sum of |K15 - G7| over the final intervals
  int evaluations = 0;
  bool converged = false;
};

namespace gk_detail {
// Abscissae of the 15-point Kronrod rule on [-1, 1] (non-negative half,
// descending); odd indices are the 7-point Gauss nodes.
inline constexpr double kNodes[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
inline constexpr double kKronrodWeights[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Weights of the 7-point Gauss rule at kNodes[1], [3], [5], [7].
inline constexpr double kGaussWeights[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Interval {
  double a, b, value, error;
};

template <typename F>
Interval Rule(const F &f, double a, double b) {
  const double center = 0.5 * (a + b), half = 0.5 * (b - a);
  const double fc = f(center);
  double kronrod = fc * kKronrodWeights[7];
  double gauss = fc * kGaussWeights[3];
  for (int j = 0; j < 7; ++j) {
    const double dx = half * kNodes[j];
    const double sum = f(center - dx) + f(center + dx);
    kronrod += kKronrodWeights[j] * sum;
    if (j % 2 == 1) gauss += kGaussWeights[j / 2] * sum;
  }
  return {a, b, kronrod * half, std::abs((kronrod - gauss) * half)};
}
}  // namespace gk_detail

// initialIntervals > 1 starts from a uniform subdivision: a single 15-point
// rule can miss a feature narrower than its node spacing and then report a
// small error for a wrong value; a finer start makes that far less likely.
template <typename F>
QuadratureResult IntegrateAdaptive(const F &f, double a, double b, double absTolerance,
                                   double relTolerance = 0.0, int initialIntervals = 1,
                                   int maxIntervals = 4000) {
  using gk_detail::Interval;
  std::vector<Interval> intervals;
  for (int k = 0; k < initialIntervals; ++k) {
    const double lo = a + (b - a) * k / initialIntervals;
    const double hi = k + 1 == initialIntervals ? b : a + (b - a) * (k + 1) / initialIntervals;
    intervals.push_back(gk_detail::Rule(f, lo, hi));
  }
  const auto byError = [](const Interval &x, const Interval &y) { return x.error < y.error; };
  std::make_heap(intervals.begin(), intervals.end(), byError);
  QuadratureResult result;
  result.evaluations = 15 * initialIntervals;
  for (;;) {
    double value = 0.0, error = 0.0;
    for (const Interval &iv : intervals) {
      value += iv.value;
      error += iv.error;
    }
    result.value = value;
    result.error = error;
    if (error <= std::max(absTolerance, relTolerance * std::abs(value))) {
      result.converged = true;
      return result;
    }
    if (static_cast<int>(intervals.size()) >= maxIntervals) return result;
    std::pop_heap(intervals.begin(), intervals.end(), byError);
    const Interval worst = intervals.back();
    intervals.pop_back();
    const double mid = 0.5 * (worst.a + worst.b);
    // An interval that cannot be split in double any more is final.
    if (!(mid > worst.a && mid < worst.b)) {
      result.value = value;
      return result;
    }
    intervals.push_back(gk_detail::Rule(f, worst.a, mid));
    std::push_heap(intervals.begin(), intervals.end(), byError);
    intervals.push_back(gk_detail::Rule(f, mid, worst.b));
    std::push_heap(intervals.begin(), intervals.end(), byError);
    result.evaluations += 30;
  }
}

}  // namespace lutbake
