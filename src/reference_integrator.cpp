#include "lutbake/reference_integrator.h"

#include "lutbake/gauss_kronrod.h"
#include "lutbake/math.h"

namespace lutbake {

namespace {

// Beckmann's inner variable t = tan(theta) / alpha carries the weight
// 2 t exp(-t^2): beyond t = 40 it is below 1e-690, so the range is cut there.
constexpr double kBeckmannSlopeCut = 40.0;

// Initial subdivisions: the grazing features (theta_max ~ alpha near
// phi = pi) are narrow, and a single 15-point rule can step over them.
constexpr int kOuterStartIntervals = 16;
constexpr int kInnerStartIntervals = 8;

enum class Channel { kA, kB };

struct InnerSetup {
  double s_o, c_o, L_o, cosPhi;
};

// Integrand of the inner integral at inner variable v (psi for GGX, t for
// Beckmann), including the Jacobian d(xi)/dv.
double InnerIntegrand(const Ndf &ndf, SmithForm smith, const InnerSetup &s, Channel channel,
                      double v) {
  double cosTheta, sinTheta, jacobian;
  if (ndf.kind == NdfKind::kGgx) {
    const double cosPsi = std::cos(v), sinPsi = std::sin(v);
    const double norm = std::sqrt(cosPsi * cosPsi + Sqr(ndf.alpha * sinPsi));
    cosTheta = cosPsi / norm;
    sinTheta = ndf.alpha * sinPsi / norm;
    jacobian = 2.0 * sinPsi * cosPsi;
  } else {
    const double tanTheta = ndf.alpha * v;
    cosTheta = 1.0 / std::sqrt(1.0 + tanTheta * tanTheta);
    sinTheta = tanTheta * cosTheta;
    jacobian = 2.0 * v * std::exp(-v * v);
  }
  const double oh = s.s_o * sinTheta * s.cosPhi + s.c_o * cosTheta;
  const double mu_i = 2.0 * oh * cosTheta - s.c_o;
  if (mu_i <= 0.0 || oh <= 0.0 || cosTheta <= 0.0) return 0.0;
  // (o.h) / cos(theta) * G2 / mu_o, the integrand in xi.
  const double w = (oh / cosTheta) * SmithG2OverMuO(smith, s.c_o, mu_i, s.L_o, ndf.MuLambda(mu_i));
  const double fc = Pow5(1.0 - oh);
  return jacobian * w * (channel == Channel::kB ? fc : 1.0 - fc);
}

QuadratureResult IntegrateChannel(const Ndf &ndf, SmithForm smith, double mu_o, Channel channel,
                                  double tolerance) {
  const double s_o = SafeSqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double L_o = ndf.MuLambda(mu_o);
  const double innerTolerance = 0.1 * tolerance;
  double worstInnerError = 0.0;
  bool innerConverged = true;
  const auto outer = [&](double phi) {
    const InnerSetup setup{s_o, mu_o, L_o, std::cos(phi)};
    const double thetaMax = 0.5 * (std::atan2(s_o * setup.cosPhi, mu_o) + 0.5 * kPi);
    double vMax;
    if (ndf.kind == NdfKind::kGgx) {
      vMax = std::atan2(std::sin(thetaMax), ndf.alpha * std::cos(thetaMax));
    } else {
      const double c = ndf.alpha * std::cos(thetaMax);
      const double s = std::sin(thetaMax);
      vMax = s < kBeckmannSlopeCut * c ? s / c : kBeckmannSlopeCut;
    }
    if (!(vMax > 0.0)) return 0.0;
    const QuadratureResult inner =
        IntegrateAdaptive([&](double v) { return InnerIntegrand(ndf, smith, setup, channel, v); },
                          0.0, vMax, innerTolerance, 0.0, kInnerStartIntervals);
    worstInnerError = std::max(worstInnerError, inner.error);
    innerConverged = innerConverged && inner.converged;
    return inner.value * kInvPi;
  };
  const QuadratureResult left =
      IntegrateAdaptive(outer, 0.0, 0.5 * kPi, 0.5 * tolerance, 0.0, kOuterStartIntervals);
  const QuadratureResult right =
      IntegrateAdaptive(outer, 0.5 * kPi, kPi, 0.5 * tolerance, 0.0, kOuterStartIntervals);
  QuadratureResult total;
  total.value = left.value + right.value;
  total.error = left.error + right.error + worstInnerError;
  total.evaluations = left.evaluations + right.evaluations;
  total.converged = left.converged && right.converged && innerConverged;
  return total;
}

}  // namespace

ReferenceAlbedo IntegrateReferenceAlbedo(const Ndf &ndf, SmithForm smith, double mu_o,
                                         double tolerance) {
  ReferenceAlbedo result;
  if (ndf.alpha == 0.0) {
    // A mirror: the only microfacet is n, the light is the mirror direction
    // with o.h = mu_o, and G2 = 1. Exact, no integral.
    result.B = Pow5(1.0 - mu_o);
    result.A = 1.0 - result.B;
    result.E = 1.0;
    result.converged = true;
    return result;
  }
  // E is taken as A + B. Integrated on its own, E's adaptive refinement was
  // seen to settle 1e-10 away from the truth at grazing view and small alpha
  // (mu_o = 1e-3, alpha = 1e-4) while A and B, whose integrands split E's
  // into a small and a large part, each agree with independent values to 1e-13.
  const QuadratureResult a = IntegrateChannel(ndf, smith, mu_o, Channel::kA, tolerance);
  const QuadratureResult b = IntegrateChannel(ndf, smith, mu_o, Channel::kB, tolerance);
  result.A = a.value;
  result.B = b.value;
  result.E = a.value + b.value;
  result.error = a.error + b.error;
  result.converged = a.converged && b.converged;
  return result;
}

ReferenceAverage IntegrateReferenceAlbedoAverage(const Ndf &ndf, SmithForm smith,
                                                 double tolerance) {
  ReferenceAverage result;
  if (ndf.alpha == 0.0) {
    result.value = 1.0;
    result.converged = true;
    return result;
  }
  double worstInner = 0.0;
  bool innerConverged = true;
  const auto integrand = [&](double mu) {
    const ReferenceAlbedo e = IntegrateReferenceAlbedo(ndf, smith, mu, 0.1 * tolerance);
    worstInner = std::max(worstInner, e.error);
    innerConverged = innerConverged && e.converged;
    return 2.0 * mu * e.E;
  };
  const double breaks[4] = {0.0, std::min(1.0, ndf.alpha), std::min(1.0, 8.0 * ndf.alpha), 1.0};
  for (int k = 0; k < 3; ++k) {
    if (!(breaks[k + 1] > breaks[k])) continue;
    const QuadratureResult part =
        IntegrateAdaptive(integrand, breaks[k], breaks[k + 1], tolerance / 3.0);
    result.value += part.value;
    result.error += part.error;
    result.converged = (k == 0 || result.converged) && part.converged;
  }
  result.error += worstInner;
  result.converged = result.converged && innerConverged;
  return result;
}

}  // namespace lutbake
