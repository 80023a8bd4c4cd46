// Table E: the directional albedo of the single-scattering microfacet BRDF
// with F = 1,
//   E(mu_o, r) = integral over the hemisphere of D(h) G2(o, i) / (4 mu_o mu_i) mu_i d omega_i,
// D the NDF (GGX or Beckmann) of width alpha = r^2, G2 the Smith term
// (height-correlated or separable). Axes: x = mu_o in [0, 1], y = perceptual
// roughness r in [0, 1], 32 x 32 by default. The integrators are in
// integrators/albedo_quadrature.h (default), reference_integrator.h
// (adaptive) and albedo_estimator.h (sampled); microfacet_table.cpp drives
// them. Limits: E = 1 at r = 0 (the mirror, exact), E -> 1 as mu_o -> 1 and
// r -> 0; check asserts E in [0, 1].
#include "lutbake/tables/bake.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

class DirectionalAlbedo final : public MuRoughnessTable {
 public:
  const char *Name() const override { return "E"; }
  uint64_t SeedId() const override { return 0; }
  std::string Summary() const override {
    return "directional albedo E(mu, r) of the single-scattering microfacet BRDF, F = 1";
  }
  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    const double alpha = r * r;
    return EvaluateAlbedo(*this, s, mu, alpha, PointSeed(SeedId(), mu, alpha, s.seed));
  }
  PlanRole Role() const override { return PlanRole::kEnergyCompensation; }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.lookupComment = "Directional albedo E at view cosine mu and perceptual roughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &DirectionalAlbedoTable() {
  static const DirectionalAlbedo table;
  return table;
}

}  // namespace lutbake
