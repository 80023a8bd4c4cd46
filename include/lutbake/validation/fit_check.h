// `lutbake check DIR` on the fitted closed forms of --format fit (T_fit.h,
// formats/fit_format.h): each file is read back from its C++ source and its
// float32 evaluation (what the file computes, PiecewiseChebyshev::
// EvaluateFloat) compared with the table's reference (the adaptive
// quadrature, independent of the panel quadrature the fit was made from) at
// points of the check's own: a 61 x 61 grid of the domain (61 points for a
// 1D table) staggered against the fit's certificate grid, and random points
// (half uniform in the coordinates, half uniform in the fit's s, which
// crowds them into the edge layers). Every point must lie within the stated
// T_max_error plus the reference's own bound. Also checked: T_coefficients
// equals what the arrays hold.
#pragma once

#include <string>
#include <vector>

#include "lutbake/validation/check.h"

namespace lutbake {

// The results ("fit" check per file, subject the file's table name).
std::vector<CheckResult> CheckFitFile(const std::string &path, const CheckOptions &options,
                                      uint64_t *referenceEvaluations);

}  // namespace lutbake
