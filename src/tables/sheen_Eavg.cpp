// Table sheen_Eavg: the cosine-weighted average of sheen_E over the view,
//   sheen_Eavg(r) = 2 integral_0^1 sheen_E(mu, r) mu dmu,
// finite for both visibilities (Charlie's E ~ C / mu at the horizon leaves
// E mu bounded). Same model and options as sheen_E; axis x = r in [0, 1],
// 32 texels (1D). It is 0 at r = 0 (sheen_E is 0 at every mu > 0 there).
// The quadrature integrates mu on panels (sheen_quadrature.h). The sampled
// estimators draw mu_o uniformly in (0, 1] and the light uniformly on the
// hemisphere, weight 2 mu_o 2 pi D W: bounded by (2 + 1/alpha) / 2 (D <=
// (2 + 1/alpha) / (2 pi), W <= 1 / (4 mu_o) for Charlie and <= 1/4 for
// Ashikhmin), where the Charlie lobe's weight would grow as 1 / mu_o.
// check asserts sheen_Eavg >= 0 and the average of sheen_E's rows.
#include <cmath>
#include <stdexcept>

#include "lutbake/integrators/sheen_estimator.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "sampled_texel.h"
#include "sheen_table.h"

namespace lutbake {

namespace {

class SheenAverageAlbedo final : public SheenTable {
 public:
  const char *Name() const override { return "sheen_Eavg"; }
  uint64_t SeedId() const override { return 5; }
  std::string Summary() const override {
    return "average sheen albedo 2 integral sheen_E(mu, r) mu dmu";
  }
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override {
    *x = LinearAxis("sheenRoughness", 0.0, 1.0, size);
    *y = LinearAxis("", 0.0, 1.0, 1);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override {
    return {RoughnessCoordinate()};
  }
  int PlannedRoughnessAxis() const override { return 0; }

  PointValue Evaluate(const BakeSettings &s, double r, double) const override {
    const double alpha = AlphaOf(s, r);
    const SheenVisibility v = s.sheenVisibility;
    if (s.estimator == Estimator::kAdaptiveQuadrature)
      return FromIntegral(IntegrateSheenAlbedoAverageAdaptive(v, alpha, AdaptiveTolerance(s)));
    if (s.estimator == Estimator::kQuadrature || alpha == 0.0)
      return FromIntegral(IntegrateSheenAlbedoAverage(v, alpha, PanelTolerance(s)));
    if (const std::string problem = EstimatorProblem(s.estimator); !problem.empty())
      throw std::invalid_argument(problem);
    // (2 + 1/alpha) / 2, and the rounding of the weights.
    const double maxWeight = (2.0 + 1.0 / alpha) / 2.0 * (1.0 + 1e-12);
    const uint64_t seed = SampleSeed(SeedId(), s, PointSeed(SeedId(), alpha, 0.0, s.seed));
    PointValue out;
    const bool sampled = SampleTexel<3, 1>(
        s,
        [&](const PointView &p, double *w[]) {
          for (size_t k = 0; k < p.n; ++k) {
            const double mu_o = 1.0 - p.u[2][k];  // in (0, 1]: Charlie's E is infinite at 0
            const SheenAlbedoEstimator e(v, alpha, SheenStrategy::kUniform, mu_o);
            w[0][k] = 2.0 * mu_o * e.Weight(p.u[0][k], p.u[1][k]);
          }
        },
        SamplesPerTexel(s), seed, &out, maxWeight);
    if (sampled) return out;
    PointValue q = FromIntegral(IntegrateSheenAlbedoAverage(v, alpha, PanelTolerance(s)));
    q.samples = out.samples;
    return q;
  }
  // As many samples per texel as a whole 32-texel row of sheen_E.
  uint64_t SamplesPerTexel(const BakeSettings &s) const override {
    return IsQuadrature(s.estimator) ? 0 : s.samples * kAverageSampleFactor;
  }
  std::string SamplerNote(const BakeSettings &) const override {
    return "mu_o uniform in (0, 1] and light directions uniform on the hemisphere, whatever "
           "the sampler's name (the Charlie lobe's weight is unbounded as mu_o -> 0)";
  }
  double ReferenceCost() const override { return 32.0; }
  // The half-vector adaptive E_avg takes seconds a point (nested adaptive
  // rules at 1e-8), too slow for check's 288 points. check judges this
  // table with the panel rule at 1/64 of its bound instead; the
  // independent judgement is its average relation to sheen_E, whose texels
  // check holds to the adaptive half-vector rule.
  Estimator ReferenceEstimator() const override { return Estimator::kQuadrature; }

  TableRelations Relations() const override {
    TableRelations r;
    r.averageOf = "sheen_E";
    return r;
  }
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {AverageOfClaim("sheen_E")};
  }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    AddModelNotes(table, &text);
    text.lookupComment = "Average sheen albedo at sheenRoughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &SheenAverageAlbedoTable() {
  static const SheenAverageAlbedo table;
  return table;
}

}  // namespace lutbake
