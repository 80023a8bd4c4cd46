// What the single-scattering microfacet tables (E, Eavg, dfg) share: the
// model (NDF and Smith form, F = 1), the roughness convention alpha =
// perceptualRoughness^2, reading both back from a file. Private to the
// tables layer.
#pragma once

#include <string>
#include <vector>

#include "lutbake/tables/table_definition.h"

namespace lutbake {

// The microfacet model part (model_part.h): the lobe's NDF and Smith form
// (options ndf, smith; F = 1) and alpha = perceptualRoughness^2, recorded
// as metadata ndf, smith, fresnel and alpha and read back from them. The
// rough-dielectric tables' part is built on it (dielectric_table.cpp).
const TableModel &MicrofacetModel();

class MicrofacetTable : public TableDefinition {
 public:
  const TableModel &ModelPart() const override { return MicrofacetModel(); }
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override;

 protected:
  // The roughness axis of a point: "roughness", perceptual roughness r in
  // {0} or [sqrt(kMinimumAlpha), 1] (alpha = r^2; 0 is the mirror, exact).
  static PointCoordinate RoughnessCoordinate();
  // The view cosine: "mu" in [0, 1] (0 is the grazing limit).
  static PointCoordinate MuCoordinate();
  // The header notes of a table over perceptual roughness.
  static void AddRoughnessNotes(HeaderText *text);
};

// The microfacet tables over (mu_o, r) (E, dfg, f82): x = the view cosine,
// y = perceptual roughness, both at texel centres of [0, 1]; eval takes
// --mu and --roughness; a plan narrows y.
class MuRoughnessTable : public MicrofacetTable {
 public:
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override;
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    return {MuCoordinate(), RoughnessCoordinate()};
  }
  int PlannedRoughnessAxis() const override { return 1; }
};

// The F82 term C(mu_o, alpha) of table f82 (f82.cpp), with the settings'
// estimator; conventions and errors as EvaluateAlbedo's (bake.h).
PointValue EvaluateF82(const TableDefinition &table, const BakeSettings &settings, double mu_o,
                       double alpha, uint64_t pointSeed);

}  // namespace lutbake
