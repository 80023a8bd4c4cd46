// Comparing the quadrature with one row of an independent reference CSV
// (tests/data/*_E_AB.csv, limits.csv): E, A and B for both Smith forms.
#pragma once

#include <algorithm>
#include <cmath>

#include "lutbake/integrators/reference_integrator.h"
#include "support/csv.h"

namespace lutbake::test {

// The largest |quadrature - reference| over E, A, B (height-correlated and
// separable) at the row's (mu, alpha).
inline double WorstDifferenceFromRow(const CsvRow &row, NdfKind kind) {
  const Ndf ndf{kind, row.Number("alpha")};
  const double mu = row.Number("mu");
  const ReferenceAlbedo hc = IntegrateReferenceAlbedo(ndf, SmithForm::kCorrelated, mu);
  const ReferenceAlbedo sep = IntegrateReferenceAlbedo(ndf, SmithForm::kSeparable, mu);
  return std::max({std::abs(hc.E - row.Number("E_hc")), std::abs(hc.A - row.Number("A_hc")),
                   std::abs(hc.B - row.Number("B_hc")), std::abs(sep.E - row.Number("E_sep")),
                   std::abs(sep.A - row.Number("A_sep")), std::abs(sep.B - row.Number("B_sep"))});
}

}  // namespace lutbake::test
