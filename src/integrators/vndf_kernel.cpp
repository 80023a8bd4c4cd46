// Highway compiles this file once per instruction set (foreach_target.h
// includes it again for each); HWY_DYNAMIC_DISPATCH picks one at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "integrators/vndf_kernel.cpp"
#include "integrators/vndf_kernel.h"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace lutbake::kernel {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// Max(x, 0) is std::max(0.0, x) on x86 (maxpd returns its second operand
// for -0 and NaN), so that even the zeros match the scalar code.

// mu Lambda(mu) of GGX as ggx::MuLambda computes it.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V MuLambdaLanes(D d, V alpha2, V mu) {
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), zero = hn::Zero(d);
  const V sin2 = hn::Max(hn::Mul(hn::Sub(one, mu), hn::Add(one, mu)), zero);
  const V a2s2 = hn::Mul(alpha2, sin2);
  const V root = hn::Sqrt(hn::Add(hn::Mul(mu, mu), a2s2));
  const V sum = hn::Add(root, mu);
  return hn::IfThenElseZero(hn::Gt(sum, zero), hn::Div(a2s2, hn::Mul(two, sum)));
}

// One vector of samples; the view o = (o_x, 0, o_z) with L_o, and its
// stretched, normalised os = (os_x, 0, os_z).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void SampleLanes(D d, double alpha, SmithForm smith, V o_x, V o_z, V L_o, V os_x, V os_z,
                            V cosPhi, V sinPhi, V u2, V *weight, V *complement, V *fc) {
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), zero = hn::Zero(d);
  const V va = hn::Set(d, alpha), alpha2 = hn::Set(d, alpha * alpha);
  // SampleVisibleNormal (ggx.cpp), os.y = 0.
  const V z = hn::Sub(hn::Mul(hn::Sub(one, u2), hn::Add(one, os_z)), os_z);
  const V sinTheta = hn::Sqrt(hn::Max(hn::Mul(hn::Sub(one, z), hn::Add(one, z)), zero));
  const V hs_x = hn::Add(hn::Mul(sinTheta, cosPhi), os_x);
  const V hs_y = hn::Add(hn::Mul(sinTheta, sinPhi), zero);
  const V hs_z = hn::Add(z, os_z);
  V h_x = hn::Mul(va, hs_x), h_y = hn::Mul(va, hs_y), h_z = hn::Max(hs_z, zero);
  const V len2 = hn::Add(hn::Add(hn::Mul(h_x, h_x), hn::Mul(h_y, h_y)), hn::Mul(h_z, h_z));
  const auto degenerate = hn::Not(hn::Gt(len2, zero));
  const V inv = hn::Div(one, hn::Sqrt(len2));
  h_x = hn::IfThenZeroElse(degenerate, hn::Mul(h_x, inv));
  h_y = hn::IfThenZeroElse(degenerate, hn::Mul(h_y, inv));
  h_z = hn::IfThenElse(degenerate, one, hn::Mul(h_z, inv));
  // AlbedoEstimator::Sample: o.h, the mirror direction, the weight G2 / G1(o).
  const V oh = hn::Add(hn::Add(hn::Mul(o_x, h_x), hn::Mul(zero, h_y)), hn::Mul(o_z, h_z));
  const V mu_i = hn::Sub(hn::Mul(hn::Mul(two, oh), h_z), o_z);
  const V L_i = MuLambdaLanes(d, alpha2, mu_i);
  V w;
  if (smith == SmithForm::kCorrelated) {
    const V denom = hn::Add(hn::Add(hn::Mul(o_z, mu_i), hn::Mul(mu_i, L_o)), hn::Mul(o_z, L_i));
    w = hn::IfThenElseZero(hn::Gt(denom, zero), hn::Div(hn::Mul(mu_i, hn::Add(o_z, L_o)), denom));
  } else {
    const V denom = hn::Add(mu_i, L_i);
    w = hn::IfThenElseZero(hn::Gt(denom, zero), hn::Div(mu_i, denom));
  }
  const auto above = hn::And(hn::Gt(mu_i, zero), hn::Gt(oh, zero));
  *weight = hn::IfThenElseZero(above, w);
  // Schlick (math.h).
  const V y = hn::Sub(one, oh), y2 = hn::Mul(y, y);
  *fc = hn::IfThenElseZero(above, hn::Mul(hn::Mul(y2, y2), y));
  *complement = hn::IfThenElseZero(
      above,
      hn::Mul(oh, hn::Add(hn::Add(hn::Add(hn::Add(one, y), y2), hn::Mul(y2, y)), hn::Mul(y2, y2))));
}

// The view for a vector of mu_o: o = (SafeSqrt(1 - mu^2), 0, mu) (math.h),
// os = Normalize(alpha o_x, 0, o_z).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void ViewLanes(D d, double alpha, V mu, V *o_x, V *os_x, V *os_z) {
  const V one = hn::Set(d, 1.0), zero = hn::Zero(d), va = hn::Set(d, alpha);
  *o_x = hn::Sqrt(hn::Max(hn::Sub(one, hn::Mul(mu, mu)), zero));
  const V sx = hn::Mul(va, *o_x), sy = hn::Mul(va, zero);
  const V inv =
      hn::Div(one, hn::Sqrt(hn::Add(hn::Add(hn::Mul(sx, sx), hn::Mul(sy, sy)), hn::Mul(mu, mu))));
  *os_x = hn::Mul(sx, inv);
  *os_z = hn::Mul(mu, inv);
}

template <class D>
HWY_INLINE void Lanes(D d, double alpha, SmithForm smith, double viewMu, double viewL, size_t k,
                      const double *cosPhi, const double *sinPhi, const double *u2,
                      const double *u0, double *a, double *b) {
  using V = hn::Vec<D>;
  V o_x, o_z, L_o, os_x, os_z;
  if (u0) {
    o_z = hn::Sqrt(hn::LoadU(d, u0 + k));  // mu_o = sqrt(u0): density 2 mu_o
    L_o = MuLambdaLanes(d, hn::Set(d, alpha * alpha), o_z);
  } else {
    o_z = hn::Set(d, viewMu);
    L_o = hn::Set(d, viewL);
  }
  ViewLanes(d, alpha, o_z, &o_x, &os_x, &os_z);
  V weight, complement, fc;
  SampleLanes(d, alpha, smith, o_x, o_z, L_o, os_x, os_z, hn::LoadU(d, cosPhi + k),
              hn::LoadU(d, sinPhi + k), hn::LoadU(d, u2 + k), &weight, &complement, &fc);
  if (b) {
    hn::StoreU(hn::Mul(weight, complement), d, a + k);
    hn::StoreU(hn::Mul(weight, fc), d, b + k);
  } else {
    hn::StoreU(weight, d, a + k);
  }
}

void GgxVisibleNormalWeightsImpl(double alpha, SmithForm smith, double viewMu, double viewL,
                                 size_t n, const double *cosPhi, const double *sinPhi,
                                 const double *u2, const double *u0, double *a, double *b) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t k = 0;
  for (; k + lanes <= n; k += lanes)
    Lanes(d, alpha, smith, viewMu, viewL, k, cosPhi, sinPhi, u2, u0, a, b);
  const hn::CappedTag<double, 1> d1;
  for (; k < n; ++k) Lanes(d1, alpha, smith, viewMu, viewL, k, cosPhi, sinPhi, u2, u0, a, b);
}

}  // namespace HWY_NAMESPACE
}  // namespace lutbake::kernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lutbake::kernel {

HWY_EXPORT(GgxVisibleNormalWeightsImpl);

void GgxVisibleNormalWeights(double alpha, SmithForm smith, double viewMu, double viewL, size_t n,
                             const double *cosPhi, const double *sinPhi, const double *u2,
                             const double *u0, double *a, double *b) {
  HWY_DYNAMIC_DISPATCH(GgxVisibleNormalWeightsImpl)
  (alpha, smith, viewMu, viewL, n, cosPhi, sinPhi, u2, u0, a, b);
}

}  // namespace lutbake::kernel
#endif
