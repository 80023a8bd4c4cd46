// A table as a fitted closed form (--format fit): the piecewise Chebyshev
// fit of integrators/chebyshev_fit.h of a table's point evaluator (what
// `lutbake eval` computes, the panel quadrature with its bound), over the
// table's FitDomain, with its certified maximum error.
#pragma once

#include <string>

#include "lutbake/integrators/chebyshev_fit.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// The default tolerance of a fit: half a binary16 ulp at 1 (2^-11 = 4.88e-4,
// rounded down), and its coefficient budget per channel.
inline constexpr double kDefaultFitTolerance = 4.9e-4;
inline constexpr int kDefaultFitCoefficients = 256;
// The budget of a tighter tolerance (below kDefaultFitTolerance).
inline constexpr int kTightFitCoefficients = 4096;

// The exact values of the table at (x, y): Evaluate with the model of
// `settings` and the deterministic panel quadrature (its default
// tolerance), channel values and their bounds.
FitExact ExactValuesOf(const TableDefinition &table, const BakeSettings &settings);

// The budget of coefficients per channel for a tolerance.
int FitCoefficientBudget(double tolerance);

// Fits the 1D or 2D table (throws std::invalid_argument for a 3D one or
// one with fitted channels, ltc_ggx). The same request gives the same fit
// (cached for the process: a bake's C++ and shader files share one fit).
FitResult FitTable(const TableDefinition &table, const BakeSettings &settings, double tolerance);

}  // namespace lutbake
