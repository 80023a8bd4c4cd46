// Table dfg: the split-sum terms of image-based lighting (Karis 2013). With
// Schlick's Fresnel F = F0 + (F90 - F0) (1 - v.h)^5 the specular albedo is
// F0 A + F90 B, where
//   A(mu_o, r) = integral of f (1 - (1 - v.h)^5) mu_i d omega_i,
//   B(mu_o, r) = integral of f (1 - v.h)^5 mu_i d omega_i,
// f the microfacet BRDF of table E with F = 1, so A + B = E (check asserts
// it). Axes as E's, 128 x 128 by default; channels R = A, G = B.
#include "lutbake/tables/bake.h"
#include "lutbake/tables/shader_dialect.h"
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
  std::vector<ShaderPiece> ShaderHelpers(const source_text::Dialect &d, const Table &,
                                         const std::vector<Table> &) const override {
    const std::string F2 = d.Float(2), F3 = d.Float(3);
    return {
        {0, "split_sum",
         "// Split-sum specular albedo (table " + std::string(Name()) +
             ", AB = its lookup at (NdotV, r)): with Schlick's\n"
             "// Fresnel F = F0 + (F90 - F0) (1 - v.h)^5 the directional albedo is\n"
             "//   integral f F cos = F0 A + F90 B,\n"
             "// A = integral (f/F) (1 - (1 - v.h)^5) cos, B = integral (f/F) (1 - v.h)^5 cos.\n"
             "// Times the prefiltered radiance, the split-sum image-based specular.\n" +
             d.Function(F3, "lutbake_specular_albedo", {{F2, "AB"}, {F3, "F0"}, {F3, "F90"}},
                        "  return F0 * AB.x + F90 * AB.y;\n")}};
  }
};

}  // namespace

const TableDefinition &SplitSumTable() {
  static const SplitSum table;
  return table;
}

}  // namespace lutbake
