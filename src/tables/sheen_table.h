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

class SheenTable : public TableDefinition {
 public:
  std::vector<std::string> ModelOptions() const override {
    return {"sheen-visibility", "sheen-alpha"};
  }
  Metadata ModelMetadata(const BakeSettings &s) const override;
  std::string AlphaMetadata(const BakeSettings &s) const override;
  std::string DescribeModel(const BakeSettings &s) const override;
  Metadata PointLabels(const BakeSettings &s) const override;
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override;
  bool SameModel(const BakeSettings &a, const BakeSettings &b) const override {
    return a.sheenVisibility == b.sheenVisibility && a.sheenAlpha == b.sheenAlpha;
  }
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
