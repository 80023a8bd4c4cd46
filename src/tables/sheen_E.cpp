// Table sheen_E: the directional albedo of the Charlie sheen BRDF of glTF's
// KHR_materials_sheen (Estevez and Kulla 2017), sheen colour 1, F = 1:
//   sheen_E(mu_o, r) = integral over the hemisphere of D(h) V(o, i) mu_i d omega_i,
//   D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
//   V = 1 / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i)   (--sheen-visibility charlie:
//       Lambda the fit the glTF extension gives), or
//   V = 1 / (4 (mu_i + mu_o - mu_i mu_o))                     (ashikhmin),
// alpha = r (--sheen-alpha linear, the default) or r^2 (squared), r glTF's
// sheenRoughness. Axes: x = mu_o in [0, 1], y = r in [0, 1], 32 x 32.
// Integrators: integrators/sheen_quadrature.h (the panel rule by default,
// the half-vector adaptive rule as the reference) and sheen_estimator.h
// (the Charlie lobe for ndf and vndf, uniform light directions).
//
// Limits. As r -> 0 the lobe collapses onto the horizon of h, which a light
// above the horizon reaches only from a grazing view: E(mu_o > 0) -> 0, and
// r = 0 is exactly 0 there. At mu_o = 0 the integral is infinite with the
// Charlie visibility for every r (its fitted Lambda stays finite at the
// horizon, so V mu_i ~ 1 / (4 mu_o (1 + Lambda(0) + Lambda(mu_i)))): eval
// refuses mu = 0 then; with Ashikhmin it is finite for r > 0. E is not
// bounded by 1: it exceeds 1 at grazing views and small r (check reports
// where). The albedo-scaling helper in the header is glTF's
//   sheen_albedo_scaling = 1 - max3(sheenColor) E(NdotV, r),
// and check's furnace measures what the stored E gives a white base under
// a white sheen: 1 + E - E_lookup.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lutbake/integrators/sheen_estimator.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"
#include "lutbake/tables/shader_dialect.h"
#include "sampled_texel.h"
#include "sheen_table.h"

namespace lutbake {

namespace {

// The albedo-scaling furnace (glTF KHR_materials_sheen): a white sheen
// over a white base that reflects everything, the base scaled by
// 1 - E_lookup(mu_o), reflects E(mu_o) + 1 - E_lookup(mu_o): 1 plus the
// error of the lookup an engine does. Over a grid of (mu, r) cell centres
// (the reference rule's values there: NeedsGrid): that deviation; judged
// against what exact texels give there (|E_lookup - lookup of exact
// texels| within the stated bounds), and where E_lookup > 1 makes the
// base's weight negative.
class AlbedoScalingFurnace final : public SetClaim {
 public:
  int Order() const override { return 3; }
  bool NeedsGrid() const override { return true; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    using namespace claim_text;
    const CheckedTable &t = self;
    if (!t.usable) return;

    const std::string name = t.def->Name() + set.Suffix();
    const Table &table = t.table;
    const std::vector<ReferencePoint> &grid = set.Grid(t);
    const int g = static_cast<int>(std::lround(std::sqrt(static_cast<double>(grid.size()))));
    double worst = 0.0, worstExact = 0.0, worstExcess = -1.0, excessValue = 0.0,
           excessAllowed = 0.0, gain = 0.0;
    std::vector<std::pair<std::string, double>> at, atExact, atExcess, atGain;
    size_t negative = 0, compared = 0;
    double negativeBelow = -1.0;
    for (const ReferencePoint &p : grid) {
      if (!std::isfinite(p.truth.value[0])) continue;
      ++compared;
      const double lookup = Lookup(table, p.x, p.y, 0);
      const double lookupRef = Lookup(table, t.ref, p.x, p.y, 0);
      const double d = p.truth.value[0] - lookup, dExact = p.truth.value[0] - lookupRef;
      const auto here = At(table, p.x, p.y);
      if (std::abs(d) > worst) worst = std::abs(d), at = here;
      if (std::abs(dExact) > worstExact) worstExact = std::abs(dExact), atExact = here;
      if (d > gain) gain = d, atGain = here;
      if (lookup > 1.0) ++negative, negativeBelow = std::max(negativeBelow, p.y);
      const double allowed = t.statedErrorMax + Lookup(table, t.refError, p.x, p.y, 0) +
                             p.truth.error[0] + 2.0 * FloatRounding(lookup);
      const double excess = std::abs(lookup - lookupRef) - allowed;
      if (excess > worstExcess)
        worstExcess = excess, excessValue = std::abs(lookup - lookupRef), excessAllowed = allowed,
        atExcess = here;
    }
    std::string detail = "white sheen + (1 - E_lookup) white base over " + std::to_string(g) +
                         " x " + std::to_string(g) + " (mu, r) cell centres: total - 1 = E - " +
                         "E_lookup, max |.| " + Short(worst) + " at " + Where(at) +
                         "; exact texels give " + Short(worstExact) + " at " + Where(atExact);
    if (gain > 0.0)
      detail += "; the most energy gained " + Short(gain) + " at " + Where(atGain) +
                " (interpolation included)";
    if (negative > 0)
      detail +=
          "; E_lookup > 1 (the base's weight negative: albedo scaling cannot conserve "
          "energy there) at " +
          std::to_string(negative) + " of " + std::to_string(compared) + " points, r up to " +
          Short(negativeBelow);
    if (worstExcess > 0.0)
      set.Add(name, "furnace", ClaimStatus::kFail,
              "the lookup departs from a lookup of exact texels by " + Short(excessValue) + " at " +
                  Where(atExcess) + ", more than the " + Short(excessAllowed) +
                  " the table's bounds allow. " + detail,
              excessValue, excessAllowed, atExcess);
    else
      set.Add(name, "furnace", ClaimStatus::kPass, detail, worst, 0.0, at);
  }
};

class SheenAlbedo final : public SheenTable {
 public:
  const char *Name() const override { return "sheen_E"; }
  uint64_t SeedId() const override { return 4; }
  std::string Summary() const override {
    return "directional albedo of the Charlie sheen BRDF (KHR_materials_sheen), sheen colour 1";
  }
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override {
    *x = MuAxis(size);
    *y = LinearAxis("sheenRoughness", 0.0, 1.0, size);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &s) const override {
    PointCoordinate mu;
    mu.option = "mu";
    mu.accepted = "comma-separated numbers in [0, 1]";
    if (UsesCharlieLambda(s.sheenVisibility)) {
      mu.min = std::numeric_limits<double>::denorm_min();
      mu.accepted =
          "comma-separated numbers in (0, 1]: with the Charlie visibility E is infinite at mu = "
          "0 (its fitted Lambda stays finite at the horizon, so E grows as 1 / mu)";
    }
    return {mu, RoughnessCoordinate()};
  }
  int PlannedRoughnessAxis() const override { return 1; }
  // A fit stops short of mu = 0, where the Charlie albedo grows as 1 / mu,
  // and of r = 0, where the lobe's grazing peak narrows without end.
  std::array<double, 4> FitDomain(const BakeSettings &) const override {
    return {1e-4, 1.0, 0.01, 1.0};
  }
  // In log(mu + 7e-4) and log(r): E ~ r^-1/2 toward r = 0.01 and changes
  // by about as much per decade of mu down to 1e-4, but a pure log(mu) would
  // spend most of its degree on the last decades, where E hardly moves.
  // Measured on sheen_E's default model with 24 x 10 coefficients, max error
  // on a 72^2 grid: shift 3e-4 3.1e-4, 5e-4 2.5e-4, 7e-4 2.0e-4, 1e-3
  // 2.6e-4, 1.5e-3 3.7e-4; plain log(mu) and linear r 2.6e-2 at 16 x 16.
  FitCoordinates FitCoordinateMaps(const BakeSettings &) const override { return {true, 7e-4}; }

  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    const double alpha = AlphaOf(s, r);
    if (!(mu >= 0.0 && mu <= 1.0))
      throw std::domain_error("mu " + FormatDouble(mu) + " is outside [0, 1]");
    const SheenVisibility v = s.sheenVisibility;
    if (s.estimator == Estimator::kAdaptiveQuadrature)
      return FromIntegral(IntegrateSheenAlbedoAdaptive(v, alpha, mu, AdaptiveTolerance(s)));
    if (s.estimator == Estimator::kQuadrature || alpha == 0.0)
      return FromIntegral(IntegrateSheenAlbedo(v, alpha, mu, PanelTolerance(s)));
    if (const std::string problem = EstimatorProblem(s.estimator); !problem.empty())
      throw std::invalid_argument(problem);
    const SheenStrategy strategy =
        s.estimator == Estimator::kUniform ? SheenStrategy::kUniform : SheenStrategy::kCharlieLobe;
    const SheenAlbedoEstimator estimator(v, alpha, strategy, mu);
    const uint64_t seed = SampleSeed(SeedId(), s, PointSeed(SeedId(), mu, alpha, s.seed));
    PointValue out;
    const bool sampled = SampleTexel<2, 1>(
        s,
        [&](const PointView &p, double *w[]) {
          for (size_t k = 0; k < p.n; ++k) w[0][k] = estimator.Weight(p.u[0][k], p.u[1][k]);
        },
        s.samples, seed, &out, estimator.MaxWeight());
    if (sampled) return out;
    PointValue q = FromIntegral(IntegrateSheenAlbedo(v, alpha, mu, PanelTolerance(s)));
    q.samples = out.samples;  // the rounds spent before switching still count
    return q;
  }
  std::string SamplerNote(const BakeSettings &s) const override {
    return s.estimator == Estimator::kUniform
               ? "light directions uniform on the hemisphere"
               : "half vectors from the Charlie lobe D(h) cos(theta_h) (the sheen has no "
                 "visible-normal form)";
  }

  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {std::make_shared<AlbedoScalingFurnace>()};
  }
  PlanRole Role() const override { return PlanRole::kSheenAlbedoScaling; }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    AddModelNotes(table, &text);
    text.notes.push_back("E is the true integral: it exceeds 1 at grazing views and small r.");
    text.lookupComment =
        "Directional albedo E of the sheen (colour 1) at view cosine mu and sheenRoughness r.";
    const std::string name = table.Name();
    text.helpers = [name](const std::string &lookup) {
      return "// glTF KHR_materials_sheen's albedo scaling of the layers under a sheen of\n"
             "// colour sheenColor, with the view's lookup alone:\n"
             "//   albedo_scaling = 1 - max3(sheenColor) E(NdotV, r),\n"
             "// and with both directions (the extension's punctual-light form):\n"
             "//   albedo_scaling = min(1 - max3(sheenColor) E(NdotV, r),\n"
             "//                        1 - max3(sheenColor) E(NdotL, r)).\n"
             "// Shade as sheenColor * f_sheen + albedo_scaling * f_base. Where\n"
             "// max3(sheenColor) E > 1 the scaling is negative: the formula is returned as\n"
             "// the extension states it, unclamped.\n"
             "inline float albedo_scaling_" +
             name +
             "(float NdotV, float r, float sheenColorR, float sheenColorG,\n"
             "                                  float sheenColorB) {\n"
             "  const float m = sheenColorR > sheenColorG ? sheenColorR : sheenColorG;\n"
             "  const float max3 = m > sheenColorB ? m : sheenColorB;\n"
             "  return 1.0f - max3 * " +
             lookup +
             "(NdotV, r);\n"
             "}\n\n"
             "inline float albedo_scaling_" +
             name +
             "(float NdotV, float NdotL, float r, float sheenColorR,\n"
             "                                  float sheenColorG, float sheenColorB) {\n"
             "  const float v = albedo_scaling_" +
             name +
             "(NdotV, r, sheenColorR, sheenColorG, sheenColorB);\n"
             "  const float l = albedo_scaling_" +
             name +
             "(NdotL, r, sheenColorR, sheenColorG, sheenColorB);\n"
             "  return v < l ? v : l;\n"
             "}\n\n";
    };
    return text;
  }
  // The same scaling in the shading languages, from E_v (and E_l) looked up.
  std::vector<ShaderPiece> ShaderHelpers(const source_text::Dialect &d, const Table &,
                                         const std::vector<Table> &) const override {
    const std::string F = d.Float(), F3 = d.Float(3);
    const std::string max3 = "max(max(sheenColor.x, sheenColor.y), sheenColor.z)";
    return {{3, "sheen_albedo_scaling",
             "// glTF KHR_materials_sheen's albedo scaling of the layers under a sheen of\n"
             "// colour sheenColor: with the view's albedo E_v = sheen_E(NdotV, sheenRoughness),\n"
             "//   albedo_scaling = 1 - max3(sheenColor) E_v,\n"
             "// and with the light's E_l = sheen_E(NdotL, sheenRoughness) too (punctual lights),\n"
             "//   albedo_scaling = min(1 - max3(sheenColor) E_v, 1 - max3(sheenColor) E_l).\n"
             "// Shade sheenColor f_sheen + albedo_scaling f_base. Unclamped, as the extension\n"
             "// states it (E exceeds 1 at grazing views of smooth sheen).\n" +
                 d.Function(F, "lutbake_sheen_albedo_scaling", {{F3, "sheenColor"}, {F, "E_v"}},
                            "  return " + d.Lit(1.0) + " - " + max3 + " * E_v;\n") +
                 d.Function(F, "lutbake_sheen_albedo_scaling2",
                            {{F3, "sheenColor"}, {F, "E_v"}, {F, "E_l"}},
                            "  return min(lutbake_sheen_albedo_scaling(sheenColor, E_v),\n"
                            "             lutbake_sheen_albedo_scaling(sheenColor, E_l));\n")}};
  }
};

}  // namespace

const TableDefinition &SheenAlbedoTable() {
  static const SheenAlbedo table;
  return table;
}

}  // namespace lutbake
