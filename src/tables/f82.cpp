// Table f82: the term that the F82-tint Fresnel of metals (Kutz et al. 2021,
// "Novel aspects of the Adobe Standard Material"; OpenPBR's metal) adds to
// the split sum. That Fresnel is Schlick's minus a bump at o.h = 1/7:
//   F(c) = F0 + (F90 - F0) (1 - c)^5 - a c (1 - c)^6,   c = o.h,
// so with A and B of table dfg the specular albedo is
//   integral of f F mu_i d omega_i = F0 A + F90 B - a C,
//   C(mu_o, r) = integral of f (o.h) (1 - o.h)^6 mu_i d omega_i,
// f = D G2 / (4 mu_o mu_i) the microfacet BRDF of table E with F = 1 (GGX or
// Beckmann, correlated or separable Smith, alpha = r^2). The F82 model fixes
// F90 = 1 and
//   a = Schlick(F0, mu_bar) (1 - tint) / (mu_bar (1 - mu_bar)^6),  mu_bar = 1/7,
// per colour channel, tint = the F82 tint (OpenPBR specular_color), so that
// F(mu_bar) = tint Schlick(F0, mu_bar).
//
// Limits and bounds. At r = 0 (the mirror: o.h = mu_o, G2 = 1) C = mu_o
// (1 - mu_o)^6, exact. Pointwise (o.h) (1 - o.h) <= 1/4 and (o.h)
// (1 - o.h)^6 <= 6^6 / 7^7 (its maximum, at o.h = 1/7), so
//   0 <= C <= B / 4   and   C <= (6^6 / 7^7) E < 0.0567,
// which check asserts (the range, and C <= B / 4 at every texel where dfg
// of the same size and model is in the set). Axes as dfg's, 128 x 128 by default: C sits at the
// same texels as A and B, so an engine can keep it as dfg's third channel
// (as EEVEE does); at r = 0 it varies in mu like B ((1 - mu)^6 against
// (1 - mu)^5), which is what set dfg's resolution.
//
// Integrated as E and dfg are: the panel quadrature (the same panels and
// levels, the weight (o.h) (1 - o.h)^6 added to its kernel), the adaptive
// reference, or E's sampled estimators (microfacet_table.cpp).
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "lutbake/tables/shader_dialect.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

using namespace claim_text;

// C <= B / 4 (dfg's channel 1) at every shared texel, within the two stated
// bounds and float rounding (no interpolation: the tables must share their
// axes, else the claim is skipped).
class AtMost final : public SetClaim {
 public:
  int Order() const override { return 4; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    const CheckedTable &small = self;

    const CheckedTable *big = set.Usable(table_);
    if (!big || !small.usable) return;
    const std::string subject = std::string(small.def->Name()) + "+" + table_ + set.Suffix();
    if (!set.SameModel(small, *big, subject, "at most")) return;
    const Table &ts = small.table, &tb = big->table;
    const auto same = [](const Axis &a, const Axis &b) {
      return a.name == b.name && a.min == b.min && a.max == b.max && a.count == b.count &&
             a.nodes == b.nodes;
    };
    const std::string claim = std::string(small.def->ChannelMeanings()[0]) +
                              " <= " + Short(factor_) + " " +
                              big->def->ChannelMeanings()[static_cast<size_t>(channel_)];
    if (!same(ts.x, tb.x) || !same(ts.y, tb.y) || channel_ >= tb.channels) {
      set.Add(subject, "at most", ClaimStatus::kSkipped,
              claim + ": the tables do not share their texels (bake them at the same size)");
      return;
    }
    double worstExcess = -1e300, worstValue = 0, worstAllowed = 0;
    std::vector<std::pair<std::string, double>> at;
    for (int y = 0; y < ts.height(); ++y)
      for (int x = 0; x < ts.width(); ++x) {
        const size_t i = ts.index(x, y, 0), j = tb.index(x, y, channel_);
        const double excess = ts.values[i] - factor_ * tb.values[j];
        const double allowed = small.Bound(i) + factor_ * big->Bound(j) +
                               FloatRounding(ts.values[i]) + FloatRounding(tb.values[j]);
        if (excess - allowed > worstExcess)
          worstExcess = excess - allowed, worstValue = excess, worstAllowed = allowed,
          at = At(ts, ts.x.TexelCenter(x), ts.y.TexelCenter(y));
      }
    const std::string where = "at " + std::to_string(ts.width() * ts.height()) + " shared texels";
    if (worstExcess > 0.0)
      set.Add(subject, "at most", ClaimStatus::kFail,
              claim + " fails " + where + ": exceeded by " + Short(worstValue) + " at " +
                  Where(at) + ", more than the " + Short(worstAllowed) + " the bounds allow",
              worstValue, worstAllowed, at);
    else
      set.Add(subject, "at most", ClaimStatus::kPass,
              claim + " " + where + " (closest at " + Where(at) + ")", worstValue, worstAllowed,
              at);
  }

 private:
  std::string table_ = "dfg";
  int channel_ = 1;
  double factor_ = 0.25;
};

class F82Term final : public MuRoughnessTable {
 public:
  const char *Name() const override { return "f82"; }
  // 6 to 9 are left to the dielectric tables of issue 15.
  uint64_t SeedId() const override { return 82; }
  std::string Summary() const override {
    return "F82-tint term C(mu, r) (specular albedo F0 A + F90 B - a C, with dfg's A, B)";
  }
  std::vector<std::string> ChannelMeanings() const override { return {"C"}; }
  std::string ChannelLayout() const override { return "Y = C"; }
  int DefaultSize() const override { return 128; }
  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    const double alpha = r * r;
    return EvaluateF82(*this, s, mu, alpha, PointSeed(SeedId(), mu, alpha, s.seed));
  }
  std::string UnseenEventTerm() const override {
    return "6^6/7^7 x 4.6 / N (visible normals; 4.6 / N for the other estimators)";
  }
  ValueClaim Range(const BakeSettings &) const override {
    // 6^6 / 7^7 = 0.056652...: the maximum of (o.h) (1 - o.h)^6, times E <= 1.
    return {0.0, 46656.0 / 823543.0, false, "in [0, 6^6/7^7] (C <= 6^6/7^7 E)"};
  }
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {std::make_shared<AtMost>()};  // C <= B / 4
  }
  PlanRole Role() const override { return PlanRole::kF82ImageBasedLighting; }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.notes.push_back(
        "With the F82-tint Fresnel F = F0 + (F90 - F0) (1 - c)^5 - a c (1 - c)^6 (c = v.h),");
    text.notes.push_back("specular albedo = F0 A + F90 B - a C (A, B: table dfg).");
    text.lookupComment = "F82 term C at view cosine mu and perceptual roughness r.";
    text.helpers = [](const std::string &) {
      return "// The F82-tint coefficient a of one colour channel (Kutz et al. 2021, OpenPBR):\n"
             "//   a = Schlick(F0, 1/7) (1 - tint) / ((1/7) (1 - 1/7)^6),\n"
             "//   Schlick(F0, c) = F0 + (1 - F0) (1 - c)^5  (F90 = 1),\n"
             "// so that F(1/7) = tint Schlick(F0, 1/7). tint is the F82 tint in [0, 1].\n"
             "inline float f82_tint_a(float F0, float tint) {\n"
             "  const double y = 6.0 / 7.0;  // 1 - mu_bar\n"
             "  const double y2 = y * y, y5 = y2 * y2 * y, y6 = y5 * y;\n"
             "  const double schlick = F0 + (1.0 - F0) * y5;\n"
             "  return static_cast<float>(schlick * (1.0 - tint) / (y6 / 7.0));\n"
             "}\n\n"
             "// Specular albedo of one colour channel: F0 A + F90 B - a C, with A, B from\n"
             "// the dfg table and C from this one at the same (NdotV, r).\n"
             "inline float specular_albedo_f82(float A, float B, float C, float F0, float F90,\n"
             "                                 float a) {\n"
             "  return F0 * A + F90 * B - a * C;\n"
             "}\n\n";
    };
    return text;
  }
  // The same two functions in the shading languages, where the set holds
  // dfg for A and B.
  std::vector<ShaderPiece> ShaderHelpers(const source_text::Dialect &d, const Table &,
                                         const std::vector<Table> &set) const override {
    if (!FindRole(set, PlanRole::kImageBasedLighting)) return {};
    const std::string F = d.Float(), F2 = d.Float(2), F3 = d.Float(3);
    const std::string one3 = d.Vec({d.Lit(1.0), d.Lit(1.0), d.Lit(1.0)});
    const double y = 6.0 / 7.0, y5 = y * y * y * y * y, y6 = y5 * y;
    return {
        {1, "f82",
         "// The F82-tint Fresnel of metals (Kutz et al. 2021; OpenPBR's metal):\n"
         "//   F(c) = F0 + (F90 - F0) (1 - c)^5 - a c (1 - c)^6,  c = v.h,\n"
         "// per colour channel, with\n"
         "//   a = Schlick(F0, 1/7) (1 - tint) / ((1/7) (1 - 1/7)^6),\n"
         "//   Schlick(F0, c) = F0 + (1 - F0) (1 - c)^5  (F90 = 1),\n"
         "// so that F(1/7) = tint Schlick(F0, 1/7); tint is the F82 tint in [0, 1].\n" +
             d.Function(F3, "lutbake_f82_tint_a", {{F3, "F0"}, {F3, "tint"}},
                        d.Let(F3, "schlick", "F0 + (" + one3 + " - F0) * " + d.Lit(y5)) +
                            "  return schlick * (" + one3 + " - tint) * " + d.Lit(7.0 / y6) +
                            ";\n") +
             "// Its specular albedo: F0 A + F90 B - a C, with A, B from dfg and C from f82 at\n"
             "// the same (NdotV, r).\n" +
             d.Function(F3, "lutbake_specular_albedo_f82",
                        {{F2, "AB"}, {F, "C"}, {F3, "F0"}, {F3, "F90"}, {F3, "a"}},
                        "  return F0 * AB.x + F90 * AB.y - a * C;\n")}};
  }
};

}  // namespace

const TableDefinition &F82Table() {
  static const F82Term table;
  return table;
}

}  // namespace lutbake
