// The LTC part of `lutbake report --tables ltc_ggx`: the lobe error of the
// baked table over a grid of (mu, r), each point looked up as a renderer
// samples the table (bilinear at texel centres), beside ltc_code's published
// 64^2 table (three.js's RectAreaLightTexturesLib.js, which the user points
// to; nothing of it is bundled) measured the same way: sampled as three.js
// samples it, at uv = (r, sqrt(1 - mu)) * 63/64 + 0.5/64, and the same
// lobe error (integrators/ltc_fit.h, LtcLobeError at level 1):
//   int_{l.z > 0} |f (n.l) - m_table D(l)| dl / E,
// with m_table the table's own magnitude channel.
#pragma once

#include <string>
#include <vector>

#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"
#include "lutbake/tables/table.h"

namespace lutbake {

struct LtcErrorMap {
  int grid = 0;  // points per axis: mu_i = (i + 0.5) / grid, r_j = (j + 0.5) / grid
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  std::string reference;             // the reference file, or empty
  std::vector<double> ours, theirs;  // grid x grid, mu fastest; theirs empty without one
  double meanOurs = 0, maxOurs = 0, meanTheirs = 0, maxTheirs = 0;
};

// ltc_code's table as three.js samples it, for Lookup (tables/lookup.h):
// 64 x 64 texels, x = r and y = sqrt(1 - mu), texel i at i / 63 (each axis
// the linear one over [-0.5/63, 1 + 0.5/63], whose texel centres those
// are), so that Lookup(table, r, sqrt(1 - mu), c) is three.js's bilinear,
// edge-clamped fetch at uv = (r, sqrt(1 - mu)) * 63/64 + 0.5/64. Channels
// m00, m20, m02, m22 from LTC_MAT_1's four, magnitude from LTC_MAT_2's
// first; texel (i, j) of each array at (j * 64 + i) * 4. Throws
// std::invalid_argument unless both hold 64 x 64 x 4 numbers.
Table ThreejsLtcTexture(const std::vector<float> &mat1, const std::vector<float> &mat2);

// `ltc`: a baked ltc_ggx table of the model (ndf, smith). referencePath:
// three.js's module with ltc_code's LTC_MAT_1 / LTC_MAT_2 (64 x 64 x 4
// numbers each), or empty. Throws IoError when the reference cannot be read.
LtcErrorMap MeasureLtcErrorMap(const Table &ltc, NdfKind ndf, SmithForm smith,
                               const std::string &referencePath, int grid = 32);

// ltc_error.csv: mu, r, ours, theirs (empty without a reference).
std::string LtcErrorCsv(const LtcErrorMap &map);
// ltc_error.svg: the two maps side by side, log10 of the error in colour.
std::string LtcErrorSvg(const LtcErrorMap &map);
// A paragraph for report.md: the means and maxima and their ratio.
std::string LtcErrorMarkdown(const LtcErrorMap &map);

}  // namespace lutbake
