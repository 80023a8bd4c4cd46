#include "lutbake/integrators/reference_integrator.h"

#include <array>
#include <vector>

#include "lutbake/core/math.h"
#include "lutbake/integrators/gauss_kronrod.h"

namespace lutbake {

namespace {

// Beckmann's inner variable t = tan(theta) / alpha carries the weight
// 2 t exp(-t^2): beyond t = 40 it is below 1e-690, so the range is cut there.
constexpr double kBeckmannSlopeCut = 40.0;

// Initial inner subdivision, graded toward v_max (InnerBreaks).
constexpr double kInnerBreakFractions[] = {0.5, 0.75, 0.875};

struct InnerSetup {
  double s_o, c_o, L_o, cosPhi;
};

// The Fresnel-like weights of the split sum: A and B (Schlick's 1 - Fc, Fc).
struct SplitSumWeights {
  static constexpr int kChannels = 2;
  std::array<double, 2> operator()(double w, double oh) const {
    const SchlickWeights fc = Schlick(oh);
    return {w * fc.complement, w * fc.fc};
  }
};

// The F82 term C: (o.h) (1 - o.h)^6.
struct F82Weight {
  static constexpr int kChannels = 1;
  std::array<double, 1> operator()(double w, double oh) const {
    const double y = 1.0 - oh, y2 = y * y;
    return {w * (oh * (y2 * y2 * y2))};
  }
};

// Integrand of the inner integral at inner variable v (for GGX v =
// tan(psi / 2) with tan(theta) = alpha tan(psi); for Beckmann t), including the Jacobian d(xi)/dv,
// times each of the weights: {A part, B part} (SplitSumWeights) or {C part} (F82Weight).
template <typename Weights, int N = Weights::kChannels>
std::array<double, N> InnerIntegrand(const Ndf &ndf, SmithForm smith, const InnerSetup &s,
                                     double v) {
  double cosTheta, sinTheta, jacobian;
  if (ndf.kind == NdfKind::kGgx) {
    // The GGX measure is d(sin^2 psi) = 2 sin(psi) cos(psi) dpsi. With
    // v = tan(psi / 2) in [0, 1], cos(psi) = (1 - v^2) / q and sin(psi) =
    // 2 v / q (q = 1 + v^2), dpsi = 2 dv / q: no sine or cosine per node.
    // Over dfg's 128^2 texels at 1e-8 this took 7815 evaluations a texel
    // instead of 8441 in psi, in 0.55x the time, the worst deviation from a
    // 1e-13 reference 8.7e-9 (1.1e-8 in psi).
    const double cosPsiQ = (1.0 - v) * (1.0 + v), sinPsiQ = 2.0 * v, q = 1.0 + v * v;
    const double norm = std::sqrt(cosPsiQ * cosPsiQ + Sqr(ndf.alpha * sinPsiQ));
    cosTheta = cosPsiQ / norm;
    sinTheta = ndf.alpha * sinPsiQ / norm;
    jacobian = 4.0 * sinPsiQ * cosPsiQ / (q * q * q);
  } else {
    const double tanTheta = ndf.alpha * v;
    cosTheta = 1.0 / std::sqrt(1.0 + tanTheta * tanTheta);
    sinTheta = tanTheta * cosTheta;
    jacobian = 2.0 * v * std::exp(-v * v);
  }
  const double oh = s.s_o * sinTheta * s.cosPhi + s.c_o * cosTheta;
  const double mu_i = 2.0 * oh * cosTheta - s.c_o;
  if (mu_i <= 0.0 || oh <= 0.0 || cosTheta <= 0.0) return {};
  // (o.h) / cos(theta) * G2 / mu_o, the integrand in xi.
  const double w =
      jacobian * (oh / cosTheta) * SmithG2OverMuO(smith, s.c_o, mu_i, s.L_o, ndf.MuLambda(mu_i));
  return Weights()(w, oh);
}

// Outer (azimuth) breaks. theta_max(phi) swings from about pi/2 to about 0
// as cos(phi) crosses [-mu_o, mu_o]: near grazing view that is a feature
// of width ~mu_o around phi = pi/2 (a jump at mu_o = 0), and for
// mu_o < alpha theta_max crosses the NDF's width alpha at |phi - pi/2| ~
// mu_o / alpha. Breaks at pi/2 +- mu_o 4^k grade the start toward both
// scales; pi/2 itself is always a break. Nothing else is: a uniform start
// of 4 intervals a side (once here) cost 1.7x the evaluations over the
// 128^2 texels of dfg at tolerance 1e-8, and the largest deviation from a
// 1e-13 reference there was 1.1e-8 either way; without it, every value at
// mu_o from 1e-12 to 1 and alpha from 1e-12 to 1 (GGX and Beckmann, either
// Smith form, tolerances 1e-8 and 1e-10) stayed within its stated bound.
std::vector<double> OuterBreaks(double mu_o) {
  std::vector<double> below, breaks;
  // The grading starts at mu_o itself (a floor of 1e-6 left mu_o = 1e-12,
  // alpha = 1e-12 unconverged after 7 million evaluations). Below 1e-200 a
  // feature of width mu_o is indistinguishable from the jump at mu_o = 0,
  // which the break at pi/2 already handles; the floor bounds the grading
  // to ~330 intervals a side.
  constexpr double kSmallestGrading = 1e-200;
  for (double d = std::max(mu_o, kSmallestGrading); d < 0.4 * kPi; d *= 4.0) below.push_back(d);
  breaks.push_back(0.0);
  for (auto it = below.rbegin(); it != below.rend(); ++it) breaks.push_back(0.5 * kPi - *it);
  breaks.push_back(0.5 * kPi);
  for (double d : below) breaks.push_back(0.5 * kPi + d);
  breaks.push_back(kPi);
  return breaks;
}

// Inner breaks, graded toward v_max: the shadowing term G2 falls to 0 there
// over a range of theta of order alpha, which the NDF variable compresses.
std::vector<double> InnerBreaks(double vMax) {
  std::vector<double> breaks{0.0};
  for (double f : kInnerBreakFractions) breaks.push_back(f * vMax);
  breaks.push_back(vMax);
  return breaks;
}

// A and B together (they share every evaluation of D, G2 and the horizon),
// or C alone.
template <typename Weights, int N = Weights::kChannels>
QuadratureResultN<N> IntegrateSplitSum(const Ndf &ndf, SmithForm smith, double mu_o,
                                       double tolerance) {
  const double s_o = SafeSqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double L_o = ndf.MuLambda(mu_o);
  const double innerTolerance = 0.1 * tolerance;
  std::array<double, N> worstInnerError{};
  bool innerConverged = true;
  int innerEvaluations = 0;
  const auto outer = [&](double phi) -> std::array<double, N> {
    const InnerSetup setup{s_o, mu_o, L_o, std::cos(phi)};
    // theta_max = (atan2(s_o cos(phi), c_o) + pi/2) / 2, written as one
    // atan2 of the vector turned by 90 degrees: the sum cancels when
    // cos(phi) < 0 and mu_o is small (-pi/2 + mu_o / x loses mu_o / x to
    // the rounding of pi/2), and the jitter of the upper limit kept the
    // outer rule from converging at mu_o = alpha = 1e-12.
    const double thetaMax = 0.5 * std::atan2(mu_o, -s_o * setup.cosPhi);
    double vMax;
    if (ndf.kind == NdfKind::kGgx) {
      // tan(psi_max / 2) = sin(psi_max) / (1 + cos(psi_max)), with
      // tan(psi_max) = tan(theta_max) / alpha.
      const double y = std::sin(thetaMax), x = ndf.alpha * std::cos(thetaMax);
      vMax = y / (std::hypot(x, y) + x);
    } else {
      const double c = ndf.alpha * std::cos(thetaMax);
      const double s = std::sin(thetaMax);
      vMax = s < kBeckmannSlopeCut * c ? s / c : kBeckmannSlopeCut;
    }
    if (!(vMax > 0.0)) return {};
    const QuadratureResultN<N> inner = IntegrateAdaptiveN<N>(
        [&](double v) { return InnerIntegrand<Weights>(ndf, smith, setup, v); }, InnerBreaks(vMax),
        innerTolerance);
    for (int c = 0; c < N; ++c) worstInnerError[c] = std::max(worstInnerError[c], inner.error[c]);
    innerConverged = innerConverged && inner.converged;
    innerEvaluations += inner.evaluations;
    std::array<double, N> value;
    for (int c = 0; c < N; ++c) value[c] = inner.value[c] * kInvPi;
    return value;
  };
  QuadratureResultN<N> total = IntegrateAdaptiveN<N>(outer, OuterBreaks(mu_o), tolerance);
  for (int c = 0; c < N; ++c) total.error[c] += worstInnerError[c];
  total.converged = total.converged && innerConverged;
  total.evaluations = innerEvaluations;
  return total;
}

}  // namespace

ReferenceAlbedo IntegrateReferenceAlbedo(const Ndf &ndf, SmithForm smith, double mu_o,
                                         double tolerance) {
  ReferenceAlbedo result;
  if (ndf.alpha == 0.0) {
    // A mirror: the only microfacet is n, the light is the mirror direction
    // with o.h = mu_o, and G2 = 1. Exact, no integral.
    const SchlickWeights fc = Schlick(mu_o);
    result.B = fc.fc;
    result.A = fc.complement;
    result.E = 1.0;
    result.converged = true;
    return result;
  }
  // A and B are integrated together, E taken as A + B. Integrated on its
  // own, E's adaptive refinement was seen to settle 1e-10 away from the truth
  // at grazing view and small alpha (mu_o = 1e-3, alpha = 1e-4) while A and
  // B, whose integrands split E's into a small and a large part, each agree
  // with independent values to 1e-13.
  const QuadratureResultN<2> ab = IntegrateSplitSum<SplitSumWeights>(ndf, smith, mu_o, tolerance);
  result.A = ab.value[0];
  result.B = ab.value[1];
  result.E = ab.value[0] + ab.value[1];
  result.error = ab.error[0] + ab.error[1];
  result.evaluations = ab.evaluations;
  result.converged = ab.converged;
  return result;
}

ReferenceF82 IntegrateReferenceF82(const Ndf &ndf, SmithForm smith, double mu_o, double tolerance) {
  ReferenceF82 result;
  if (ndf.alpha == 0.0) {
    // A mirror: o.h = mu_o and G2 = 1, so C = mu_o (1 - mu_o)^6. Exact.
    const double y = 1.0 - mu_o, y2 = y * y;
    result.C = mu_o * (y2 * y2 * y2);
    result.converged = true;
    return result;
  }
  const QuadratureResultN<1> c = IntegrateSplitSum<F82Weight>(ndf, smith, mu_o, tolerance);
  result.C = c.value[0];
  result.error = c.error[0];
  result.evaluations = c.evaluations;
  result.converged = c.converged;
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
  // E_avg = int_0^1 2 mu E(mu) dmu, taken over s with mu = s^2:
  // int_0^1 4 s^3 E(s^2) ds. E's singular term near grazing, c mu log(mu),
  // becomes 2 c s^2 log(s) times s^3, which the rule resolves with fewer
  // bisections: over GGX and Beckmann at r = 0.0156 to 0.98, 1.3x fewer
  // evaluations in all at tolerance 1e-8, each value within 1e-10 of the
  // same reference at 1e-11.
  const auto integrand = [&](double s) {
    const double mu = s * s;
    const ReferenceAlbedo e = IntegrateReferenceAlbedo(ndf, smith, mu, 0.1 * tolerance);
    worstInner = std::max(worstInner, e.error);
    result.evaluations += static_cast<uint64_t>(e.evaluations);
    innerConverged = innerConverged && e.converged;
    return 4.0 * s * mu * e.E;
  };
  // Breaks at mu = alpha and 8 alpha, where the grazing boundary layer ends.
  const double breaks[4] = {0.0, std::sqrt(std::min(1.0, ndf.alpha)),
                            std::sqrt(std::min(1.0, 8.0 * ndf.alpha)), 1.0};
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
