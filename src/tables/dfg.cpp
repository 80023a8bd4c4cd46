// Table dfg: the split-sum terms of image-based lighting (Karis 2013). With
// Schlick's Fresnel F = F0 + (F90 - F0) (1 - v.h)^5 the specular albedo is
// F0 A + F90 B, where
//   A(mu_o, r) = integral of f (1 - (1 - v.h)^5) mu_i d omega_i,
//   B(mu_o, r) = integral of f (1 - v.h)^5 mu_i d omega_i,
// f the microfacet BRDF of table E with F = 1, so A + B = E (check asserts
// it). Axes as E's, 128 x 128 by default; channels R = A, G = B.
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"
#include "lutbake/tables/shader_dialect.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

using namespace claim_text;

// A + B = E at E's texel centres, dfg interpolated there: within what
// exact texels give, the stated bounds and float rounding.
class SumsTo final : public SetClaim {
 public:
  int Order() const override { return 0; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    const std::string &sumName = sum_;
    const CheckedTable &channels = self;

    const CheckedTable *e = set.Usable(sumName), *d = &channels;
    if (!e || !d->usable) return;
    const std::string subject = sumName + "+" + d->def->Name() + set.Suffix();
    if (!set.SameModel(*e, *d, subject, "identity")) return;
    const Table &te = e->table, &td = d->table;
    double worst = 0.0, worstExcess = -1.0, excessValue = 0, excessAllowed = 0;
    std::vector<std::pair<std::string, double>> at, atExcess;
    for (int y = 0; y < te.height(); ++y)
      for (int x = 0; x < te.width(); ++x) {
        const double mu = te.x.TexelCenter(x), r = te.y.TexelCenter(y);
        const size_t i = te.index(x, y, 0);
        const double sum = Lookup(td, mu, r, 0) + Lookup(td, mu, r, 1);
        const double dev = std::abs(sum - te.values[i]);
        // What exact texels give: the interpolation error of A + B at this point.
        const double exactDev =
            std::abs(Lookup(td, d->ref, mu, r, 0) + Lookup(td, d->ref, mu, r, 1) - e->ref[i]);
        const double allowed = exactDev + 2.0 * d->statedErrorMax + e->statedErrorMax +
                               Lookup(td, d->refError, mu, r, 0) +
                               Lookup(td, d->refError, mu, r, 1) + e->refError[i] +
                               2.0 * FloatRounding(sum) + FloatRounding(te.values[i]);
        if (dev > worst) worst = dev, at = At(te, mu, r);
        if (dev - allowed > worstExcess)
          worstExcess = dev - allowed, excessValue = dev, excessAllowed = allowed,
          atExcess = At(te, mu, r);
      }
    const std::string where =
        "at E's " + std::to_string(te.width() * te.height()) + " texel centres (dfg interpolated)";
    if (worstExcess > 0.0)
      set.Add(subject, "identity", ClaimStatus::kFail,
              "A + B - E = " + Short(excessValue) + " at " + Where(atExcess) + ", more than the " +
                  Short(excessAllowed) + " that the tables' bounds and interpolation allow (" +
                  where + ")",
              excessValue, excessAllowed, atExcess);
    else
      set.Add(subject, "identity", ClaimStatus::kPass,
              "A + B = E " + where + ": max |A + B - E| " + Short(worst) + " at " + Where(at),
              worst, 0.0, at);
  }

 private:
  std::string sum_ = "E";
};

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
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {std::make_shared<SumsTo>()};
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
