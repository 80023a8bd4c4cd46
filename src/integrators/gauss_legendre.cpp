#include "lutbake/integrators/gauss_legendre.h"

#include <array>
#include <cassert>
#include <cmath>
#include <mutex>

#include "lutbake/core/math.h"

namespace lutbake {

namespace {

struct StoredRule {
  std::array<double, kMaxGaussLegendreNodes> x{}, w{};
  GaussLegendreRule rule;
};

// Node k of P_n on [-1, 1] by Newton's method from the Chebyshev-like
// start cos(pi (k + 3/4) / (n + 1/2)); P_n and P_n' by the three-term
// recurrence. The weight is 2 / ((1 - z^2) P_n'(z)^2), halved for [0, 1].
void Compute(int n, StoredRule *out) {
  for (int k = 0; k < n; ++k) {
    double z = std::cos(kPi * (k + 0.75) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p = 1.0, previous = 0.0;
      for (int j = 1; j <= n; ++j) {
        const double next = ((2.0 * j - 1.0) * z * p - (j - 1.0) * previous) / j;
        previous = p;
        p = next;
      }
      derivative = n * (z * p - previous) / (z * z - 1.0);
      const double step = p / derivative;
      z -= step;
      if (std::abs(step) <= 1e-17) break;
    }
    // Node k is the k-th largest z; x = (1 - z) / 2 increases with k.
    out->x[k] = 0.5 * (1.0 - z);
    out->w[k] = 1.0 / ((1.0 - z * z) * derivative * derivative);
  }
  out->rule = {n, out->x.data(), out->w.data()};
}

}  // namespace

const GaussLegendreRule &GaussLegendre(int n) {
  assert(n >= 1 && n <= kMaxGaussLegendreNodes);
  static std::array<StoredRule, kMaxGaussLegendreNodes + 1> rules;
  static std::array<std::once_flag, kMaxGaussLegendreNodes + 1> once;
  std::call_once(once[n], [n] { Compute(n, &rules[n]); });
  return rules[n].rule;
}

}  // namespace lutbake
