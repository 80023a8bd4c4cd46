#include "lutbake/models/fresnel.h"

#include <complex>

#include "lutbake/core/math.h"

namespace lutbake {

std::string_view ToString(FresnelModel model) {
  switch (model) {
    case FresnelModel::kSchlick: return "schlick";
    case FresnelModel::kDielectric: return "dielectric";
    case FresnelModel::kConductor: return "conductor";
    case FresnelModel::kF82: return "f82";
  }
  return "?";
}

double SchlickFresnel(double f0, double mu) { return f0 + (1.0 - f0) * Pow5(1.0 - mu); }

double F82TintCoefficient(double f0, double tint) {
  // mu_bar = 1/7: mu_bar (1 - mu_bar)^6 = 6^6 / 7^7, so
  // a = Schlick(f0, 1/7) (1 - tint) 7^7 / 6^6.
  constexpr double kMuBar = 1.0 / 7.0, kBump = 46656.0 / 823543.0;  // 6^6 / 7^7
  return SchlickFresnel(f0, kMuBar) * (1.0 - tint) / kBump;
}

double F82TintFresnel(double f0, double tint, double mu) {
  const double y = 1.0 - mu, y2 = y * y;
  return SchlickFresnel(f0, mu) - F82TintCoefficient(f0, tint) * mu * (y2 * y2 * y2);
}

double ExactFresnel(double eta, double k, double mu) {
  const std::complex<double> n(eta, k);
  const std::complex<double> n2 = n * n;
  const double sin2 = std::max(0.0, (1.0 - mu) * (1.0 + mu));
  const std::complex<double> w = std::sqrt(n2 - sin2);
  const std::complex<double> sDen = mu + w;
  const std::complex<double> pDen = n2 * mu + w;
  // Both denominators vanish only for n = 0 (a perfect reflector of no
  // index) at normal incidence, where the limit is F = 1.
  if (std::norm(sDen) == 0.0 || std::norm(pDen) == 0.0) return 1.0;
  const double rs = std::norm((mu - w) / sDen);
  const double rp = std::norm((n2 * mu - w) / pDen);
  return std::min(1.0, 0.5 * (rs + rp));
}

}  // namespace lutbake
