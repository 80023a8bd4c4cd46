// Globally adaptive Gauss-Kronrod (7/15-point) quadrature in one dimension.
//
// Each interval is integrated with the 15-point Kronrod rule; the difference
// to the embedded 7-point Gauss rule is its error estimate. The interval with
// the largest estimate is bisected until the sum of estimates is at most
// max(absTolerance, relTolerance |I|) or the interval budget is spent.
// Nested calls give the multidimensional reference integrals.
#pragma once

#include <algorithm>
#include <array>
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

template <int C>
struct Interval {
  double a, b;
  std::array<double, C> value, error;
  double worst;  // the largest channel error: the priority for bisection
};

template <int C, typename F>
Interval<C> Rule(const F &f, double a, double b) {
  const double center = 0.5 * (a + b), half = 0.5 * (b - a);
  const std::array<double, C> fc = f(center);
  std::array<double, C> kronrod, gauss;
  for (int c = 0; c < C; ++c) {
    kronrod[c] = fc[c] * kKronrodWeights[7];
    gauss[c] = fc[c] * kGaussWeights[3];
  }
  for (int j = 0; j < 7; ++j) {
    const double dx = half * kNodes[j];
    const std::array<double, C> lo = f(center - dx), hi = f(center + dx);
    for (int c = 0; c < C; ++c) {
      const double sum = lo[c] + hi[c];
      kronrod[c] += kKronrodWeights[j] * sum;
      if (j % 2 == 1) gauss[c] += kGaussWeights[j / 2] * sum;
    }
  }
  Interval<C> out{a, b, {}, {}, 0.0};
  for (int c = 0; c < C; ++c) {
    out.value[c] = kronrod[c] * half;
    out.error[c] = std::abs((kronrod[c] - gauss[c]) * half);
    out.worst = std::max(out.worst, out.error[c]);
  }
  return out;
}
}  // namespace gk_detail

template <int C>
struct QuadratureResultN {
  std::array<double, C> value{};
  std::array<double, C> error{};  // per channel: sum of |K15 - G7| over the final intervals
  int evaluations = 0;
  bool converged = false;
};

// The same for C integrands at once over shared intervals: f returns
// std::array<double, C>; converged when every channel's error sum is within
// its tolerance. Channels that share one integrand's expensive part (A and B
// of the split sum) cost one evaluation instead of C.
//
// breaks: the initial subdivision as an increasing list of points from a to
// b (at least two); known features placed on interval ends are resolved from
// the start instead of being found (or missed) by bisection.
template <int C, typename F>
QuadratureResultN<C> IntegrateAdaptiveN(const F &f, const std::vector<double> &breaks,
                                        double absTolerance, double relTolerance = 0.0,
                                        int maxIntervals = 4000) {
  using gk_detail::Interval;
  std::vector<Interval<C>> intervals;
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    if (breaks[k + 1] > breaks[k])
      intervals.push_back(gk_detail::Rule<C>(f, breaks[k], breaks[k + 1]));
  const auto byError = [](const Interval<C> &x, const Interval<C> &y) { return x.worst < y.worst; };
  std::make_heap(intervals.begin(), intervals.end(), byError);
  QuadratureResultN<C> result;
  result.evaluations = 15 * static_cast<int>(intervals.size());
  for (;;) {
    std::array<double, C> value{}, error{};
    for (const Interval<C> &iv : intervals)
      for (int c = 0; c < C; ++c) {
        value[c] += iv.value[c];
        error[c] += iv.error[c];
      }
    result.value = value;
    result.error = error;
    bool done = true;
    for (int c = 0; c < C; ++c)
      done = done && error[c] <= std::max(absTolerance, relTolerance * std::abs(value[c]));
    if (done || intervals.empty()) {
      result.converged = true;
      return result;
    }
    if (static_cast<int>(intervals.size()) >= maxIntervals) return result;
    std::pop_heap(intervals.begin(), intervals.end(), byError);
    const Interval<C> worst = intervals.back();
    intervals.pop_back();
    const double mid = 0.5 * (worst.a + worst.b);
    // An interval that cannot be split in double any more is final.
    if (!(mid > worst.a && mid < worst.b)) {
      intervals.push_back(worst);
      return result;
    }
    intervals.push_back(gk_detail::Rule<C>(f, worst.a, mid));
    std::push_heap(intervals.begin(), intervals.end(), byError);
    intervals.push_back(gk_detail::Rule<C>(f, mid, worst.b));
    std::push_heap(intervals.begin(), intervals.end(), byError);
    result.evaluations += 30;
  }
}

// initialIntervals > 1 starts from a uniform subdivision: a single 15-point
// rule can miss a feature narrower than its node spacing and then report a
// small error for a wrong value; a finer start makes that far less likely.
template <typename F>
QuadratureResult IntegrateAdaptive(const F &f, double a, double b, double absTolerance,
                                   double relTolerance = 0.0, int initialIntervals = 1,
                                   int maxIntervals = 4000) {
  std::vector<double> breaks(initialIntervals + 1);
  for (int k = 0; k <= initialIntervals; ++k) breaks[k] = a + (b - a) * k / initialIntervals;
  breaks.back() = b;
  const QuadratureResultN<1> r =
      IntegrateAdaptiveN<1>([&](double x) { return std::array<double, 1>{f(x)}; }, breaks,
                            absTolerance, relTolerance, maxIntervals);
  QuadratureResult out;
  out.value = r.value[0];
  out.error = r.error[0];
  out.evaluations = r.evaluations;
  out.converged = r.converged;
  return out;
}

}  // namespace lutbake
