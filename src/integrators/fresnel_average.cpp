#include "lutbake/integrators/fresnel_average.h"

#include <cmath>

#include "lutbake/integrators/gauss_kronrod.h"

namespace lutbake {

namespace {
// Tolerance of the F_avg integrals: the integrands are smooth (or split at
// their one kink), so adaptive Gauss-Kronrod reaches rounding level quickly.
constexpr double kFavgTolerance = 1e-15;
}  // namespace

FresnelAverageResult SchlickFresnelAverage(double f0) {
  const QuadratureResult r = IntegrateAdaptive(
      [f0](double mu) { return 2.0 * mu * SchlickFresnel(f0, mu); }, 0.0, 1.0, kFavgTolerance);
  return {r.value, r.error};
}

FresnelAverageResult F82TintFresnelAverage(double f0, double tint) {
  return {f0 * (20.0 / 21.0) + 1.0 / 21.0 - F82TintCoefficient(f0, tint) / 126.0, 0.0};
}

FresnelAverageResult ExactFresnelAverage(double eta, double k) {
  const auto integrand = [eta, k](double mu) { return 2.0 * mu * ExactFresnel(eta, k, mu); };
  if (k == 0.0 && eta < 1.0) {
    // Total internal reflection below mu_c = sqrt(1 - eta^2): F = 1 there
    // exactly, so that part integrates to mu_c^2; the rest is smooth.
    const double muCritical = std::sqrt((1.0 - eta) * (1.0 + eta));
    const QuadratureResult r = IntegrateAdaptive(integrand, muCritical, 1.0, kFavgTolerance);
    return {muCritical * muCritical + r.value, r.error};
  }
  const QuadratureResult r = IntegrateAdaptive(integrand, 0.0, 1.0, kFavgTolerance);
  return {r.value, r.error};
}

}  // namespace lutbake
