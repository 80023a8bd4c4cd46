// Highway compiles this file once per instruction set (foreach_target.h
// includes it again for each); HWY_DYNAMIC_DISPATCH picks one at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "integrators/dielectric_kernel.cpp"
#include "integrators/dielectric_kernel.h"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace lutbake::kernel {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// G2 / G1(o) of smith.h at the cosine m = mN / mD (mD > 0; lanes where
// `valid`, others 0), as a numerator and a denominator (the caller divides
// once for everything), with m clamped to at most 1. With L = m Lambda(m) =
// a2s2 / (2 (root + m)), root = sqrt(m^2 + a2s2), a2s2 = alpha^2 (1 - m)(1 +
// m) (ggx.h):
//   correlated: m (mu_o + L_o) / (mu_o m + m L_o + mu_o L),
//   separable:  m / (m + L),
// both multiplied through by d = 2 (root + m), and every length by mD (the
// ratio is homogeneous of degree 0 in m, root and d; a2s2 of degree 2):
//   correlated: mN (mu_o + L_o) d' / ((mu_o mN + mN L_o) d' + mu_o a2s2'),
//   separable:  mN d' / (mN d' + a2s2'),
// a2s2' = alpha^2 (mD - mN)(mD + mN), d' = 2 (sqrt(mN^2 + a2s2') + mN).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void SmithParts(D d, const DielectricConstants &k, V mN, V mD, hn::Mask<D> valid,
                           V *numerator, V *denominator) {
  const V two = hn::Set(d, 2.0), zero = hn::Zero(d);
  const V alpha2 = hn::Set(d, k.alpha * k.alpha);
  // Lanes outside `valid` computed at m = 1 (finite everywhere), then zeroed.
  const V m = hn::IfThenElse(valid, hn::Min(mN, mD), mD);
  const V a2s2 = hn::Mul(alpha2, hn::Max(zero, hn::Mul(hn::Sub(mD, m), hn::Add(mD, m))));
  const V root = hn::Sqrt(hn::Add(hn::Mul(m, m), a2s2));
  const V dd = hn::Mul(two, hn::Add(root, m));
  if (k.smith == SmithForm::kCorrelated) {
    const V mu_o = hn::Set(d, k.mu_o), L_o = hn::Set(d, k.L_o);
    *denominator =
        hn::Add(hn::Mul(hn::Add(hn::Mul(mu_o, m), hn::Mul(m, L_o)), dd), hn::Mul(mu_o, a2s2));
    *numerator = hn::IfThenElseZero(valid, hn::Mul(hn::Mul(m, hn::Set(d, k.mu_o + k.L_o)), dd));
  } else {
    const V md = hn::Mul(m, dd);
    *denominator = hn::Add(md, a2s2);
    *numerator = hn::IfThenElseZero(valid, md);
  }
}

// The facet weight as wN / wD (wD > 0), before the clamp to at most 1 and
// the mask of visible facets (c > 0).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void WeightParts(D d, const DielectricConstants &k, V c, V hz, V muR, V *wN, V *wD) {
  const V one = hn::Set(d, 1.0), zero = hn::Zero(d), half = hn::Set(d, 0.5), four = hn::Set(d, 4.0);
  const double e2m1s = (k.eta - 1.0) * (k.eta + 1.0);
  const V e2m1 = hn::Set(d, e2m1s), eta2 = hn::Set(d, k.eta * k.eta);
  const V cc = hn::Min(hn::Max(c, zero), one);
  const V W2 = hn::Add(e2m1, hn::Mul(cc, cc));
  const auto refracts = hn::Gt(W2, zero);
  const V W = hn::Sqrt(hn::IfThenElseZero(refracts, W2));
  // The squared denominators, 1 where the facet reflects totally (unused),
  // inverted by one division: 1 / S^2 = P^2 / (S^2 P^2) and alike (S^2 P^2
  // between ~1e-9 and ~1e13 on eta in [1/128, 128]).
  const V sDen = hn::Add(cc, W), pDen = hn::Add(hn::Mul(eta2, cc), W);
  const V S2 = hn::IfThenElse(refracts, hn::Mul(sDen, sDen), one);
  const V P2 = hn::IfThenElse(refracts, hn::Mul(pDen, pDen), one);
  const V invSP = hn::Div(one, hn::Mul(S2, P2));
  const V invS = hn::Mul(P2, invSP), invP = hn::Mul(S2, invSP);
  const V rs = hn::Mul(hn::Neg(e2m1), invS);
  const V rp = hn::Mul(
      hn::Mul(e2m1, hn::Sub(hn::Mul(hn::Set(d, k.eta * k.eta + 1.0), hn::Mul(cc, cc)), one)), invP);
  const V ccW4 = hn::Mul(four, hn::Mul(cc, W));
  const V ts = hn::Mul(ccW4, invS), tp = hn::Mul(hn::Mul(eta2, ccW4), invP);
  const V F = hn::IfThenElse(
      refracts,
      hn::Min(hn::Max(hn::Mul(half, hn::Add(hn::Mul(rs, rs), hn::Mul(rp, rp))), zero), one), one);
  const V T =
      hn::IfThenElseZero(refracts, hn::Min(hn::Max(hn::Mul(half, hn::Add(ts, tp)), zero), one));
  const auto reflects = hn::And(hn::Gt(muR, zero), hn::Gt(F, zero));
  V nR, dR;
  SmithParts(d, k, muR, one, reflects, &nR, &dR);
  if (k.lobes == DielectricLobes::kReflectionAndTransmission) {
    // -mu_t = (mu_o - (c - W) h.z) / eta with c - W = (1 - eta^2) / (c + W)
    // (exact at eta = 1), = (mu_o (c + W) + (eta^2 - 1) h.z) / (eta (c + W));
    // c + W > 0 where T > 0.
    const auto transmits = hn::Gt(T, zero);
    const V cpw = hn::IfThenElse(transmits, hn::Add(c, W), one);
    const V tN = hn::Add(hn::Mul(hn::Set(d, k.mu_o), cpw), hn::Mul(e2m1, hz));
    const V tD = hn::Mul(hn::Set(d, k.eta), cpw);
    const auto below = hn::And(transmits, hn::Gt(tN, zero));
    V nT, dT;
    SmithParts(d, k, tN, tD, below, &nT, &dT);
    // F nR / dR + T nT / dT over the common denominator.
    *wN = hn::Add(hn::Mul(hn::Mul(F, nR), dT), hn::Mul(hn::Mul(T, nT), dR));
    *wD = hn::Mul(dR, dT);
  } else {
    *wN = hn::Mul(F, nR);
    *wD = dR;
  }
}

// The weight itself: min(wN, wD) / wD (at most 1), 0 where c <= 0.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V WeightLanes(D d, const DielectricConstants &k, V c, V hz, V muR) {
  V wN, wD;
  WeightParts(d, k, c, hz, muR, &wN, &wD);
  return hn::IfThenElseZero(hn::Gt(c, hn::Zero(d)), hn::Div(hn::Min(wN, wD), wD));
}

constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);

void DielectricWeightsImpl(const DielectricConstants &k, const double *c, const double *hz,
                           const double *muR, size_t n, double *w) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes)
    hn::StoreU(WeightLanes(d, k, hn::LoadU(d, c + i), hn::LoadU(d, hz + i), hn::LoadU(d, muR + i)),
               d, w + i);
  if (i < n) {
    // The last facets padded with c = 0 (weight 0), through a buffer.
    HWY_ALIGN double bc[kMaxLanes] = {}, bh[kMaxLanes] = {}, bm[kMaxLanes] = {}, bw[kMaxLanes];
    for (size_t j = 0; i + j < n; ++j) {
      bc[j] = c[i + j];
      bh[j] = hz[i + j];
      bm[j] = muR[i + j];
    }
    hn::Store(WeightLanes(d, k, hn::Load(d, bc), hn::Load(d, bh), hn::Load(d, bm)), d, bw);
    for (size_t j = 0; i + j < n; ++j) w[i + j] = bw[j];
  }
}

// One vector of nodes (see DielectricTerms).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V TermLanes(D d, const DielectricConstants &k, V sc, bool tail, V v, V ruleJac) {
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  const V alpha = hn::Set(d, k.alpha), mu_o = hn::Set(d, k.mu_o);
  const V q = hn::Add(one, hn::Mul(v, v)), q2 = hn::Mul(q, q);
  V cosTheta, sinTheta, c, numerator;
  if (tail) {
    const V r = hn::Sqrt(hn::Add(hn::Mul(v, v), hn::Mul(alpha, alpha)));
    const V invR = hn::Div(one, r);
    cosTheta = hn::Mul(v, invR);
    sinTheta = hn::Mul(alpha, invR);
    c = hn::Add(hn::Mul(sc, sinTheta), hn::Mul(mu_o, cosTheta));
    numerator = hn::Mul(hn::Mul(two, c), r);
  } else {
    const V T = hn::Mul(alpha, v);
    cosTheta = hn::Div(one, hn::Sqrt(hn::Add(one, hn::Mul(T, T))));
    sinTheta = hn::Mul(T, cosTheta);
    c = hn::Add(hn::Mul(sc, sinTheta), hn::Mul(mu_o, cosTheta));
    numerator = hn::Mul(hn::Mul(hn::Add(hn::Mul(sc, T), mu_o), two), v);
  }
  const V muR = hn::Sub(hn::Mul(hn::Mul(two, c), cosTheta), mu_o);
  // ruleJac numerator / q2 invNorm w, w = min(wN, wD) / wD: one division.
  V wN, wD;
  WeightParts(d, k, c, cosTheta, muR, &wN, &wD);
  const V term =
      hn::Div(hn::Mul(hn::Mul(ruleJac, hn::Mul(numerator, hn::Set(d, k.invNorm))), hn::Min(wN, wD)),
              hn::Mul(q2, wD));
  return hn::IfThenElseZero(hn::Gt(c, hn::Zero(d)), term);
}

void DielectricTermsImpl(const DielectricConstants &k, double sc, bool tail, const double *v,
                         const double *ruleJac, size_t n, double *terms) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  const auto vsc = hn::Set(d, sc);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes)
    hn::StoreU(TermLanes(d, k, vsc, tail, hn::LoadU(d, v + i), hn::LoadU(d, ruleJac + i)), d,
               terms + i);
  if (i < n && n >= lanes) {
    // The last whole vector, ending at n: its first lanes recompute terms
    // already stored, to the same bits (each lane is computed alone).
    i = n - lanes;
    hn::StoreU(TermLanes(d, k, vsc, tail, hn::LoadU(d, v + i), hn::LoadU(d, ruleJac + i)), d,
               terms + i);
  } else if (i < n) {
    // Padded with v = 1/2 and weight 0 (the term is then 0).
    HWY_ALIGN double bv[kMaxLanes], bj[kMaxLanes] = {}, bt[kMaxLanes];
    for (size_t j = 0; j < kMaxLanes; ++j) bv[j] = 0.5;
    for (size_t j = 0; i + j < n; ++j) {
      bv[j] = v[i + j];
      bj[j] = ruleJac[i + j];
    }
    hn::Store(TermLanes(d, k, vsc, tail, hn::Load(d, bv), hn::Load(d, bj)), d, bt);
    for (size_t j = 0; i + j < n; ++j) terms[i + j] = bt[j];
  }
}

// One vector of an arc's nodes (see ArcTerms): ArcTermScalar's operations,
// lane by lane.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ArcLanes(D d, const ArcConstants &k, V v, V ruleW) {
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), zero = hn::Zero(d);
  const V alpha2 = hn::Set(d, k.alpha2);
  const V v2 = hn::Mul(v, v);
  const V den = hn::Add(one, v2), num = hn::Sub(one, v2);
  const V o = hn::Add(hn::Mul(hn::Set(d, k.a), den), hn::Mul(hn::Set(d, k.ka), num));
  const V i = hn::Mul(hn::Add(hn::Mul(hn::Set(d, k.b), den), hn::Mul(hn::Set(d, k.kb), num)),
                      hn::Set(d, k.invDivisor));
  const V mo0 = hn::Min(o, den), mi0 = hn::Min(i, den);
  const auto valid = hn::And(hn::Gt(mo0, zero), hn::Gt(mi0, zero));
  // Invalid pairs computed at 1 (finite) and dropped below.
  const V mo = hn::IfThenElse(valid, mo0, den), mi = hn::IfThenElse(valid, mi0, den);
  const V so = hn::Mul(alpha2, hn::Max(hn::Mul(hn::Sub(den, mo), hn::Add(den, mo)), zero));
  const V si = hn::Mul(alpha2, hn::Max(hn::Mul(hn::Sub(den, mi), hn::Add(den, mi)), zero));
  const V dO = hn::Mul(two, hn::Add(hn::Sqrt(hn::Add(hn::Mul(mo, mo), so)), mo));
  const V dI = hn::Mul(two, hn::Add(hn::Sqrt(hn::Add(hn::Mul(mi, mi), si)), mi));
  V numerator, denominator;
  if (k.smith == SmithForm::kCorrelated) {
    const V p = hn::Mul(hn::Mul(mo, mi), hn::Mul(dO, dI));
    numerator = p;
    denominator = hn::Add(hn::Add(p, hn::Mul(hn::Mul(mi, so), dI)), hn::Mul(hn::Mul(mo, si), dO));
  } else {
    const V po = hn::Mul(mo, dO), pi = hn::Mul(mi, dI);
    numerator = hn::Mul(po, pi);
    denominator = hn::Mul(hn::Add(po, so), hn::Add(pi, si));
  }
  const V g = hn::Div(hn::Mul(ruleW, numerator), hn::Mul(den, denominator));
  return hn::IfThenElseZero(valid, g);
}

void ArcTermsImpl(const ArcConstants &k, const double *v, const double *ruleW, size_t n,
                  double *terms) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes)
    hn::StoreU(ArcLanes(d, k, hn::LoadU(d, v + i), hn::LoadU(d, ruleW + i)), d, terms + i);
  if (i < n) {
    // Padded with v = 0 and weight 0 (the term is then 0).
    HWY_ALIGN double bv[kMaxLanes] = {}, bw[kMaxLanes] = {}, bt[kMaxLanes];
    for (size_t j = 0; i + j < n; ++j) {
      bv[j] = v[i + j];
      bw[j] = ruleW[i + j];
    }
    hn::Store(ArcLanes(d, k, hn::Load(d, bv), hn::Load(d, bw)), d, bt);
    for (size_t j = 0; i + j < n; ++j) terms[i + j] = bt[j];
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace lutbake::kernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lutbake::kernel {

HWY_EXPORT(DielectricWeightsImpl);
HWY_EXPORT(DielectricTermsImpl);
HWY_EXPORT(ArcTermsImpl);

void ArcTerms(const ArcConstants &constants, const double *v, const double *ruleW, size_t n,
              double *terms) {
  HWY_DYNAMIC_DISPATCH(ArcTermsImpl)(constants, v, ruleW, n, terms);
}

double ArcTermScalar(const ArcConstants &k, double v, double ruleW) {
  // Every cosine and length times den = 1 + v^2 (cos(psi) = num / den): G2
  // is homogeneous of degree 0 in them, and the one division also takes
  // the measure's 1 / den.
  const double den = 1.0 + v * v, num = 1.0 - v * v;
  const double o = k.a * den + k.ka * num, i = (k.b * den + k.kb * num) * k.invDivisor;
  const double mo = o < den ? o : den, mi = i < den ? i : den;
  if (!(mo > 0.0 && mi > 0.0)) return 0.0;
  const double so = k.alpha2 * std::max((den - mo) * (den + mo), 0.0);
  const double si = k.alpha2 * std::max((den - mi) * (den + mi), 0.0);
  const double dO = 2.0 * (std::sqrt(mo * mo + so) + mo), dI = 2.0 * (std::sqrt(mi * mi + si) + mi);
  double numerator = 0.0, denominator = 1.0;
  if (k.smith == SmithForm::kCorrelated) {
    const double p = (mo * mi) * (dO * dI);
    numerator = p;
    denominator = (p + (mi * so) * dI) + (mo * si) * dO;
  } else {
    const double po = mo * dO, pi = mi * dI;
    numerator = po * pi;
    denominator = (po + so) * (pi + si);
  }
  return (ruleW * numerator) / (den * denominator);
}

void DielectricTerms(const DielectricConstants &constants, double sc, bool tail, const double *v,
                     const double *ruleJac, size_t n, double *terms) {
  HWY_DYNAMIC_DISPATCH(DielectricTermsImpl)(constants, sc, tail, v, ruleJac, n, terms);
}

void DielectricWeights(const DielectricConstants &constants, const double *c, const double *hz,
                       const double *muR, size_t n, double *w) {
  HWY_DYNAMIC_DISPATCH(DielectricWeightsImpl)(constants, c, hz, muR, n, w);
}

namespace {

// SmithParts, one lane.
void SmithPartsScalar(const DielectricConstants &k, double mN, double mD, bool valid,
                      double *numerator, double *denominator) {
  const double m = valid ? std::min(mN, mD) : mD;
  const double a2s2 = k.alpha * k.alpha * std::max(0.0, (mD - m) * (mD + m));
  const double root = std::sqrt(m * m + a2s2);
  const double dd = 2.0 * (root + m);
  if (k.smith == SmithForm::kCorrelated) {
    *denominator = (k.mu_o * m + m * k.L_o) * dd + k.mu_o * a2s2;
    *numerator = valid ? m * (k.mu_o + k.L_o) * dd : 0.0;
  } else {
    const double md = m * dd;
    *denominator = md + a2s2;
    *numerator = valid ? md : 0.0;
  }
}

}  // namespace

double DielectricWeightScalar(const DielectricConstants &k, double c, double hz, double muR) {
  const double e2m1 = (k.eta - 1.0) * (k.eta + 1.0), eta2 = k.eta * k.eta;
  const double cc = std::min(std::max(c, 0.0), 1.0);
  const double W2 = e2m1 + cc * cc;
  double F = 1.0, T = 0.0, W = 0.0;
  if (W2 > 0.0) {
    W = std::sqrt(W2);
    const double sDen = cc + W, pDen = eta2 * cc + W;
    const double S2 = sDen * sDen, P2 = pDen * pDen, invSP = 1.0 / (S2 * P2);
    const double invS = P2 * invSP, invP = S2 * invSP;
    const double rs = -e2m1 * invS;
    const double rp = e2m1 * ((eta2 + 1.0) * (cc * cc) - 1.0) * invP;
    const double ccW4 = 4.0 * (cc * W);
    const double ts = ccW4 * invS, tp = (eta2 * ccW4) * invP;
    F = std::min(std::max(0.5 * (rs * rs + rp * rp), 0.0), 1.0);
    T = std::min(std::max(0.5 * (ts + tp), 0.0), 1.0);
  }
  double nR = 0.0, dR = 1.0;
  SmithPartsScalar(k, muR, 1.0, muR > 0.0 && F > 0.0, &nR, &dR);
  double wN = F * nR, wD = dR;
  if (k.lobes == DielectricLobes::kReflectionAndTransmission) {
    const bool transmits = T > 0.0;
    const double cpw = transmits ? c + W : 1.0;
    const double tN = k.mu_o * cpw + e2m1 * hz, tD = k.eta * cpw;
    double nT = 0.0, dT = 1.0;
    SmithPartsScalar(k, tN, tD, transmits && tN > 0.0, &nT, &dT);
    wN = (F * nR) * dT + (T * nT) * dR;
    wD = dR * dT;
  }
  if (!(c > 0.0)) return 0.0;
  return std::min(wN, wD) / wD;
}

}  // namespace lutbake::kernel
#endif
