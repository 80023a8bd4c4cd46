#include "lutbake/integrators/dielectric_estimator.h"

#include <stdexcept>

namespace lutbake {

namespace {

void CheckArguments(double alpha, double eta) {
  if (!(alpha > 0.0 && alpha <= 1.0))
    throw std::invalid_argument("dielectric estimator: alpha must lie in (0, 1]");
  if (!(eta >= kMinRelativeIor && eta <= kMaxRelativeIor))
    throw std::invalid_argument("dielectric estimator: eta must lie in [1/128, 128]");
}

// The facet weight of a visible normal sampled from (u0, u1) for the view
// o, L_o = mu_o Lambda(mu_o).
double SampledWeight(const Ndf &ndf, SmithForm smith, DielectricLobes lobes, double eta,
                     const Vec3 &o, double L_o, double u0, double u1) {
  const Vec3 h = ndf.SampleVisibleNormal(o, u0, u1);
  const double c = Dot(o, h);
  // The mirror's cosine, 2 c h.z - mu_o; the facet weight handles c <= 0
  // (measure zero under D_o) and both horizons.
  const double mu_r = 2.0 * c * h.z - o.z;
  return DielectricFacetWeight(ndf, smith, lobes, eta, o.z, L_o, c, h.z, mu_r);
}

}  // namespace

DielectricAlbedoEstimator::DielectricAlbedoEstimator(NdfKind ndf, SmithForm smith,
                                                     DielectricLobes lobes, double alpha,
                                                     double mu_o, double eta)
    : ndf_{ndf, alpha}, smith_(smith), lobes_(lobes), eta_(eta) {
  CheckArguments(alpha, eta);
  if (!(mu_o > 0.0 && mu_o <= 1.0))
    throw std::invalid_argument("dielectric estimator: mu_o must lie in (0, 1]");
  o_ = ViewDirection(mu_o);
  L_o_ = ndf_.MuLambda(mu_o);
}

double DielectricAlbedoEstimator::Weight(double u0, double u1) const {
  return SampledWeight(ndf_, smith_, lobes_, eta_, o_, L_o_, u0, u1);
}

DielectricAverageEstimator::DielectricAverageEstimator(NdfKind ndf, SmithForm smith,
                                                       DielectricLobes lobes, double alpha,
                                                       double eta)
    : ndf_{ndf, alpha}, smith_(smith), lobes_(lobes), eta_(eta) {
  CheckArguments(alpha, eta);
}

double DielectricAverageEstimator::Weight(double u0, double u1, double u2) const {
  const double mu_o = u2;
  if (!(mu_o > 0.0)) return 0.0;  // weight 2 mu_o w = 0 at mu_o = 0
  // The view's quantities directly: no per-sample estimator (and no
  // argument checks, done once in the constructor).
  const Vec3 o = ViewDirection(mu_o);
  return 2.0 * mu_o * SampledWeight(ndf_, smith_, lobes_, eta_, o, ndf_.MuLambda(mu_o), u0, u1);
}

}  // namespace lutbake
