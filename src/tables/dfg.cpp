// Table dfg: the split-sum terms of image-based lighting (Karis 2013). With
// Schlick's Fresnel F = F0 + (F90 - F0) (1 - v.h)^5 the specular albedo is
// F0 A + F90 B, where
//   A(mu_o, r) = integral of f (1 - (1 - v.h)^5) mu_i d omega_i,
//   B(mu_o, r) = integral of f (1 - v.h)^5 mu_i d omega_i,
// f the microfacet BRDF of table E with F = 1, so A + B = E (check asserts
// it). Axes as E's, 128 x 128 by default; channels R = A, G = B.
#include "lutbake/tables/bake.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

class SplitSum final : public MuRoughnessTable {
 public:
  const char *Name() const override { return "dfg"; }
  uint64_t SeedId() const override { return 3; }
  std::string Summary() const override {
    return "split-sum terms A, B (specular albedo F0 A + F90 B) for image-based lighting";
  }
  std::vector<std::string> ChannelNames() const override { return {"R", "G"}; }
  std::vector<std::string> ChannelMeanings() const override { return {"A", "B"}; }
  std::string ChannelLayout() const override { return "R = A (scale), G = B (bias)"; }
  int DefaultSize() const override { return 128; }
  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    const double alpha = r * r;
    return EvaluateAlbedo(*this, s, mu, alpha, PointSeed(SeedId(), mu, alpha, s.seed));
  }
  ValueClaim Range(const BakeSettings &) const override {
    return {0.0, 1.0, true, "A, B >= 0 and A + B <= 1"};
  }
  TableRelations Relations() const override {
    TableRelations r;
    r.channelsSumTo = "E";
    return r;
  }
  PlanRole Role() const override { return PlanRole::kImageBasedLighting; }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.layout =
        "; channel 0 = A (scale), 1 = B (bias):\n"
        "// specular albedo = F0 A + F90 B.\n";
    text.lookupComment = "Split-sum terms {A, B} at view cosine mu and perceptual roughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &SplitSumTable() {
  static const SplitSum table;
  return table;
}

}  // namespace lutbake
