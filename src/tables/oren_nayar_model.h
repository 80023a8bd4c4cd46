// What the Oren-Nayar tables (oren_nayar_E, oren_nayar_full_E,
// ltc_oren_nayar) share: the model (models/oren_nayar.h, reflectance 1) of a
// variant, its metadata and reading it back, and the axes x = mu in [0, 1],
// y = sigma in [0, pi/2] (the facet slope angle's standard deviation,
// radians). Private to the tables layer.
#pragma once

#include <string>
#include <vector>

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
  std::vector<std::string> ModelOptions() const override { return {}; }
  Metadata ModelMetadata(const BakeSettings &) const override {
    return {{"model", Model()}, {"reflectance", "1"}};
  }
  std::string AlphaMetadata(const BakeSettings &) const override {
    return "sigma = the standard deviation of the facet slope angle, radians";
  }
  std::string DescribeModel(const BakeSettings &) const override { return Model(); }
  bool ReadModel(const Table &table, BakeSettings *,
                 std::vector<std::string> *problems) const override {
    const std::string model = RequiredMetadata(table, "model", problems);
    if (!model.empty() && model != Model())
      problems->push_back("model '" + model + "', expected '" + Model() + "'");
    return problems->empty();
  }
  bool SameModel(const BakeSettings &, const BakeSettings &) const override { return true; }

 protected:
  std::string Model() const {
    return variant_ == OrenNayarVariant::kQualitative ? "oren-nayar qualitative (A + B)"
                                                      : "oren-nayar full (C1, C2, C3, L2)";
  }
  OrenNayarVariant variant_;
};

}  // namespace lutbake
