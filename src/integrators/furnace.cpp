#include "lutbake/integrators/furnace.h"

#include <array>
#include <cmath>
#include <vector>

#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/models/fresnel.h"
#include "lutbake/models/lambert.h"
#include "lutbake/models/schlick_ggx.h"
#include "lutbake/models/smith.h"

namespace lutbake {

namespace {

// The stated error from the Gauss-Kronrod estimates (furnace.h).
constexpr double kSafety = 16.0;
constexpr double kFloor = 1e-13;
// Channel 1 (an error density) is carried scaled down by this, so that its
// own Gauss-Kronrod estimate, which does not matter, never drives the
// refinement of channel 0.
constexpr double kErrorScale = 1e-3;

struct RawIntegral {
  double value = 0, error = 0;  // error: raw estimate, before kSafety
};

// int f over [breaks.front(), breaks.back()], f returning {value, density of
// an error already stated}: the result's error is the raw Gauss-Kronrod
// estimate of channel 0 plus the integral of channel 1 divided by kSafety,
// so that kSafety * error states both.
template <typename F>
RawIntegral Integrate(const F &f, std::vector<double> breaks, double rawTolerance) {
  std::vector<double> sorted;
  for (double b : breaks)
    if (sorted.empty() || b > sorted.back()) sorted.push_back(b);
  if (sorted.size() < 2) return {};
  const QuadratureResultN<2> r = IntegrateAdaptiveN<2>(
      [&](double x) {
        std::array<double, 2> v = f(x);
        v[1] *= kErrorScale;
        return v;
      },
      sorted, rawTolerance, 0.0, 20000);
  return {r.value[0], r.error[0] + r.value[1] / (kErrorScale * kSafety)};
}

FurnaceValue Stated(const RawIntegral &r) { return {r.value, kSafety * r.error + kFloor}; }

// int_ua^ub u^n g(u) du: u itself below uc = max(1/2, 1e-16^(1/(n+1))),
// t = u^(n+1) above it (u^n du = dt / (n + 1)), with breaks in t.
template <typename G>
RawIntegral PowerWeighted(double n, const G &g, double ua, double ub, double rawTolerance) {
  RawIntegral total;
  if (!(ub > ua)) return total;
  const double uc = std::max(0.5, std::pow(1e-16, 1.0 / (n + 1.0)));
  if (ua < uc) {
    const RawIntegral low = Integrate(
        [&](double u) {
          return std::array<double, 2>{std::pow(u, n) * g(u), 0.0};
        },
        {ua, std::min(ub, uc)}, 0.5 * rawTolerance);
    total.value += low.value;
    total.error += low.error;
  }
  if (ub > uc) {
    const double ta = std::pow(std::max(ua, uc), n + 1.0), tb = std::pow(ub, n + 1.0);
    std::vector<double> breaks{ta};
    for (double t : {1e-12, 1e-8, 1e-4, 1e-2})
      if (t > ta && t < tb) breaks.push_back(t);
    breaks.push_back(tb);
    const RawIntegral high = Integrate(
        [&](double t) {
          const double u = std::exp(std::log(t) / (n + 1.0));
          return std::array<double, 2>{g(u) / (n + 1.0), 0.0};
        },
        breaks, 0.5 * rawTolerance);
    total.value += high.value;
    total.error += high.error;
  }
  return total;
}

double Fresnel(const FurnaceModel &m, double cosine) {
  switch (m.fresnel) {
    case FurnaceFresnel::kOne: return 1.0;
    case FurnaceFresnel::kSchlick: return SchlickFresnel(m.f0, cosine);
    case FurnaceFresnel::kExact: return ExactFresnel(m.eta, m.k, cosine);
  }
  return 1.0;
}

bool IsSchlickGgx(FurnaceVisibility v) {
  return v == FurnaceVisibility::kSchlickGgxIbl || v == FurnaceVisibility::kSchlickGgxDirect;
}

double SchlickK(const FurnaceModel &m, double perceptualRoughness) {
  return SchlickGgxKFromRoughness(
      m.visibility == FurnaceVisibility::kSchlickGgxIbl ? SchlickGgxK::kIbl : SchlickGgxK::kDirect,
      perceptualRoughness);
}

// The microfacet albedo by nested adaptive Gauss-Kronrod over the half
// vector (furnace.h), Fresnel switched on or off.
RawIntegral NestedMicrofacetAlbedo(const FurnaceModel &m, double perceptualRoughness, double mu_o,
                                   bool withFresnel, double rawTolerance) {
  const double alpha = perceptualRoughness * perceptualRoughness;
  const Ndf ndf{m.ndf, alpha};
  const double s_o = SafeSqrt(1.0 - mu_o * mu_o);
  const bool schlickG = IsSchlickGgx(m.visibility);
  const double k = schlickG ? SchlickK(m, perceptualRoughness) : 0.0;
  const SmithForm smith = m.visibility == FurnaceVisibility::kSeparable ? SmithForm::kSeparable
                                                                        : SmithForm::kCorrelated;
  const double L_o = schlickG ? 0.0 : ndf.MuLambda(mu_o);
  // G2 / mu_o at the light cosine mu_i, finite at mu_o = 0.
  const auto gOverMu = [&](double mu_i) {
    if (mu_i <= 0.0) return 0.0;
    if (schlickG) return SchlickGgxG1(k, mu_i) / (mu_o * (1.0 - k) + k);
    return SmithG2OverMuO(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i));
  };
  // (1 / pi) (o.h / cos(theta_h)) (G2 / mu_o) F d(xi) / d(inner variable),
  // with T = tan(theta_h) and w = (s_o cos(phi) T + mu_o) d(xi)/d(var).
  const auto point = [&](double sc, double T, double w) {
    const double T2 = T * T;
    const double mu_i = (2.0 * T * sc + mu_o * (1.0 - T2)) / (1.0 + T2);
    const double oh = (sc * T + mu_o) / std::sqrt(1.0 + T2);
    const double F = withFresnel ? Fresnel(m, Clamp(oh, 0.0, 1.0)) : 1.0;
    return kInvPi * w * gOverMu(mu_i) * F;
  };
  const auto inner = [&](double phi) -> std::array<double, 2> {
    const double sc = s_o * std::cos(phi);
    // The horizon: mu_i > 0 <=> T < T_max = (sc + R) / mu_o = mu_o / (R - sc).
    const double R = std::sqrt(sc * sc + mu_o * mu_o);
    const double tMax = sc >= 0.0 ? (mu_o > 0.0 ? (sc + R) / mu_o : HUGE_VAL) : mu_o / (R - sc);
    RawIntegral r;
    if (m.ndf == NdfKind::kGgx) {
      // xi = sin^2(psi), T = alpha tan(psi), d(xi) = sin(2 psi) d(psi);
      // T d(xi)/d(psi) = 2 alpha sin^2(psi).
      const double psiMax = std::atan(tMax / alpha);
      r = Integrate(
          [&](double psi) {
            const double s = std::sin(psi), c = std::cos(psi);
            const double w = 2.0 * sc * alpha * s * s + mu_o * 2.0 * s * c;
            return std::array<double, 2>{point(sc, alpha * s / c, w), 0.0};
          },
          {0.0, 0.25 * psiMax, 0.5 * psiMax, 0.75 * psiMax, psiMax}, rawTolerance / 4.0);
    } else {
      // xi = 1 - exp(-t^2), T = alpha t, d(xi) = 2 t exp(-t^2) dt; beyond
      // t = 9 the NDF holds below exp(-81) of its mass.
      const double t1 = std::min(tMax / alpha, 9.0);
      r = Integrate(
          [&](double t) {
            const double w = (sc * alpha * t + mu_o) * 2.0 * t * std::exp(-t * t);
            return std::array<double, 2>{point(sc, alpha * t, w), 0.0};
          },
          {0.0, 0.25 * t1, 0.5 * t1, 0.75 * t1, t1}, rawTolerance / 4.0);
    }
    // Channel 1 is an already stated error density: the inner raw estimate
    // times kSafety.
    return {r.value, kSafety * r.error};
  };
  return Integrate(inner, {0.0, 0.25 * kPi, 0.5 * kPi, 0.75 * kPi, kPi}, rawTolerance / 2.0);
}

}  // namespace

std::string_view ToString(FurnaceModelKind kind) {
  switch (kind) {
    case FurnaceModelKind::kLambert: return "lambert";
    case FurnaceModelKind::kPhong: return "phong";
    case FurnaceModelKind::kBlinnPhong: return "blinn-phong";
    case FurnaceModelKind::kOrenNayar: return "oren-nayar";
    case FurnaceModelKind::kEon: return "eon";
    case FurnaceModelKind::kMicrofacet: return "microfacet";
  }
  return "lambert";
}

std::string_view ToString(FurnaceVisibility visibility) {
  switch (visibility) {
    case FurnaceVisibility::kCorrelated: return "correlated";
    case FurnaceVisibility::kSeparable: return "separable";
    case FurnaceVisibility::kSchlickGgxIbl: return "schlick-ggx-ibl";
    case FurnaceVisibility::kSchlickGgxDirect: return "schlick-ggx-direct";
  }
  return "correlated";
}

std::string_view ToString(FurnaceFresnel fresnel) {
  switch (fresnel) {
    case FurnaceFresnel::kOne: return "one";
    case FurnaceFresnel::kSchlick: return "schlick";
    case FurnaceFresnel::kExact: return "exact";
  }
  return "one";
}

FurnaceIntegrator::FurnaceIntegrator(const FurnaceModel &model, double parameter, double tolerance)
    : model_(model), parameter_(parameter), tolerance_(tolerance) {
  if (model_.kind != FurnaceModelKind::kMicrofacet || !model_.compensation || parameter_ <= 0.0)
    return;
  switch (model_.fresnel) {
    case FurnaceFresnel::kOne: fAvg_ = 1.0; break;
    case FurnaceFresnel::kSchlick: {
      const FresnelAverageResult r = SchlickFresnelAverage(model_.f0);
      fAvg_ = r.value;
      fAvgError_ = r.error;
      break;
    }
    case FurnaceFresnel::kExact: {
      const FresnelAverageResult r = ExactFresnelAverage(model_.eta, model_.k);
      fAvg_ = r.value;
      fAvgError_ = r.error;
      break;
    }
  }
  // I = 2 int_0^1 (1 - E(mu)) mu dmu, E's stated error carried as channel 1.
  const RawIntegral I = Integrate(
      [&](double mu) {
        const FurnaceValue E = WhiteMicrofacetAlbedo(mu);
        return std::array<double, 2>{2.0 * mu * (1.0 - E.value), 2.0 * mu * E.error};
      },
      {0.0, 1e-3, 1e-2, 0.05, 0.2, 0.5, 1.0}, tolerance_ / kSafety);
  I_ = I.value;
  IError_ = kSafety * I.error + kFloor;
  if (IsSchlickGgx(model_.visibility)) {
    eAvg_ = 1.0 - I_;
    eAvgError_ = IError_;
  } else {
    const AverageQuadrature avg = IntegrateAverageQuadrature(
        Ndf{model_.ndf, parameter_ * parameter_},
        model_.visibility == FurnaceVisibility::kSeparable ? SmithForm::kSeparable
                                                           : SmithForm::kCorrelated,
        0.1 * tolerance_);
    eAvg_ = avg.value;
    eAvgError_ = avg.bound;
  }
}

FurnaceValue FurnaceIntegrator::WhiteMicrofacetAlbedo(double mu_o) const {
  const double r = parameter_;
  if (r <= 0.0) {
    // The mirror: G2 at the mirror direction (1 for exact Smith).
    if (!IsSchlickGgx(model_.visibility)) return {1.0, 0.0};
    const double g = SchlickGgxG1(SchlickK(model_, 0.0), mu_o);
    return {g * g, 0.0};
  }
  if (!IsSchlickGgx(model_.visibility)) {
    const SplitSumQuadrature q = IntegrateSplitSumQuadrature(
        Ndf{model_.ndf, r * r},
        model_.visibility == FurnaceVisibility::kSeparable ? SmithForm::kSeparable
                                                           : SmithForm::kCorrelated,
        mu_o, 0.1 * tolerance_, false);
    return {q.A + q.B, q.boundE};
  }
  return Stated(NestedMicrofacetAlbedo(model_, r, mu_o, false, tolerance_ / kSafety));
}

FurnaceValue FurnaceIntegrator::SingleScattering(double mu_o) const {
  const double rawTolerance = tolerance_ / kSafety;
  const double p = parameter_;
  const double theta_o = std::acos(Clamp(mu_o, 0.0, 1.0));
  const auto diffuse = [&](const auto &ring) {
    return Stated(Integrate(
        [&](double theta_i) {
          return std::array<double, 2>{std::sin(theta_i) * ring(theta_i), 0.0};
        },
        {0.0, theta_o, 0.5 * kPi}, rawTolerance));
  };
  switch (model_.kind) {
    case FurnaceModelKind::kLambert:
      return diffuse([](double theta_i) { return 2.0 * kPi * kLambertBrdf * std::cos(theta_i); });
    case FurnaceModelKind::kOrenNayar:
      return diffuse([&](double theta_i) {
        return OrenNayarCosineRing(model_.orenNayar, p, theta_o, theta_i);
      });
    case FurnaceModelKind::kEon:
      return diffuse(
          [&](double theta_i) { return EonCosineRing(model_.eon, p, theta_o, theta_i); });
    case FurnaceModelKind::kPhong: {
      const double c = PhongNormalisationFactor(model_.phong, p);
      const double s_o = SafeSqrt(1.0 - mu_o * mu_o);
      const auto W = [&](double u) { return PhongConeIntegral(mu_o, u); };
      RawIntegral a = PowerWeighted(p, W, 0.0, s_o, 0.5 * rawTolerance / c);
      const RawIntegral b = PowerWeighted(p, W, s_o, 1.0, 0.5 * rawTolerance / c);
      return Stated({c * (a.value + b.value), c * (a.error + b.error)});
    }
    case FurnaceModelKind::kBlinnPhong: {
      const double c = BlinnPhongNormalisationFactor(model_.blinnPhong, p);
      const BlinnPhongBreaks breaks = BlinnPhongHorizonBreaks(mu_o);
      const auto P = [&](double u) { return BlinnPhongRingIntegral(mu_o, u); };
      const RawIntegral a = PowerWeighted(p, P, breaks.none, breaks.full, 0.5 * rawTolerance / c);
      const RawIntegral b = PowerWeighted(p, P, breaks.full, 1.0, 0.5 * rawTolerance / c);
      return Stated({c * (a.value + b.value), c * (a.error + b.error)});
    }
    case FurnaceModelKind::kMicrofacet: break;
  }
  // Microfacet.
  const double r = p;
  if (r <= 0.0) {
    const FurnaceValue g = WhiteMicrofacetAlbedo(mu_o);
    return {Fresnel(model_, mu_o) * g.value, 0.0};
  }
  if (!IsSchlickGgx(model_.visibility) && model_.fresnel != FurnaceFresnel::kExact) {
    const bool schlick = model_.fresnel == FurnaceFresnel::kSchlick;
    const SplitSumQuadrature q = IntegrateSplitSumQuadrature(
        Ndf{model_.ndf, r * r},
        model_.visibility == FurnaceVisibility::kSeparable ? SmithForm::kSeparable
                                                           : SmithForm::kCorrelated,
        mu_o, 0.1 * tolerance_, schlick);
    if (!schlick) return {q.A + q.B, q.boundE};
    // F = F0 + (1 - F0) Fc = F0 (1 - Fc) + Fc: albedo = F0 A + B.
    return {model_.f0 * q.A + q.B, model_.f0 * q.boundA + q.boundB};
  }
  return Stated(NestedMicrofacetAlbedo(model_, r, mu_o, true, rawTolerance));
}

FurnacePoint FurnaceIntegrator::Albedo(double mu_o) const {
  FurnacePoint point;
  point.singleScattering = SingleScattering(mu_o);
  point.albedo = point.singleScattering;
  if (model_.kind != FurnaceModelKind::kMicrofacet || !model_.compensation || parameter_ <= 0.0 ||
      !(1.0 - eAvg_ > 0.0))
    return point;
  const FurnaceValue E = WhiteMicrofacetAlbedo(mu_o);
  const double oneMinusEavg = 1.0 - eAvg_;
  const double D = 1.0 - fAvg_ * oneMinusEavg;
  // F_ms = F_avg^p E_avg / D, p = 2 (Kulla-Conty) or 1 (furnace.h).
  const double fPower = model_.msFresnelSquared ? fAvg_ : 1.0;
  const double fMs = fPower * fAvg_ * eAvg_ / D;
  const double ratio = I_ / oneMinusEavg;
  const double lobe = fMs * (1.0 - E.value) * ratio;
  // First-order propagation of the errors of E, I, E_avg and F_avg, with 1%
  // for the second-order terms.
  // d F_ms / d E_avg = F^p (1 - F) / D^2; d F_ms / d F_avg = E / D^2 (p = 1),
  // F E (2 - F (1 - E)) / D^2 (p = 2).
  const double dF = model_.msFresnelSquared ? fAvg_ * eAvg_ * (2.0 - fAvg_ * oneMinusEavg) / (D * D)
                                            : eAvg_ / (D * D);
  const double fMsError = fPower * fAvg_ * (1.0 - fAvg_) / (D * D) * eAvgError_ + dF * fAvgError_;
  const double lobeError =
      fMs *
          (E.error * ratio + (1.0 - E.value) * (IError_ / oneMinusEavg +
                                                I_ * eAvgError_ / (oneMinusEavg * oneMinusEavg))) +
      (1.0 - E.value) * ratio * fMsError;
  point.albedo = {point.singleScattering.value + lobe,
                  point.singleScattering.error + 1.01 * lobeError + kFloor};
  return point;
}

FurnaceValue FurnaceIntegrator::Average() const {
  const RawIntegral r = Integrate(
      [&](double mu) {
        const FurnaceValue a = Albedo(mu).albedo;
        return std::array<double, 2>{2.0 * mu * a.value, 2.0 * mu * a.error};
      },
      {0.0, 1e-3, 1e-2, 0.05, 0.2, 0.5, 1.0}, tolerance_ / kSafety);
  return Stated(r);
}

}  // namespace lutbake
