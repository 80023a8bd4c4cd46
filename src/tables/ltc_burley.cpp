// Table ltc_burley: linearly transformed cosines (ltc_table.h) fitted to
// the cosine-weighted Burley diffuse lobe f(v, l) (n.l) of table burley_E
// (Disney 2012, base colour 1; models/burley.h), as Unity HDRP's Disney
// diffuse LTC slice holds it. Axes as burley_E's: x = mu in [0, 1], y =
// perceptual roughness r in [0, 1], texel centres, 64 x 64 by default.
//
// Channels m00, m20, m02, m22, magnitude, fresnel (ltc_table.h):
//   magnitude = int f (n.l) dl: burley_E's value at the point, bit for bit
//               (its closed form, bound 1e-14);
//   fresnel   = int f (n.l) (1 - v.h)^5 dl: the light-direction rule at
//               level 2, bounded by its difference from level 1 plus 1e-12;
//               the nested adaptive Gauss-Kronrod (IntegrateLobeMomentsAdaptive)
//               for check's reference.
// The lobe is smooth over the hemisphere: the fit and the errors integrate
// it by the light-direction rule (BurleyLtcLobe).
#include <cmath>
#include <stdexcept>

#include "burley_model.h"
#include "definitions.h"
#include "ltc_table.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "sampled_texel.h"

namespace lutbake {

namespace {

class LtcBurley final : public LtcTableDefinition<BurleyModelTable> {
 public:
  const char *Name() const override { return "ltc_burley"; }
  uint64_t SeedId() const override { return 16; }
  std::string Summary() const override {
    return "linearly transformed cosine of Burley's (Disney 2012) diffuse lobe for area lights: "
           "M^-1, magnitude = burley_E, fresnel";
  }
  std::string ChannelLayout() const override {
    return "m00, m20, m02, m22 = M^-1 [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame n = "
           "+z, v = (sqrt(1 - mu^2), 0, mu); magnitude = int f (n.l) dl (= burley_E); fresnel = "
           "int f (n.l) (1 - v.h)^5 dl";
  }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "m00..m22: fitted by Nelder-Mead to the L1 error on the sphere, integrated by a "
           "light-direction Gauss quadrature, each texel started from its neighbour's (largest "
           "roughness first, from mu = 1 down, then each mu from the largest roughness down); "
           "magnitude: table burley_E's closed form; fresnel: the light-direction rule at level 2";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "m00..m22: 0 (the fit is the value; its quality is fitErrors); magnitude: 1e-14 (the "
           "closed form's rounding); fresnel: |level 2 - level 1| + 1e-12";
  }
  // Its magnitude is burley_E's value.
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {ChannelIsClaim("burley_E", 4)};
  }

  LtcLobe LobeAt(const BakeSettings &, double r) const override { return BurleyLtcLobe(r); }
  void Moments(const BakeSettings &s, double mu, double r, PointValue *out) const override {
    BakeSettings q = s;
    if (q.estimator != Estimator::kAdaptiveQuadrature) q.estimator = Estimator::kQuadrature;
    const PointValue e = BurleyAlbedoTable().Evaluate(q, mu, r);
    out->value[4] = e.value[0];
    out->error[4] = e.error[0];
    out->evaluations += e.evaluations;
    out->quadrature = true;
    LtcDiffuseFresnel(LobeAt(s, r), q, mu, out);
  }
  void CheckPoint(const BakeSettings &, double mu, double r) const override {
    if (!(mu >= 0.0 && mu <= 1.0) || !(r >= 0.0 && r <= 1.0))
      throw std::domain_error("(mu, r) = (" + FormatDouble(mu) + ", " + FormatDouble(r) +
                              ") is outside [0, 1] x [0, 1]");
  }
  std::string LobeErrorRule() const override {
    return "light-direction rule, within 4e-4 of its next level (measured at 64 x 64, worst at "
           "grazing views)";
  }

  HeaderText Header(const Table &) const override {
    HeaderText text;
    text.notes.push_back(
        "Burley (Disney 2012) diffuse, base colour 1: f = F(NdotL) F(NdotV) / pi, F(u) = 1 +");
    text.notes.push_back(
        "(F_D90 - 1) (1 - u)^5, F_D90 = 0.5 + 2 r LdotH^2, r = perceptual roughness.");
    AddLtcNotes(&text, "burley_E");
    text.lookupComment =
        "{m00, m20, m02, m22, magnitude, fresnel} at view cosine mu and perceptual roughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &LtcBurleyTable() {
  static const LtcBurley table;
  return table;
}

}  // namespace lutbake
