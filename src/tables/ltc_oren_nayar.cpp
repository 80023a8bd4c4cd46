// Table ltc_oren_nayar: linearly transformed cosines (ltc_table.h) fitted
// to the cosine-weighted qualitative ("A + B") Oren-Nayar lobe f(v, l) (n.l)
// of table oren_nayar_E (models/oren_nayar.h, reflectance 1), as Unity
// HDRP's Oren-Nayar LTC slice holds it. Axes as oren_nayar_E's: x = mu in
// [0, 1], y = sigma in [0, pi/2] (radians), texel centres, 64 x 64 by
// default.
//
// Channels m00, m20, m02, m22, magnitude, fresnel (ltc_table.h):
//   magnitude = int f (n.l) dl: oren_nayar_E's value at the point, bit for
//               bit (the furnace's integrator and bound);
//   fresnel   = int f (n.l) (1 - v.h)^5 dl: the light-direction rule at
//               level 2, bounded by its difference from level 1 plus 1e-12;
//               the nested adaptive Gauss-Kronrod for check's reference.
// The lobe is smooth over the hemisphere but for its kinks at theta_l =
// theta_o and cos(dphi) = 0, where the light-direction rule's panels are cut
// (OrenNayarLtcLobe). At sigma = 0 it is Lambert's: the LTC is the cosine.
#include <cmath>
#include <stdexcept>

#include "definitions.h"
#include "ltc_table.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "oren_nayar_model.h"

namespace lutbake {

namespace {

class LtcOrenNayar final : public LtcTableDefinition<OrenNayarModelTable> {
 public:
  LtcOrenNayar() : LtcTableDefinition<OrenNayarModelTable>(OrenNayarVariant::kQualitative) {}
  const char *Name() const override { return "ltc_oren_nayar"; }
  uint64_t SeedId() const override { return 17; }
  std::string Summary() const override {
    return "linearly transformed cosine of the qualitative (A + B) Oren-Nayar lobe for area "
           "lights: M^-1, magnitude = oren_nayar_E, fresnel";
  }
  std::string ChannelLayout() const override {
    return "m00, m20, m02, m22 = M^-1 [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame n = "
           "+z, v = (sqrt(1 - mu^2), 0, mu); magnitude = int f (n.l) dl (= oren_nayar_E); "
           "fresnel = int f (n.l) (1 - v.h)^5 dl";
  }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "m00..m22: fitted by Nelder-Mead to the L1 error on the sphere, integrated by a "
           "light-direction Gauss quadrature, each texel started from its neighbour's (largest "
           "sigma first, from mu = 1 down, then each mu from the largest sigma down); magnitude: "
           "table oren_nayar_E's quadrature; fresnel: the light-direction rule at level 2";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "m00..m22: 0 (the fit is the value; its quality is fitErrors); magnitude: "
           "oren_nayar_E's (16 x the Gauss-Kronrod estimate + 1e-13); fresnel: |level 2 - level "
           "1| + 1e-12";
  }
  // Its magnitude is oren_nayar_E's value.
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override {
    return {ChannelIsClaim("oren_nayar_E", 4)};
  }

  LtcLobe LobeAt(const BakeSettings &, double sigma) const override {
    return OrenNayarLtcLobe(variant_, sigma);
  }
  void Moments(const BakeSettings &s, double mu, double sigma, PointValue *out) const override {
    BakeSettings q = s;
    if (q.estimator != Estimator::kAdaptiveQuadrature) q.estimator = Estimator::kQuadrature;
    const PointValue e = OrenNayarAlbedoTable().Evaluate(q, mu, sigma);
    out->value[4] = e.value[0];
    out->error[4] = e.error[0];
    out->evaluations += e.evaluations;
    out->quadrature = true;
    LtcDiffuseFresnel(LobeAt(s, sigma), q, mu, out);
  }
  void CheckPoint(const BakeSettings &, double mu, double sigma) const override {
    if (!(mu >= 0.0 && mu <= 1.0) || !(sigma >= 0.0 && sigma <= kMaxSigma))
      throw std::domain_error("(mu, sigma) = (" + FormatDouble(mu) + ", " + FormatDouble(sigma) +
                              ") is outside [0, 1] x [0, pi/2]");
  }
  std::string LobeErrorRule() const override {
    return "light-direction rule, within 4e-4 of its next level (measured at 64 x 64, worst at "
           "grazing views)";
  }

  HeaderText Header(const Table &) const override {
    HeaderText text;
    text.notes.push_back("Oren-Nayar diffuse, " + ModelName() + ", reflectance 1.");
    text.notes.push_back(
        "sigma: the standard deviation of the facet slope angle, in radians, in [0, pi/2].");
    AddLtcNotes(&text, "oren_nayar_E");
    text.lookupComment =
        "{m00, m20, m02, m22, magnitude, fresnel} at view cosine mu and sigma (radians).";
    return text;
  }
};

}  // namespace

const TableDefinition &LtcOrenNayarTable() {
  static const LtcOrenNayar table;
  return table;
}

}  // namespace lutbake
