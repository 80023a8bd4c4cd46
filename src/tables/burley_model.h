// What the Burley diffuse tables (burley_E, ltc_burley) share: the model
// (Burley's diffuse, Disney 2012, base colour 1; models/burley.h), its
// metadata and reading it back, and the axes x = mu, y = perceptual
// roughness r in [0, 1] (r enters F_D90 alone). Private to the tables layer.
#pragma once

#include <string>
#include <vector>

#include "diffuse_model_part.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

class BurleyModelTable : public TableDefinition {
 public:
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override {
    *x = MuAxis(size);
    *y = RoughnessAxis(size);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    PointCoordinate mu;
    mu.option = "mu";
    mu.accepted = "comma-separated numbers in [0, 1]";
    PointCoordinate r;
    r.option = "roughness";
    r.accepted = "comma-separated numbers in [0, 1] (perceptual roughness)";
    return {mu, r};
  }
  const TableModel &ModelPart() const override {
    static const DiffuseModel model(
        kModel, "n/a: perceptualRoughness r enters F_D90 = 0.5 + 2 r cos^2(theta_d) alone");
    return model;
  }
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override {
    const size_t before = problems->size();
    ModelPart().Read(table, s, problems);
    if (table.x.name != "mu" || table.x.min < 0.0 || table.x.max > 1.0)
      problems->push_back("the x axis is not mu within [0, 1]");
    if (!table.is2D() || table.y.name != "perceptualRoughness" || table.y.min < 0.0 ||
        table.y.max > 1.0)
      problems->push_back("the y axis is not perceptualRoughness within [0, 1]");
    return problems->size() == before;
  }

 protected:
  static constexpr const char *kModel = "burley diffuse (disney 2012)";
};

}  // namespace lutbake
