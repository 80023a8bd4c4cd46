// `lutbake check DIR`: validates a baked set without trusting the baker.
//
// Every table in DIR (T.exr, T.bin, T.h, T.err.exr for T in E, Eavg, Favg,
// dfg, and the variants a bake plan names E_beckmann, Favg_dielectric, ...,
// each suffix checked as a set of its own; a plan's closed-form Favg.h is
// recognised) is read back and checked for
//   metadata   the files describe a table lutbake knows (kind, model, axes,
//              texel convention), and every format holds the same numbers;
//   finite     no NaN or Inf among values and error bounds;
//   range      E, E_avg, F_avg, A, B in [0, 1] and A + B <= 1 (float rounding allowed);
//   texels     every texel against a fresh evaluation by the quadrature
//              (independent of the sampler that baked it): within the
//              table's stated errorMax, and outside its own per-texel 99%
//              bound no more often than 1% allows (binomial, +3 sigma);
//   points     random points between the texels: the bilinear lookup an
//              engine would do against the quadrature at that point (the
//              real error a shader sees, interpolation included);
//   identity   A + B = E at E's texel centres (dfg interpolated);
//   average    E_avg = 2 integral E mu dmu from E's rows;
//   monotonic  what holds for the exact integrals: E_avg non-increasing in
//              r; Schlick F_avg increasing in F0; dielectric F_avg
//              increasing in eta >= 1;
//   closed form  Schlick F_avg = 20/21 F0 + 1/21;
//   furnace    with the Kulla-Conty lobe f_ms = (1 - E(mu_o)) (1 - E(mu_i)) /
//              (pi (1 - E_avg)) built from the baked E and E_avg through
//              bilinear lookups, E(mu) + integral f_ms cos = 1 on a fine
//              (mu, r) grid: the deviation, its maximum and where.
// Each comparison allows the table's own error bounds, the reference's
// error and float32 rounding, and for identity, average and furnace also
// the part that exact values at the same texels would show (interpolation
// and the texel-centre rule), computed from the reference: a check fails
// only when the files disagree with the truth by more than they claim.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/bake.h"

namespace lutbake {

struct CheckOptions {
  int randomPoints = 256;            // per table, for the points check
  uint64_t seed = 0;                 // of the random points
  int furnaceGrid = 257;             // furnace points per axis, both ends included
  double referenceTolerance = 1e-8;  // of the quadrature (its bound: 2x this + 1e-10)
  ProgressFn progress;               // fraction of the reference evaluations done
};

enum class CheckStatus { kPass, kFail, kSkipped };

struct CheckResult {
  std::string subject;  // "E", "Eavg", "Favg", "dfg", or "E+dfg", "E+Eavg", "DIR"
  std::string check;    // "metadata", "finite", "range", "texels", ...
  CheckStatus status = CheckStatus::kPass;
  std::string detail;    // one or two sentences: what was compared, the worst value, where
  double worst = 0.0;    // the headline number (a deviation), 0 if none
  double allowed = 0.0;  // what was allowed at the worst point, 0 if not applicable
  std::vector<std::pair<std::string, double>> at;  // coordinates of the worst point
};

struct CheckReport {
  std::string dir;
  std::vector<std::string> files;  // the files read
  std::vector<CheckResult> results;
  uint64_t referenceEvaluations = 0;  // points integrated by the quadrature
  double seconds = 0.0;
  bool passed() const;
};

// Throws IoError when `dir` is not a readable directory; everything found
// wrong inside it is a failed CheckResult instead.
CheckReport CheckBakedSet(const std::string &dir, const CheckOptions &options = {});

}  // namespace lutbake
