// The innermost loop of the sheen quadrature (sheen_quadrature.cpp): the
// azimuthal sum of the Charlie NDF at one light cosine,
//   sum_j w_j dhat(T_j),  dhat = (1 + m^2 / T)^(-p),  T_j = ds2 + B4 c2_j,
// vectorised with Highway and dispatched at run time to the widest
// instruction set the processor has. Lanes with T = 0 (h = n) give 0, and so
// do lanes where dhat < e^-700 (no double below it matters against the
// largest node, 1). The general power uses Highway's Exp and Log1p (within a
// few ulp); p = 1/2, 1 and 2 (alpha = 1, 1/2, 1/4) use a square root or
// divisions. The sum is the same on every call; its last bits may differ
// between instruction sets (Exp and Log1p use fused multiply-adds where the
// processor has them).
#pragma once

#include <cstddef>

namespace lutbake::kernel {

struct CharlieAzimuth {
  double p = 0.5;    // q / 2 = 1 / (2 alpha)
  double m2 = 0.0;   // (mu_o + mu_i)^2
  double ds2 = 0.0;  // (s_o - s_i)^2
  double B4 = 0.0;   // 4 s_o s_i
};

// n must be a multiple of kAzimuthPadding (pad with w = 0, c2 = 1).
inline constexpr size_t kAzimuthPadding = 8;
double SumCharlieAzimuth(const CharlieAzimuth &constants, const double *c2, const double *w,
                         size_t n);

}  // namespace lutbake::kernel
