// Table ltc_sheen: linearly transformed cosines (ltc_table.h) fitted to the
// cosine-weighted Charlie sheen lobe f(v, l) (n.l) of table sheen_E (glTF
// KHR_materials_sheen, sheen colour 1, F = 1; --sheen-visibility charlie or
// ashikhmin, --sheen-alpha linear or squared), for rectangular and polygonal
// area lights on sheen (three.js#34438). Axes as sheen_E's: x = mu in
// [0, 1], y = sheenRoughness r in [0, 1], texel centres, 64 x 64 by default.
//
// Channels m00, m20, m02, m22, magnitude, fresnel (ltc_table.h):
//   magnitude = int f (n.l) dl: sheen_E's value at the point, bit for bit
//               (the same integrator and tolerance, the same bound);
//   fresnel   = int f (n.l) (1 - v.h)^5 dl: the half-vector rule (below) at
//               level 2, bounded by its difference from level 1 plus
//               kFresnelFloor; the adaptive Schlick-weighted Gauss-Kronrod
//               (sheen_quadrature.h) for check's reference.
// The lobe is integrated by the half-vector rule of width max(alpha, 1e-3)
// (SheenLtcLobe): the Charlie D peaks at the horizon of h, where the rule's
// tail panels are graded. At r = 0 there is no lobe (magnitude = fresnel =
// 0): the fit keeps its neighbour's matrix, and the errors are 0. With the
// Charlie visibility the albedo is infinite at mu = 0: eval refuses that
// point (no texel centre lies there).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "definitions.h"
#include "ltc_table.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "sampled_texel.h"
#include "sheen_table.h"

namespace lutbake {

namespace {

// What the fresnel bound adds to |level 2 - level 1|: the largest
// difference of level 2 from the adaptive reference measured over both
// visibilities, both mappings and a 16 x 16 grid was 6e-9 (ltc_sheen_test).
constexpr double kFresnelFloor = 5e-8;

class LtcSheen final : public LtcTableDefinition<SheenTable> {
 public:
  PlanRole Role() const override { return PlanRole::kSheenAreaLights; }
  const char *Name() const override { return "ltc_sheen"; }
  uint64_t SeedId() const override { return 15; }
  std::string Summary() const override {
    return "linearly transformed cosine of the Charlie sheen lobe (F = 1) for area lights: M^-1, "
           "magnitude = sheen_E, fresnel";
  }
  std::string ChannelLayout() const override {
    return "m00, m20, m02, m22 = M^-1 [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame n = "
           "+z, v = (sqrt(1 - mu^2), 0, mu); magnitude = int f (n.l) dl (= sheen_E); fresnel = "
           "int f (n.l) (1 - v.h)^5 dl";
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
          "comma-separated numbers in (0, 1]: with the Charlie visibility the lobe's albedo is "
          "infinite at mu = 0";
    }
    return {mu, RoughnessCoordinate()};
  }
  int PlannedRoughnessAxis() const override { return 1; }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "m00..m22: fitted by Nelder-Mead to the L1 error on the sphere, integrated by a "
           "half-vector quadrature, each texel started from its neighbour's (largest roughness "
           "first, from mu = 1 down, then each mu from the largest roughness down); magnitude: "
           "table sheen_E's panel Gauss-Legendre quadrature; fresnel: the half-vector rule at "
           "level 2";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "m00..m22: 0 (the fit is the value; its quality is fitErrors); magnitude: sheen_E's "
           "(two orders of the panel rule); fresnel: |level 2 - level 1| + 5e-8";
  }
  // Its magnitude is sheen_E's value.
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {ChannelIsClaim("sheen_E", 4)};
  }

  LtcLobe LobeAt(const BakeSettings &s, double r) const override {
    return SheenLtcLobe(s.sheenVisibility, AlphaOf(s, r));
  }
  void Moments(const BakeSettings &s, double mu, double r, PointValue *out) const override {
    BakeSettings q = s;
    if (q.estimator != Estimator::kAdaptiveQuadrature) q.estimator = Estimator::kQuadrature;
    const PointValue e = SheenAlbedoTable().Evaluate(q, mu, r);
    out->value[4] = e.value[0];
    out->error[4] = e.error[0];
    out->evaluations += e.evaluations;
    out->quadrature = true;
    const double alpha = AlphaOf(s, r);
    if (alpha == 0.0) {  // no lobe
      out->value[5] = out->error[5] = 0.0;
      return;
    }
    if (q.estimator == Estimator::kAdaptiveQuadrature) {
      const SheenIntegral f =
          IntegrateSheenSchlickWeightedAdaptive(s.sheenVisibility, alpha, mu, AdaptiveTolerance(s));
      out->value[5] = f.value;
      out->error[5] = f.bound;
      out->evaluations += f.evaluations;
      return;
    }
    const LtcLobe lobe = LobeAt(s, r);
    double m1 = 0, f1 = 0, m2 = 0, f2 = 0;
    IntegrateLobeMoments(lobe, mu, 1, &m1, &f1);
    IntegrateLobeMoments(lobe, mu, 2, &m2, &f2);
    out->value[5] = f2;
    out->error[5] = std::fabs(f2 - f1) + kFresnelFloor;
  }
  void CheckPoint(const BakeSettings &s, double mu, double r) const override {
    AlphaOf(s, r);  // throws outside [0, 1]
    const bool charlie = UsesCharlieLambda(s.sheenVisibility);
    if (!(mu >= 0.0 && mu <= 1.0) || (charlie && mu == 0.0))
      throw std::domain_error("mu " + FormatDouble(mu) + " is outside " +
                              (charlie ? "(0, 1] (the Charlie visibility's albedo is infinite "
                                         "at mu = 0)"
                                       : "[0, 1]"));
  }
  std::string LobeErrorRule() const override {
    return "half-vector rule of width max(alpha, 1e-3), within 6e-3 of its next level (measured at "
           "64 x 64: worst 5.2e-3, at the smallest roughness)";
  }

  HeaderText Header(const Table &table) const override {
    HeaderText text;
    AddModelNotes(table, &text);
    AddLtcNotes(&text, "sheen_E");
    text.lookupComment =
        "{m00, m20, m02, m22, magnitude, fresnel} at view cosine mu and sheenRoughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &LtcSheenTable() {
  static const LtcSheen table;
  return table;
}

}  // namespace lutbake
