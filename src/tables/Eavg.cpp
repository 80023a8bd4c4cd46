// Table Eavg: the cosine-weighted average of table E over the view cosine,
//   E_avg(r) = 2 integral_0^1 E(mu, r) mu dmu,
// the normalisation of Kulla and Conty's multiple-scattering lobe
//   f_ms = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)).
// Axis: x = perceptual roughness r in [0, 1], 32 texels by default (1D).
// The sampled estimators integrate the 3D integral at once (mu = sqrt(u)
// has density 2 mu); the quadrature integrates mu on panels graded toward
// 0. check asserts E_avg in [0, 1], non-increasing in r, the average of E's
// rows, and the Kulla-Conty furnace; a header bake of E and Eavg adds
// kulla_conty.h, and shader code of the two the same functions (below).
#include <algorithm>

#include "lutbake/core/math.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"
#include "lutbake/tables/shader_dialect.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

using source_text::Dialect;

// The Kulla-Conty functions of any E and E_avg pair, in one of the shading
// languages: the lobe, its albedo, its Fresnel colour and Schlick's F_avg.
std::string KullaContyShaderCore(const Dialect &d) {
  const std::string F = d.Float(), F3 = d.Float(3);
  const std::string one3 = d.Vec({d.Lit(1.0), d.Lit(1.0), d.Lit(1.0)});
  return "// Kulla-Conty multiple scattering (Kulla and Conty 2017), as kulla_conty.h.\n"
         "// A single-scattering microfacet BRDF reflects E(mu_o, r) of the light (F = 1)\n"
         "// and loses 1 - E to paths that bounce between microfacets; the lobe\n"
         "//   f_ms(mu_o, mu_i, r) = (1 - E(mu_o, r)) (1 - E(mu_i, r)) / (pi (1 - E_avg(r))),\n"
         "// E_avg(r) = 2 integral_0^1 E(mu, r) mu dmu, gives that energy back:\n"
         "//   integral f_ms mu_i d(omega_i) = 1 - E(mu_o),\n"
         "// so f + f_ms passes the white furnace. 0 where E_avg rounds to 1 (the mirror).\n" +
         d.Function(F, "lutbake_f_ms", {{F, "E_o"}, {F, "E_i"}, {F, "Eavg"}},
                    d.Let(F, "lost", d.Lit(1.0) + " - Eavg") +
                        d.Let(F, "lobe",
                              "max(" + d.Lit(1.0) + " - E_o, " + d.Lit(0.0) + ") * max(" +
                                  d.Lit(1.0) + " - E_i, " + d.Lit(0.0) + ") / (" +
                                  d.Lit(3.14159265358979) + " * max(lost, " + d.Lit(1e-30) + "))") +
                        "  return " + d.Select("lost > " + d.Lit(0.0), "lobe", d.Lit(0.0)) +
                        ";\n") +
         "// The albedo of the lobe, integral f_ms cos over the hemisphere = 1 - E(mu_o):\n"
         "// under a constant environment L the lobe adds L F_ms (1 - E(mu_o)).\n" +
         d.Function(F, "lutbake_ms_albedo", {{F, "E_o"}},
                    "  return max(" + d.Lit(1.0) + " - E_o, " + d.Lit(0.0) + ");\n") +
         "// The Fresnel colour of the lobe, per channel: the light that leaves after any\n"
         "// number of bounces, each reflecting F_avg and escaping with E_avg,\n"
         "//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),\n"
         "// F_avg clamped to [0, 1] (the denominator is then at least E_avg > 0).\n" +
         d.Function(F3, "lutbake_fresnel_ms", {{F3, "Favg"}, {F, "Eavg"}},
                    d.Let(F3, "f",
                          "clamp(Favg, " + d.Vec({d.Lit(0.0), d.Lit(0.0), d.Lit(0.0)}) + ", " +
                              one3 + ")") +
                        d.Let(F3, "denominator", one3 + " - f * (" + d.Lit(1.0) + " - Eavg)") +
                        "  return f * f * Eavg / max(denominator, " +
                        d.Vec({d.Lit(1e-30), d.Lit(1e-30), d.Lit(1e-30)}) + ");\n") +
         "// F_avg of Schlick's Fresnel, exactly: 2 integral_0^1 F(mu) mu dmu\n"
         "// = 20/21 F0 + 1/21 F90.\n" +
         d.Function(
             F3, "lutbake_favg_schlick", {{F3, "F0"}, {F3, "F90"}},
             "  return F0 * " + d.Lit(20.0 / 21.0) + " + F90 * " + d.Lit(1.0 / 21.0) + ";\n");
}

// The white furnace of the Kulla-Conty lobe built from the baked E and
// E_avg through bilinear lookups, on a fine (mu, r) grid:
//   E(mu) + integral f_ms cos = E_o + (1 - E_o) (1 - E~) / (1 - E_avg),
//   E~ = 2 integral_0^1 E_lookup(mu_i) mu_i dmu_i (exact for a piecewise-linear lookup),
// so the deviation from 1 is d = (1 - E_o) (E_avg - E~) / (1 - E_avg).
class KullaContyFurnace final : public SetClaim {
 public:
  int Order() const override { return 2; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    using namespace claim_text;
    const std::string &ofName = averaged_;
    const CheckedTable &average = self;

    const CheckedTable *e = set.Usable(ofName), *a = &average;
    if (!e || !a->usable) return;
    const std::string subject = ofName + "+" + a->def->Name() + set.Suffix();
    if (!set.SameModel(*e, *a, subject, "furnace")) return;
    const Table &te = e->table, &ta = a->table;
    if (te.x.min != 0.0 || te.x.max != 1.0) {
      set.Add(subject, "furnace", ClaimStatus::kSkipped,
              "E does not span mu in [0, 1], so integral f_ms cos cannot be formed");
      return;
    }
    const int g = std::max(2, set.FurnaceGrid());
    // The roughness range both tables cover.
    const double rLo = std::max(te.y.min, ta.x.min), rHi = std::min(te.y.max, ta.x.max);
    const double errE = e->statedErrorMax, errA = a->statedErrorMax;
    const double refErrorE = *std::max_element(e->refError.begin(), e->refError.end());
    double worst = 0.0, worstRef = 0.0, worstExcess = -1.0, excessValue = 0, excessAllowed = 0;
    std::vector<std::pair<std::string, double>> at, atRef, atExcess;
    int notJudged = 0, undefined = 0;
    double notJudgedBelow = -1.0, undefinedBelow = -1.0;
    for (int j = 0; j < g; ++j) {
      const double r = rLo + (rHi - rLo) * j / (g - 1);
      const double avg = Lookup(ta, r, 0.0, 0), avgRef = Lookup(ta, a->ref, r, 0.0, 0);
      const double mix = LookupMuAverage(te, te.values, r, 0);
      const double mixRef = LookupMuAverage(te, e->ref, r, 0);
      const double epsA = errA + FloatRounding(avg) + Lookup(ta, a->refError, r, 0.0, 0);
      const double epsE = errE + FloatRounding(1.0) + refErrorE;
      // E_avg = 1 (it rounds there as r -> 0 in float): f_ms is 0 / 0 and an
      // engine must guard the division. Reported, not judged.
      if (!(1.0 - avg > 0.0) || !(1.0 - avgRef > 0.0)) {
        undefined += g;
        undefinedBelow = std::max(undefinedBelow, r);
        continue;
      }
      // Where 1 - E_avg is within ten times E_avg's error the lobe's
      // normalisation is not determined by the table: the deviation is
      // reported but not judged against exact texels.
      const bool judged = 1.0 - avg > 10.0 * epsA;
      if (!judged) {
        notJudged += g;
        notJudgedBelow = std::max(notJudgedBelow, r);
      }
      for (int i = 0; i < g; ++i) {
        const double mu = static_cast<double>(i) / (g - 1);
        const double eo = Lookup(te, mu, r, 0), eoRef = Lookup(te, e->ref, mu, r, 0);
        const double q = (avg - mix) / (1.0 - avg);
        const double d = (1.0 - eo) * q;
        const double dRef = (1.0 - eoRef) * (avgRef - mixRef) / (1.0 - avgRef);
        if (std::abs(d) > worst) worst = std::abs(d), at = {{"mu", mu}, {"roughness", r}};
        if (std::abs(dRef) > worstRef)
          worstRef = std::abs(dRef), atRef = {{"mu", mu}, {"roughness", r}};
        if (!judged) continue;
        // First-order propagation of the bounds of E_o, E~ and E_avg, with
        // 20% for the second-order terms (epsA < (1 - E_avg) / 10 here).
        const double allowed = 1.2 * (std::abs(q) * epsE + (1.0 - eo) / (1.0 - avg) * epsE +
                                      (1.0 - eo) * std::abs(1.0 - mix) / Sqr(1.0 - avg) * epsA);
        const double excess = std::abs(d - dRef) - allowed;
        if (excess > worstExcess)
          worstExcess = excess, excessValue = std::abs(d - dRef), excessAllowed = allowed,
          atExcess = {{"mu", mu}, {"roughness", r}};
      }
    }
    std::string detail = "E + integral f_ms cos - 1 over " + std::to_string(g) + " x " +
                         std::to_string(g) + " (mu, r) in [0, 1] x [" + Short(rLo) + ", " +
                         Short(rHi) + "]: max |deviation| " + Short(worst) + " at " + Where(at) +
                         "; exact texels at the same places give " + Short(worstRef) + " at " +
                         Where(atRef);
    if (notJudged > 0)
      detail += "; " + std::to_string(notJudged) + " points with r <= " + Short(notJudgedBelow) +
                " not judged against exact texels (1 - E_avg within 10x E_avg's error)";
    if (undefined > 0)
      detail += "; E_avg is 1 at r <= " + Short(undefinedBelow) +
                ": f_ms is 0 / 0 there and an engine must guard it";
    if (worstExcess > 0.0)
      set.Add(subject, "furnace", ClaimStatus::kFail,
              "the baked deviation departs from that of exact texels by " + Short(excessValue) +
                  " at " + Where(atExcess) + ", more than the " + Short(excessAllowed) +
                  " the tables' bounds allow. " + detail,
              excessValue, excessAllowed, atExcess);
    else
      set.Add(subject, "furnace", ClaimStatus::kPass, detail, worst, 0.0, at);
  }

 private:
  std::string averaged_ = "E";
};

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
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {AverageOfClaim("E"), std::make_shared<KullaContyFurnace>()};
  }
  PlanRole Role() const override { return PlanRole::kEnergyCompensation; }
  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.lookupComment = "Average albedo E_avg at perceptual roughness r.";
    return text;
  }
  // Where the set holds the E of the same model (E_beckmann beside
  // Eavg_beckmann): the Kulla-Conty functions, and f_ms from the two
  // textures.
  std::vector<ShaderPiece> ShaderHelpers(const Dialect &d, const Table &avg,
                                         const std::vector<Table> &set) const override {
    const std::string ofName = Relations().averageOf;
    const std::string suffix = avg.Name().substr(std::string(Name()).size());
    const auto of = std::find_if(set.begin(), set.end(), [&](const Table &t) {
      return t.definition && t.definition->Name() == ofName && t.Name() == ofName + suffix;
    });
    if (of == set.end()) return {};
    const std::string F = d.Float();
    auto params = d.TextureParams(of->Name() + "_texture");
    for (const auto &p : d.TextureParams(avg.Name() + "_texture")) params.push_back(p);
    params.insert(params.end(), {{F, "mu_o"}, {F, "mu_i"}, {F, "r"}});
    const std::string e =
        "lutbake_sample_" + of->Name() + "(" + d.TextureArgs(of->Name() + "_texture");
    return {{2, "kulla_conty", KullaContyShaderCore(d)},
            {2, "kulla_conty_" + avg.Name(),
             "// f_ms from the textures of " + of->Name() + " and " + avg.Name() + ".\n" +
                 d.Function(F, "lutbake_f_ms_" + of->Name(), params,
                            "  return lutbake_f_ms(" + e + ", mu_o, r), " + e + ", mu_i, r),\n" +
                                "                      lutbake_sample_" + avg.Name() + "(" +
                                d.TextureArgs(avg.Name() + "_texture") + ", r));\n")}};
  }
};

}  // namespace

const TableDefinition &AverageAlbedoTable() {
  static const AverageAlbedo table;
  return table;
}

}  // namespace lutbake
