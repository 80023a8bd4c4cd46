// Highway compiles this file once per instruction set (foreach_target.h
// includes it again for each); HWY_DYNAMIC_DISPATCH picks one at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "integrators/sheen_kernel.cpp"
#include "integrators/sheen_kernel.h"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

// Exp and Log1p; must come after highway.h.
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace lutbake::kernel {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

double SumCharlieAzimuthImpl(const CharlieAzimuth &k, const double *c2, const double *w, size_t n) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  using V = hn::Vec<decltype(d)>;
  const V one = hn::Set(d, 1.0), zero = hn::Zero(d);
  const V m2 = hn::Set(d, k.m2), ds2 = hn::Set(d, k.ds2), B4 = hn::Set(d, k.B4);
  const V minusP = hn::Set(d, -k.p), floor = hn::Set(d, -700.0);
  const int power = k.p == 0.5 ? 1 : k.p == 1.0 ? 2 : k.p == 2.0 ? 3 : 0;
  V sum = zero;
  for (size_t j = 0; j < n; j += lanes) {
    const V T = hn::Add(ds2, hn::Mul(B4, hn::LoadU(d, c2 + j)));
    const auto positive = hn::Gt(T, zero);
    const V safeT = hn::IfThenElse(positive, T, one);
    V f;
    if (power == 1) {
      f = hn::Sqrt(hn::Div(safeT, hn::Add(safeT, m2)));
    } else if (power == 2) {
      f = hn::Div(safeT, hn::Add(safeT, m2));
    } else if (power == 3) {
      const V r = hn::Div(safeT, hn::Add(safeT, m2));
      f = hn::Mul(r, r);
    } else {
      const V e = hn::Mul(minusP, hn::Log1p(d, hn::Div(m2, safeT)));
      const auto kept = hn::Gt(e, floor);
      f = hn::IfThenElseZero(kept, hn::Exp(d, hn::IfThenElse(kept, e, zero)));
    }
    sum = hn::Add(sum, hn::Mul(hn::LoadU(d, w + j), hn::IfThenElseZero(positive, f)));
  }
  return hn::GetLane(hn::SumOfLanes(d, sum));
}

}  // namespace HWY_NAMESPACE
}  // namespace lutbake::kernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lutbake::kernel {

HWY_EXPORT(SumCharlieAzimuthImpl);

double SumCharlieAzimuth(const CharlieAzimuth &constants, const double *c2, const double *w,
                         size_t n) {
  return HWY_DYNAMIC_DISPATCH(SumCharlieAzimuthImpl)(constants, c2, w, n);
}

}  // namespace lutbake::kernel
#endif  // HWY_ONCE
