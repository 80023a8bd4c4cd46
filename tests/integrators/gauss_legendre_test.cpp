// Gauss-Legendre rules: weights sum to 1, polynomials up to degree 2n - 1
// integrate exactly, nodes are symmetric, and an analytic integrand
// converges at the rate rho^(-2n) that the panel quadrature relies on.
#include "lutbake/integrators/gauss_legendre.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lutbake {
namespace {

TEST(GaussLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
  for (int n = 1; n <= kMaxGaussLegendreNodes; ++n) {
    const GaussLegendreRule &rule = GaussLegendre(n);
    ASSERT_EQ(rule.n, n);
    // int_0^1 x^k dx = 1 / (k + 1); rounding of n terms of size ~1/n.
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.w[i] * std::pow(rule.x[i], k);
      EXPECT_NEAR(sum, 1.0 / (k + 1), 4e-16 * n) << "n = " << n << ", degree " << k;
    }
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.x[i], 0.0);
      EXPECT_LT(rule.x[i], 1.0);
      EXPECT_GT(rule.w[i], 0.0);
      if (i > 0) {
        EXPECT_GT(rule.x[i], rule.x[i - 1]);
      }
      // Symmetric about 1/2, to the last bits.
      EXPECT_NEAR(rule.x[i] + rule.x[n - 1 - i], 1.0, 2e-16);
      EXPECT_NEAR(rule.w[i], rule.w[n - 1 - i], 1e-16);
    }
  }
}

TEST(GaussLegendre, AnalyticIntegrandConvergesAtTheBernsteinRate) {
  // f(x) = 1 / (1 + (x - 1/2)^2 / c^2) on [0, 1] has poles at 1/2 +- i c; on
  // [-1, 1] they sit at +-2ic, so rho = 2c + sqrt(4c^2 + 1). The error of the
  // n-node rule must fall at least as fast as a constant times rho^(-2n).
  const double c = 0.5, rho = 2 * c + std::sqrt(4 * c * c + 1);
  const double exact = 2 * c * std::atan(0.5 / c);
  for (int n = 2; n <= 14; ++n) {
    const GaussLegendreRule &rule = GaussLegendre(n);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += rule.w[i] / (1 + std::pow((rule.x[i] - 0.5) / c, 2));
    EXPECT_LE(std::abs(sum - exact), 8.0 * std::pow(rho, -2.0 * n) + 1e-16) << n;
  }
}

}  // namespace
}  // namespace lutbake
