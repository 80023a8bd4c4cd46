// What the sheen tables (sheen_E, sheen_Eavg) share: the model (Charlie NDF,
// the visibility, the roughness mapping, sheen colour 1, F = 1), reading it
// back from a file, the roughness coordinate, and the estimators they take.
// Private to the tables layer.
#pragma once

#include <string>
#include <vector>

#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// The sheen's model part: the Charlie NDF with the visibility and
// roughness mapping of options sheen-visibility and sheen-alpha, sheen
// colour 1, F = 1 (metadata ndf, visibility, sheenColor, fresnel, alpha).
const TableModel &SheenModel();

class SheenTable : public TableDefinition {
 public:
  const TableModel &ModelPart() const override { return SheenModel(); }
  Metadata PointLabels(const BakeSettings &s) const override;
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override;
  std::string QuadratureDescription(const BakeSettings &s) const override;
  std::string QuadratureBound(const BakeSettings &s) const override;
  std::string EstimatorProblem(Estimator e) const override;
  std::string UnseenEventTerm() const override {
    return "4.6 W / N (W the largest weight the texel's sampler can return, proven)";
  }
  // E is not bounded by 1: the claim is E >= 0.
  ValueClaim Range(const BakeSettings &) const override {
    return {0.0, HUGE_VAL, false, ">= 0 (the true integral, not bounded by 1)"};
  }

 protected:
  // alpha from the sheen roughness r in [0, 1] (domain_error outside).
  static double AlphaOf(const BakeSettings &s, double r);
  static PointCoordinate RoughnessCoordinate();
  // A quadrature result as a point value (one channel).
  static PointValue FromIntegral(const SheenIntegral &q);
  // Header notes on the model and the roughness mapping.
  static void AddModelNotes(const Table &table, HeaderText *text);
};

}  // namespace lutbake
