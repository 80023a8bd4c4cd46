// Gauss-Legendre rules on [0, 1]: n nodes integrate polynomials of degree
// 2n - 1 exactly, and an integrand analytic inside the Bernstein ellipse of
// parameter rho (foci at the panel's ends, semi-axes summing to rho times
// the half-length) to O(rho^(-2n)). The panel quadrature
// (albedo_quadrature.h) places its panels so that rho is at least ~4.6.
#pragma once

namespace lutbake {

inline constexpr int kMaxGaussLegendreNodes = 64;

struct GaussLegendreRule {
  int n = 0;
  const double *x = nullptr;  // nodes in (0, 1), increasing
  const double *w = nullptr;  // weights, summing to 1
};

// The n-node rule, 1 <= n <= kMaxGaussLegendreNodes. Computed once (Newton's
// method on the Legendre recurrence, to the last bit of double) and kept for
// the life of the program; safe to call from several threads.
const GaussLegendreRule &GaussLegendre(int n);

}  // namespace lutbake
