// Highway compiles this file once per instruction set (foreach_target.h
// includes it again for each); HWY_DYNAMIC_DISPATCH picks one at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "integrators/albedo_kernel.cpp"
#include "integrators/albedo_kernel.h"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace lutbake::kernel {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// The weighted integrand at x with weight `weight` (one node in each lane),
// written with two divisions and two square roots. With u = 1 + x^2:
//   core (T = alpha x):  1 + T^2 = s,          s = 1 + alpha^2 x^2,
//                        mu_i (1 + T^2) = 2 alpha x sc + mu_o (1 - alpha^2 x^2),
//                        density (o.h / cos(theta)) = 2 x (alpha x sc + mu_o) / u^2;
//   tail (T = alpha / x): 1 + T^2 = s / x^2,  s = x^2 + alpha^2,
//                        mu_i (1 + T^2) x^2 = 2 alpha x sc + mu_o (x^2 - alpha^2),
//                        density (o.h / cos(theta)) = 2 (alpha sc + mu_o x) / u^2.
// In both, with r = 1 / (s u^2): mu_i = N u^2 r, o.h = Q u sqrt(r) and
// density (o.h / cos(theta)) = 2 P s r, where N, Q and P are the numerators
// above (Q = alpha x sc + mu_o, P = x Q in the core; Q = P = alpha sc + mu_o x
// in the tail). And with L_i = mu_i
// Lambda(mu_i) = a2s2 / (2 (root + mu_i)), root = sqrt(mu_i^2 + a2s2),
// a2s2 = alpha^2 (1 - mu_i^2) (ggx.h), G2 / mu_o (smith.h) is
//   correlated: 2 mu_i (root + mu_i) / (2 mu_i (root + mu_i) (mu_o + L_o) + mu_o a2s2),
//   separable:  2 mu_i (root + mu_i) / ((mu_o + L_o) (2 mu_i (root + mu_i) + a2s2)).
//
// With kF82, also the F82 weight (o.h) (1 - o.h)^6 = oh y^6 into c, computed
// after and apart from a and b, which are then the same bits as without it.
template <bool kF82, class D, class V = hn::Vec<D>>
HWY_INLINE void GgxSplitSumLanes(D d, const GgxSplitSumConstants &k, bool tail, V x, V sc, V weight,
                                 V *a, V *b, V *c) {
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), zero = hn::Zero(d);
  const V alpha = hn::Set(d, k.alpha), alpha2 = hn::Set(d, k.alpha * k.alpha);
  const V mu_o = hn::Set(d, k.mu_o), muL_o = hn::Set(d, k.mu_o + k.L_o);
  const V x2 = hn::Mul(x, x), u = hn::Add(one, x2), u2 = hn::Mul(u, u);
  const V ax = hn::Mul(alpha, x), a2x2 = hn::Mul(alpha2, x2);
  V s, N, Q, P;
  if (tail) {
    s = hn::Add(x2, alpha2);
    N = hn::Add(hn::Mul(hn::Mul(two, ax), sc), hn::Mul(mu_o, hn::Sub(x2, alpha2)));
    Q = hn::Add(hn::Mul(alpha, sc), hn::Mul(mu_o, x));
    P = Q;
  } else {
    s = hn::Add(one, a2x2);
    N = hn::Add(hn::Mul(hn::Mul(two, ax), sc), hn::Mul(mu_o, hn::Sub(one, a2x2)));
    Q = hn::Add(hn::Mul(ax, sc), mu_o);
    P = hn::Mul(x, Q);
  }
  const V r = hn::Div(one, hn::Mul(s, u2));
  const V mu_i = hn::Mul(hn::Mul(N, u2), r);
  const V densityQ = hn::Mul(hn::Mul(two, P), hn::Mul(s, r));
  const V oh = hn::Mul(hn::Mul(Q, u), hn::Sqrt(r));
  const V a2s2 = hn::Mul(alpha2, hn::Mul(hn::Sub(one, mu_i), hn::Add(one, mu_i)));
  const V root = hn::Sqrt(hn::Add(hn::Mul(mu_i, mu_i), a2s2));
  const V m = hn::Mul(hn::Mul(two, mu_i), hn::Add(root, mu_i));  // 2 mu_i (root + mu_i)
  V g;
  if (k.fitted == FittedVisibility::kSchlickGgx) {
    // G1(mu_i) G1(mu_o) / mu_o = mu_i / ((mu_i (1 - k) + k) (mu_o (1 - k) + k)).
    const V kk = hn::Set(d, k.fitParameter), onek = hn::Set(d, 1.0 - k.fitParameter);
    const V denominatorO = hn::Set(d, k.mu_o * (1.0 - k.fitParameter) + k.fitParameter);
    g = hn::Div(mu_i, hn::Mul(hn::Add(hn::Mul(mu_i, onek), kk), denominatorO));
  } else if (k.fitted == FittedVisibility::kSmithJointApprox) {
    // G2 / mu_o = 2 mu_i / (mu_i (mu_o (1 - a) + a) + mu_o (mu_i (1 - a) + a)).
    const V a = hn::Set(d, k.fitParameter), onea = hn::Set(d, 1.0 - k.fitParameter);
    const V termO = hn::Set(d, k.mu_o * (1.0 - k.fitParameter) + k.fitParameter);
    g = hn::Div(hn::Mul(two, mu_i),
                hn::Add(hn::Mul(mu_i, termO), hn::Mul(mu_o, hn::Add(hn::Mul(mu_i, onea), a))));
  } else {
    g = k.smith == SmithForm::kCorrelated
            ? hn::Div(m, hn::Add(hn::Mul(m, muL_o), hn::Mul(mu_o, a2s2)))
            : hn::Div(m, hn::Mul(muL_o, hn::Add(m, a2s2)));
  }
  const auto visible = hn::And(hn::Gt(mu_i, zero), hn::Gt(Q, zero));
  const V f = hn::IfThenElseZero(visible, hn::Mul(hn::Mul(weight, densityQ), g));
  // Schlick: Fc = y^5, 1 - Fc = oh (1 + y + y^2 + y^3 + y^4), y = 1 - oh (math.h).
  const V y = hn::Sub(one, oh), y2 = hn::Mul(y, y);
  const V fc = hn::Mul(hn::Mul(y2, y2), y);
  const V complement =
      hn::Mul(oh, hn::Add(hn::Add(hn::Add(one, y), hn::Add(y2, hn::Mul(y2, y))), hn::Mul(y2, y2)));
  *a = hn::Mul(f, complement);
  *b = hn::Mul(f, fc);
  if constexpr (kF82) *c = hn::Mul(f, hn::Mul(oh, hn::Mul(fc, y)));  // f oh y^6
}

// The partial sums: panel p goes into sum p mod 8 at every vector width.
constexpr size_t kPartialSums = 8;

template <bool kF82>
void SumGgxSplitSumLoop(const GgxSplitSumConstants &k, bool tail, int ruleNodes,
                        const double *ruleX, const double *ruleW, const Panels &panels,
                        double *sums) {
  const hn::CappedTag<double, kPartialSums> d;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d), parts = kPartialSums / lanes;
  // The partial sums live in memory (arrays of vectors are not portable).
  double partA[kPartialSums] = {}, partB[kPartialSums] = {}, partC[kPartialSums] = {};
  // Eight panels at a time, one per lane; their nodes one after the other.
  const auto block = [&](const double *from, const double *width, const double *sc,
                         const double *scale) {
    for (size_t p = 0; p < parts; ++p) {
      const size_t o = p * lanes;
      const V vfrom = hn::LoadU(d, from + o), vwidth = hn::LoadU(d, width + o);
      const V vsc = hn::LoadU(d, sc + o), vscale = hn::LoadU(d, scale + o);
      V sumA = hn::LoadU(d, partA + o), sumB = hn::LoadU(d, partB + o);
      V sumC = hn::LoadU(d, partC + o);
      for (int i = 0; i < ruleNodes; ++i) {
        V a, b, c;
        const V x = hn::Add(vfrom, hn::Mul(vwidth, hn::Set(d, ruleX[i])));
        GgxSplitSumLanes<kF82>(d, k, tail, x, vsc, hn::Mul(vscale, hn::Set(d, ruleW[i])), &a, &b,
                               &c);
        sumA = hn::Add(sumA, a);
        sumB = hn::Add(sumB, b);
        if constexpr (kF82) sumC = hn::Add(sumC, c);
      }
      hn::StoreU(sumA, d, partA + o);
      hn::StoreU(sumB, d, partB + o);
      if constexpr (kF82) hn::StoreU(sumC, d, partC + o);
    }
  };
  size_t p = 0;
  for (; p + kPartialSums <= panels.n; p += kPartialSums)
    block(panels.from + p, panels.width + p, panels.sc + p, panels.scale + p);
  if (p < panels.n) {
    // The last panels padded with weight 0 on [1, 2]: adding 0 leaves every
    // partial sum as it was.
    double from[kPartialSums], width[kPartialSums], sc[kPartialSums], scale[kPartialSums];
    for (size_t j = 0; j < kPartialSums; ++j) {
      const bool real = p + j < panels.n;
      from[j] = real ? panels.from[p + j] : 1.0;
      width[j] = real ? panels.width[p + j] : 1.0;
      sc[j] = real ? panels.sc[p + j] : 0.0;
      scale[j] = real ? panels.scale[p + j] : 0.0;
    }
    block(from, width, sc, scale);
  }
  sums[0] = ((partA[0] + partA[1]) + (partA[2] + partA[3])) +
            ((partA[4] + partA[5]) + (partA[6] + partA[7]));
  sums[1] = ((partB[0] + partB[1]) + (partB[2] + partB[3])) +
            ((partB[4] + partB[5]) + (partB[6] + partB[7]));
  if constexpr (kF82)
    sums[2] = ((partC[0] + partC[1]) + (partC[2] + partC[3])) +
              ((partC[4] + partC[5]) + (partC[6] + partC[7]));
}

void SumGgxSplitSumImpl(const GgxSplitSumConstants &k, bool tail, int ruleNodes,
                        const double *ruleX, const double *ruleW, const Panels &panels,
                        double sums[2]) {
  SumGgxSplitSumLoop<false>(k, tail, ruleNodes, ruleX, ruleW, panels, sums);
}

void SumGgxSplitSumF82Impl(const GgxSplitSumConstants &k, bool tail, int ruleNodes,
                           const double *ruleX, const double *ruleW, const Panels &panels,
                           double sums[3]) {
  SumGgxSplitSumLoop<true>(k, tail, ruleNodes, ruleX, ruleW, panels, sums);
}

// FirstPanel (albedo_quadrature.cpp): !(distance > 0) -> 0, then
// std::max(distance, lengthForMass).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FirstPanelLanes(D d, V distance, V lengthForMass) {
  const V positive = hn::IfThenElseZero(hn::Gt(distance, hn::Zero(d)), distance);
  return hn::IfThenElse(hn::Lt(positive, lengthForMass), lengthForMass, positive);
}

void GgxAzimuthSetupImpl(const GgxAzimuthConstants &k, size_t n, const double *sc,
                         const double *T_max, const double *slope, const double *boundNumerator,
                         int *kind, double *first, double *end, double *g2, double *lengthForMass) {
  const hn::CappedTag<double, 8> d;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  const V alpha = hn::Set(d, k.alpha), muL_o = hn::Set(d, k.muL_o), d_mu = hn::Set(d, k.d_mu);
  const V negligible = hn::Set(d, k.negligibleMass);
  const V d_muAlpha = hn::Set(d, k.d_mu * k.alpha);
  const V infinity = hn::Set(d, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; i += lanes) {
    const V vsc = hn::LoadU(d, sc + i), Tm = hn::LoadU(d, T_max + i);
    const V vslope = hn::LoadU(d, slope + i), numerator = hn::LoadU(d, boundNumerator + i);
    const auto valid = hn::Gt(Tm, zero);
    const auto bounded = hn::Lt(Tm, infinity);
    const V M = hn::Div(numerator, muL_o);
    const V tMax = hn::Div(Tm, alpha);
    const V t2 = hn::Mul(tMax, tMax);
    const V xiMax = hn::Div(t2, hn::Add(one, t2));
    const auto left = hn::And(bounded, hn::Le(hn::Mul(M, xiMax), negligible));
    const auto live = hn::AndNot(left, valid);
    const auto core = hn::Le(tMax, one);
    // The core graded toward t_max.
    const V firstCore = FirstPanelLanes(d, hn::Div(d_mu, hn::Mul(alpha, vslope)),
                                        hn::Div(negligible, hn::Mul(hn::Mul(two, tMax), M)));
    // The tail from w_min.
    const V wMin = hn::Div(alpha, Tm), share = hn::Div(negligible, M);
    const V vg2 = hn::Div(d_muAlpha, hn::Mul(hn::Mul(vslope, Tm), Tm));
    const V mass = hn::Div(share, hn::Add(wMin, hn::Sqrt(hn::Add(hn::Mul(wMin, wMin), share))));
    const auto hypotNeeded = hn::Not(hn::Lt(vg2, alpha));
    const V firstTail = FirstPanelLanes(d, vg2, mass);
    // mu_o = 0: min(alpha, d_mu alpha / (2 sc)), or alpha where d_mu = 0.
    const V toward = hn::Div(d_muAlpha, hn::Mul(two, vsc));
    const V firstAll = k.d_mu > 0.0 ? hn::IfThenElse(hn::Lt(toward, alpha), toward, alpha) : alpha;
    const V vkind = hn::IfThenElseZero(
        live,
        hn::IfThenElse(core, hn::Set(d, kAzimuthCore),
                       hn::IfThenElse(bounded,
                                      hn::IfThenElse(hypotNeeded, hn::Set(d, kAzimuthTailHypot),
                                                     hn::Set(d, kAzimuthTail)),
                                      hn::Set(d, kAzimuthTailAll))));
    hn::StoreU(hn::IfThenElse(core, firstCore, hn::IfThenElse(bounded, firstTail, firstAll)), d,
               first + i);
    hn::StoreU(hn::IfThenElse(core, tMax, wMin), d, end + i);
    hn::StoreU(vg2, d, g2 + i);
    hn::StoreU(mass, d, lengthForMass + i);
    double kinds[8];
    hn::StoreU(vkind, d, kinds);
    for (size_t j = 0; j < lanes; ++j) kind[i + j] = static_cast<int>(kinds[j]);
  }
}

void GradedCutsTowardLoImpl(size_t n, const double *lo, const double *first, double ratio,
                            int maxCuts, double *cuts, int *count) {
  const hn::CappedTag<double, 8> d;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
  const V vratio = hn::Set(d, ratio), tiny = hn::Set(d, 0x1p-60);
  for (size_t i = 0; i < n; i += lanes) {
    const V length = hn::Sub(one, hn::LoadU(d, lo + i));
    V size = hn::LoadU(d, first + i);
    // first = max(first, length 2^-60) where first > 0.
    const V least = hn::Mul(length, tiny);
    size =
        hn::IfThenElse(hn::Gt(size, zero), hn::IfThenElse(hn::Lt(size, least), least, size), size);
    auto active = hn::And(hn::Gt(size, zero), hn::Lt(size, length));
    V last = zero, before = zero, cutCount = zero;
    for (int k = 1; k < maxCuts && !hn::AllFalse(d, active); ++k) {
      const V next = hn::Add(last, size);
      active = hn::And(active, hn::Lt(next, length));
      before = hn::IfThenElse(active, last, before);
      last = hn::IfThenElse(active, next, last);
      hn::StoreU(next, d, cuts + static_cast<size_t>(k - 1) * n + i);
      cutCount = hn::Add(cutCount, hn::IfThenElseZero(active, one));
      size = hn::Mul(size, vratio);
    }
    // What is left after the last cut joins the piece before it when under
    // half that piece's length.
    const auto join = hn::And(hn::Ge(cutCount, one),
                              hn::Lt(hn::Sub(length, last), hn::Mul(half, hn::Sub(last, before))));
    cutCount = hn::Sub(cutCount, hn::IfThenElseZero(join, one));
    double counts[8];
    hn::StoreU(cutCount, d, counts);
    for (size_t j = 0; j < lanes; ++j) count[i + j] = static_cast<int>(counts[j]);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace lutbake::kernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lutbake::kernel {

HWY_EXPORT(SumGgxSplitSumImpl);
HWY_EXPORT(SumGgxSplitSumF82Impl);
HWY_EXPORT(GgxAzimuthSetupImpl);
HWY_EXPORT(GradedCutsTowardLoImpl);

void GradedCutsTowardLo(size_t n, const double *lo, const double *first, double ratio, int maxCuts,
                        double *cuts, int *count) {
  HWY_DYNAMIC_DISPATCH(GradedCutsTowardLoImpl)(n, lo, first, ratio, maxCuts, cuts, count);
}

void GgxAzimuthSetup(const GgxAzimuthConstants &constants, size_t n, const double *sc,
                     const double *T_max, const double *slope, const double *boundNumerator,
                     int *kind, double *first, double *end, double *g2, double *lengthForMass) {
  HWY_DYNAMIC_DISPATCH(GgxAzimuthSetupImpl)
  (constants, n, sc, T_max, slope, boundNumerator, kind, first, end, g2, lengthForMass);
}

void SumGgxSplitSum(const GgxSplitSumConstants &constants, bool tail, int ruleNodes,
                    const double *ruleX, const double *ruleW, const Panels &panels,
                    double sums[2]) {
  HWY_DYNAMIC_DISPATCH(SumGgxSplitSumImpl)(constants, tail, ruleNodes, ruleX, ruleW, panels, sums);
}

void SumGgxSplitSumF82(const GgxSplitSumConstants &constants, bool tail, int ruleNodes,
                       const double *ruleX, const double *ruleW, const Panels &panels,
                       double sums[3]) {
  HWY_DYNAMIC_DISPATCH(SumGgxSplitSumF82Impl)
  (constants, tail, ruleNodes, ruleX, ruleW, panels, sums);
}

}  // namespace lutbake::kernel
#endif
