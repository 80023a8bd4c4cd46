// What the Oren-Nayar tables (oren_nayar_E, oren_nayar_full_E,
// ltc_oren_nayar) share: the model (models/oren_nayar.h, reflectance 1) of a
// variant, its metadata and reading it back, and the axes x = mu in [0, 1],
// y = sigma in [0, pi/2] (the facet slope angle's standard deviation,
// radians). Private to the tables layer.
#pragma once

#include <string>
#include <vector>

#include "diffuse_model_part.h"
#include "lutbake/models/oren_nayar.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

class OrenNayarModelTable : public TableDefinition {
 public:
  static constexpr double kMaxSigma = 0.5 * kPi;

  explicit OrenNayarModelTable(OrenNayarVariant variant) : variant_(variant) {}
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override {
    *x = MuAxis(size);
    *y = LinearAxis("sigma", 0.0, kMaxSigma, size);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    PointCoordinate mu;
    mu.option = "mu";
    mu.accepted = "comma-separated numbers in [0, 1]";
    PointCoordinate sigma;
    sigma.option = "sigma";
    sigma.max = kMaxSigma;
    sigma.accepted = "comma-separated numbers in [0, pi/2] (radians)";
    sigma.meaning = "the facet slope angle's standard deviation, radians";
    return {mu, sigma};
  }
  const TableModel &ModelPart() const override {
    static const char *kSigma = "sigma = the standard deviation of the facet slope angle, radians";
    static const DiffuseModel qualitative("oren-nayar qualitative (A + B)", kSigma),
        full("oren-nayar full (C1, C2, C3, L2)", kSigma);
    return variant_ == OrenNayarVariant::kQualitative ? qualitative : full;
  }
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override {
    ModelPart().Read(table, s, problems);
    return problems->empty();
  }

 protected:
  std::string ModelName() const { return ModelPart().Describe(BakeSettings{}); }
  OrenNayarVariant variant_;
};

}  // namespace lutbake
