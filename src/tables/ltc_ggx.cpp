// Table ltc_ggx: linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt
// 2016; models/ltc.h) fitted to the cosine-weighted microfacet lobe
// f(v, l) (n.l) of table E (F = 1, --ndf, --smith), for rectangular and
// polygonal area lights. Axes as E's: x = mu in [0, 1], y = perceptual
// roughness r (alpha = r^2), texel centres, 64 x 64 by default.
//
// Channels, in this order (issue 28):
//   m00, m20, m02, m22  M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
//                       (normalised so that its middle element is 1), acting
//                       on directions in the frame where n = +z and the view
//                       is v = (sqrt(1 - mu^2), 0, mu); det M^-1 > 0.
//   magnitude           int f (n.l) dl: exactly table E's value at the point
//                       (the same integrator, the same bound);
//   fresnel             int f (n.l) (1 - v.h)^5 dl: table dfg's B;
// so that the lobe is approximated by magnitude D(l), D the LTC density, and a
// Schlick F by F0 magnitude + (1 - F0) fresnel.
//
// The fit, eval, the error maps and check's measures: ltc_table.h, shared
// by every LTC table; the lobe here is integrated by the half-vector rule.
#include <cmath>
#include <stdexcept>

#include "definitions.h"
#include "ltc_area_light_code.h"
#include "ltc_table.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

class LtcGgx final : public LtcTableDefinition<MuRoughnessTable> {
 public:
  PlanRole Role() const override { return PlanRole::kAreaLights; }
  const char *Name() const override { return "ltc_ggx"; }
  uint64_t SeedId() const override { return 14; }
  std::string Summary() const override {
    return "linearly transformed cosine of the microfacet lobe (F = 1) for area lights: M^-1, "
           "magnitude = E, fresnel";
  }
  std::string ChannelLayout() const override {
    return "m00, m20, m02, m22 = M^-1 [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame n = "
           "+z, v = (sqrt(1 - mu^2), 0, mu); magnitude = int f (n.l) dl (= E); fresnel = int f "
           "(n.l) (1 - v.h)^5 dl";
  }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "m00..m22: fitted by Nelder-Mead to the L1 error on the sphere, integrated by a "
           "half-vector quadrature, each texel started from its neighbour's (largest roughness "
           "first, from mu = 1 down, then each mu from the largest roughness down); magnitude "
           "and fresnel: table E's and dfg's panel Gauss-Legendre quadrature";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "m00..m22: 0 (the fit is the value; its quality is fitErrors); magnitude, fresnel: "
           "|V_k - V_(k-1)| + 1e-10 of the panel rule at two orders";
  }
  // Its magnitude is E's value.
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {ChannelIsClaim("E", 4)};
  }
  // The lobe at perceptual roughness r.
  LtcLobe LobeAt(const BakeSettings &s, double r) const override {
    return MicrofacetLtcLobe(Ndf{s.ndf, r * r}, s.smith);
  }
  // magnitude and fresnel (with their bounds) into channels 4 and 5.
  // The panel quadrature, as tables E and dfg bake; the adaptive one when
  // asked (check's reference).
  void Moments(const BakeSettings &s, double mu, double r, PointValue *out) const override {
    BakeSettings q = s;
    if (q.estimator != Estimator::kAdaptiveQuadrature) q.estimator = Estimator::kQuadrature;
    const double alpha = r * r;
    const PointValue e = EvaluateAlbedo(DirectionalAlbedoTable(), q, mu, alpha, 0);
    const PointValue ab = EvaluateAlbedo(SplitSumTable(), q, mu, alpha, 0);
    out->value[4] = e.value[0];
    out->error[4] = e.error[0];
    out->value[5] = ab.value[1];
    out->error[5] = ab.error[1];
    out->evaluations += e.evaluations + ab.evaluations;
    out->quadrature = true;
  }
  void CheckPoint(const BakeSettings &, double mu, double r) const override {
    if (!(mu >= 0.0 && mu <= 1.0) || !(r == 0.0 || (r >= std::sqrt(kMinimumAlpha) && r <= 1.0)))
      throw std::domain_error("(mu, r) = (" + FormatDouble(mu) + ", " + FormatDouble(r) +
                              ") is outside [0, 1] x ({0} or [1e-12, 1])");
  }
  std::string LobeErrorRule() const override {
    return "half-vector rule, within ~1.3e-3 at grazing views";
  }

  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    AddLtcNotes(&text, "E");
    text.lookupComment =
        "{m00, m20, m02, m22, magnitude, fresnel} at view cosine mu and perceptual roughness r.";
    return text;
  }
  // Rectangular area lights (ltc_area_light_code.h): the polygon integral
  // once, then this table's rectangle.
  std::vector<ShaderPiece> ShaderHelpers(const source_text::Dialect &d, const Table &table,
                                         const std::vector<Table> &) const override {
    if (table.channels != 6) return {};
    return {{4, "ltc_polygon", LtcPolygonFunctions(d)},
            {4, "ltc_rectangle_" + table.Name(), LtcRectangleFunctions(d, table)}};
  }
};

}  // namespace

const TableDefinition &LtcGgxTable() {
  static const LtcGgx table;
  return table;
}

}  // namespace lutbake
