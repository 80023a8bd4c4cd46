// Table glass_Eavg: the cosine-weighted average of glass_E over the view,
//   glass_Eavg(r, eta) = 2 integral_0^1 glass_E(mu, r, eta) mu dmu,
// integrated from the exact glass_E (Gauss panels in mu, graded toward 0 and,
// for eta < 1, toward the critical cosine sqrt(1 - eta^2) from both sides).
// Axes: x = perceptual roughness r (32), y = eta (dielectric_table.h), 2D.
// Between the two sides of an interface the transmitted parts obey
// reciprocity (dielectric.h):
//   glass_Eavg(eta) - spec_Eavg(eta) = eta^2 (glass_Eavg(1/eta) - spec_Eavg(1/eta)),
// which is 1 - F_avg(eta) = eta^2 (1 - F_avg(1/eta)) for a smooth interface.
// The sampled estimators draw mu_o uniformly (weight 2 mu_o w, at most 2).
#include "dielectric_table.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

class GlassAverageAlbedo final : public DielectricTable {
 public:
  const char *Name() const override { return "glass_Eavg"; }
  uint64_t SeedId() const override { return 7; }
  std::string Summary() const override {
    return "average albedo of rough glass (reflection + transmission), 2 integral glass_E mu dmu, "
           "over (r, eta)";
  }
  DielectricLobes Lobes() const override { return DielectricLobes::kReflectionAndTransmission; }
  void Axes(const BakeSettings &s, int size, Axis *x, Axis *y) const override {
    *x = RoughnessAxis(size);
    *y = EtaAxis(s.depthSize > 0 ? s.depthSize : 17);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    return {RoughnessCoordinate(), EtaCoordinate()};
  }
  PlanRole Role() const override { return PlanRole::kGlassCompensation; }
  int PlannedRoughnessAxis() const override { return 0; }
  PointValue Evaluate(const BakeSettings &s, double r, double eta) const override {
    return EvaluateAverage(s, r, eta);
  }
  // As many samples per texel as a whole 32-texel row of glass_E.
  uint64_t SamplesPerTexel(const BakeSettings &s) const override {
    return IsQuadrature(s.estimator) ? 0 : s.samples * kAverageSampleFactor;
  }
  double ReferenceCost() const override { return 32.0; }
  // No adaptive E_avg: check judges this table with the panel rule at 1/64
  // of its bound, and independently through its average of glass_E's rows,
  // whose texels it holds to the adaptive rule.
  Estimator ReferenceEstimator() const override { return Estimator::kQuadrature; }
  TableRelations Relations() const override {
    TableRelations r;
    r.averageOf = "glass_E";
    return r;
  }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddNotes(&text);
    text.lookupComment =
        "Average albedo of rough glass (reflection + transmission) at perceptual roughness r and "
        "relative IOR eta.";
    return text;
  }
};

}  // namespace

const TableDefinition &GlassAverageAlbedoTable() {
  static const GlassAverageAlbedo table;
  return table;
}

}  // namespace lutbake
