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
#include "sampled_texel.h"
#include "sheen_table.h"

namespace lutbake {

namespace {

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

  TableRelations Relations() const override {
    TableRelations r;
    r.albedoScaling = true;
    return r;
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
};

}  // namespace

const TableDefinition &SheenAlbedoTable() {
  static const SheenAlbedo table;
  return table;
}

}  // namespace lutbake
