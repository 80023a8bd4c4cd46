// Table Eavg: the cosine-weighted average of table E over the view cosine,
//   E_avg(r) = 2 integral_0^1 E(mu, r) mu dmu,
// the normalisation of Kulla and Conty's multiple-scattering lobe
//   f_ms = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)).
// Axis: x = perceptual roughness r in [0, 1], 32 texels by default (1D).
// The sampled estimators integrate the 3D integral at once (mu = sqrt(u)
// has density 2 mu); the quadrature integrates mu on panels graded toward
// 0. check asserts E_avg in [0, 1], non-increasing in r, the average of E's
// rows, and the Kulla-Conty furnace; a header bake of E and Eavg adds
// kulla_conty.h.
#include "lutbake/tables/bake.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

class AverageAlbedo final : public MicrofacetTable {
 public:
  const char *Name() const override { return "Eavg"; }
  uint64_t SeedId() const override { return 1; }
  std::string Summary() const override {
    return "average albedo E_avg(r) = 2 integral E(mu, r) mu dmu (Kulla-Conty)";
  }
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override {
    *x = RoughnessAxis(size);
    *y = LinearAxis("", 0.0, 1.0, 1);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    return {RoughnessCoordinate()};
  }
  int PlannedRoughnessAxis() const override { return 0; }
  PointValue Evaluate(const BakeSettings &s, double r, double) const override {
    const double alpha = r * r;
    return EvaluateAlbedoAverage(s, alpha, PointSeed(SeedId(), alpha, 0.0, s.seed));
  }
  // As many samples per texel as a whole 32-texel row of E.
  uint64_t SamplesPerTexel(const BakeSettings &s) const override {
    return IsQuadrature(s.estimator) ? 0 : s.samples * kAverageSampleFactor;
  }
  double ReferenceCost() const override { return 32.0; }
  std::optional<MonotonicClaim> Monotonic(const BakeSettings &) const override {
    MonotonicClaim claim;
    claim.direction = -1;
    claim.claim = "E_avg non-increasing in roughness";
    return claim;
  }
  TableRelations Relations() const override {
    TableRelations r;
    r.averageOf = "E";
    r.kullaConty = true;
    return r;
  }
  PlanRole Role() const override { return PlanRole::kEnergyCompensation; }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.lookupComment = "Average albedo E_avg at perceptual roughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &AverageAlbedoTable() {
  static const AverageAlbedo table;
  return table;
}

}  // namespace lutbake
