// An independent E for GGX, for the tests: over the light direction in
// (mu_i, phi) instead of the half vector, where G2 depends on mu_i alone and
// the azimuthal integral of D has a closed form, so that E is a 1D integral.
//
// With Q = |o + i|^2 = a + b cos(phi), a = 2 (1 + mu_o mu_i), b = 2 s_o s_i,
// and P = (mu_o + mu_i)^2, cos^2(theta_h) = P / Q and
//   D = alpha^2 Q^2 / (pi (Q - delta)^2),  delta = (1 - alpha^2) P,
// so that, with A' = a - delta and S = sqrt(A'^2 - b^2),
//   J(mu_o, mu_i) = int_0^2pi D dphi = 2 alpha^2 (1 + 2 delta / S + delta^2 A' / S^3)
// (int dphi / (A' + b cos) = 2 pi / S, int dphi / (A' + b cos)^2 = 2 pi A' / S^3), and
//   E(mu_o) = int_0^1 G2(mu_o, mu_i) J / (4 mu_o) dmu_i.
// A' - b = Q(pi) - delta is written without cancellation as
//   eps = 4 cos^2(Sigma/2) (sin^2(Delta/2) + alpha^2 cos^2(Delta/2)),
// Sigma = theta_o + theta_i, Delta = theta_o - theta_i.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/models/ggx.h"
#include "lutbake/models/smith.h"

namespace lutbake::test {

inline double AzimuthalIntegralOfGgx(double alpha, double mu_o, double mu_i) {
  const double s_o = std::sqrt((1 - mu_o) * (1 + mu_o)), s_i = std::sqrt((1 - mu_i) * (1 + mu_i));
  const double b = 2 * s_o * s_i;
  const double delta = (1 - alpha * alpha) * (mu_o + mu_i) * (mu_o + mu_i);
  // 1 + cos(Sigma) = (1 - s_o s_i) + mu_o mu_i, 1 - s_o s_i = (mu_o^2 + mu_i^2 - mu_o^2 mu_i^2) /
  // (1 + s_o s_i).
  const double cos2HalfSum =
      0.5 *
      ((mu_o * mu_o + mu_i * mu_i - mu_o * mu_o * mu_i * mu_i) / (1 + s_o * s_i) + mu_o * mu_i);
  // sin^2(Delta/2) = sin^2(Delta) / (2 (1 + cos(Delta))).
  const double sinDelta = s_o * mu_i - mu_o * s_i;
  const double sin2HalfDifference = sinDelta * sinDelta / (2 * (1 + mu_o * mu_i + s_o * s_i));
  const double eps =
      4 * cos2HalfSum * (sin2HalfDifference + alpha * alpha * (1 - sin2HalfDifference));
  const double Ap = eps + b, S = std::sqrt(eps * (eps + 2 * b));
  return 2 * alpha * alpha * (1 + 2 * delta / S + delta * delta * Ap / (S * S * S));
}

// E by adaptive Gauss-Kronrod over mu_i, with breaks graded toward mu_o (the
// peak, width ~alpha) and toward 0 (G2's boundary layer).
inline double ClosedFormAzimuthE(double alpha, double mu_o, SmithForm smith,
                                 double tolerance = 1e-14) {
  const double L_o = ggx::MuLambda(alpha, mu_o);
  const auto f = [&](double mu_i) {
    if (!(mu_i > 0)) return std::array<double, 1>{0.0};
    return std::array<double, 1>{
        SmithG2OverMuO(smith, mu_o, mu_i, L_o, ggx::MuLambda(alpha, mu_i)) *
        AzimuthalIntegralOfGgx(alpha, mu_o, mu_i) / 4};
  };
  std::vector<double> breaks{0.0, 1.0, mu_o};
  for (double d = alpha * 1e-3; d < 1; d *= 2)
    for (double b : {mu_o + d, mu_o - d, d, d * mu_o})
      if (b > 0 && b < 1) breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  return IntegrateAdaptiveN<1>(f, breaks, tolerance, 0.0, 20000).value[0];
}

}  // namespace lutbake::test
