// The visible-normal estimator of GGX (albedo_estimator.h) on a batch of
// samples, vectorised with Highway and dispatched at run time like the
// quadrature's kernel (albedo_kernel.h). Each lane performs exactly the
// operations of AlbedoEstimator::Sample, in the same order: the weights are
// bit-identical to the scalar estimator's on every instruction set.
#pragma once

#include <cstddef>

#include "lutbake/models/smith.h"

namespace lutbake::kernel {

// Sample k: the visible normal from the spherical cap (ggx.h) at azimuth
// phi (cosPhi[k], sinPhi[k] = cos, sin of 2 pi u1) and height variable
// u2[k]; the light is its mirror direction. The view is fixed (u0 ==
// nullptr: viewMu, viewL = mu Lambda(mu)) or per sample, mu_o = sqrt(u0[k])
// (E_avg's estimator: mu_o with density 2 mu_o).
// Writes the weight G2 / G1(o) (0 below the horizon) times 1 - (1 - o.h)^5
// into a[k] and times (1 - o.h)^5 into b[k]; with b == nullptr, the weight
// itself into a[k].
void GgxVisibleNormalWeights(double alpha, SmithForm smith, double viewMu, double viewL, size_t n,
                             const double *cosPhi, const double *sinPhi, const double *u2,
                             const double *u0, double *a, double *b);

}  // namespace lutbake::kernel
