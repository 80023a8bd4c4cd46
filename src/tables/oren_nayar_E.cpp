// Tables oren_nayar_E and oren_nayar_full_E: the directional albedo of
// Oren-Nayar rough diffuse reflection (models/oren_nayar.h), reflectance 1,
// over the view cosine and the roughness sigma (the standard deviation of
// the facet slope angle, in radians):
//   E(mu_o, sigma) = integral over the hemisphere of f(o, i) mu_i d omega_i,
// oren_nayar_E for the qualitative "A + B" form engines use, oren_nayar_full_E
// for the paper's full model (C1, C2, C3 and the interreflection term).
// Axes: x = mu_o in [0, 1], y = sigma in [0, pi/2], 32 x 32.
//
// Neither model conserves energy: E falls below 1 as sigma grows (0.56 for
// the qualitative form at sigma = pi/2, normal view) and exceeds 1 at
// grazing views for small sigma (the B term's tan(b)); lutbake furnace
// shows both. An engine uses the table to normalise the lobe at the view,
// f / E(NdotV, sigma), which makes its directional albedo 1 (the header's
// helper), or to weigh a diffuse base in a layered material.
//
// Integrators: the furnace's (integrators/furnace.h: the azimuth in closed
// form, adaptive Gauss-Kronrod over theta_i split at theta_o) by default;
// the reference `check` uses is independent of that closed form: nested
// adaptive Gauss-Kronrod over (theta_i, dphi) of the BRDF itself, split at
// theta_i = theta_o and dphi = pi/2 (where max(0, cos dphi) and |cos dphi|
// kink). Exact limit: sigma = 0 is Lambert, E = 1 (check's limit claim).
#include <array>
#include <cmath>
#include <stdexcept>

#include "lutbake/integrators/furnace.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/models/oren_nayar.h"
#include "lutbake/tables/bake.h"
#include "oren_nayar_model.h"

namespace lutbake {

namespace {

class OrenNayarAlbedo final : public OrenNayarModelTable {
 public:
  OrenNayarAlbedo(const char *name, uint64_t seedId, OrenNayarVariant variant)
      : OrenNayarModelTable(variant), name_(name), seedId_(seedId) {}
  const char *Name() const override { return name_; }
  uint64_t SeedId() const override { return seedId_; }
  std::string Summary() const override {
    return variant_ == OrenNayarVariant::kQualitative
               ? "directional albedo of qualitative (A + B) Oren-Nayar diffuse, over (mu, sigma)"
               : "directional albedo of the full Oren-Nayar model (C1, C2, C3, interreflection), "
                 "over (mu, sigma)";
  }
  // Deterministic only: the furnace's rule, or the reference below.
  bool Sampled() const override { return false; }
  uint64_t SamplesPerTexel(const BakeSettings &) const override { return 0; }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "quadrature (adaptive Gauss-Kronrod over theta_i, the azimuth in closed form)";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "16 x the Gauss-Kronrod estimate + 1e-13";
  }
  PointValue Evaluate(const BakeSettings &s, double mu, double sigma) const override {
    if (!(mu >= 0.0 && mu <= 1.0))
      throw std::domain_error("mu " + FormatDouble(mu) + " is outside [0, 1]");
    if (!(sigma >= 0.0 && sigma <= kMaxSigma))
      throw std::domain_error("sigma " + FormatDouble(sigma) + " is outside [0, pi/2]");
    PointValue out;
    if (s.estimator == Estimator::kAdaptiveQuadrature) {
      const QuadratureResultN<2> r = Reference(mu, sigma);
      out.value[0] = r.value[0];
      out.error[0] = kQuadratureErrorFactor * (r.error[0] + r.value[1]) + 1e-13;
      return out;
    }
    FurnaceModel model;
    model.kind = FurnaceModelKind::kOrenNayar;
    model.orenNayar = variant_;
    const FurnacePoint p = FurnaceIntegrator(model, sigma).Albedo(mu);
    out.value[0] = p.albedo.value;
    out.error[0] = p.albedo.error;
    return out;
  }
  ValueClaim Range(const BakeSettings &) const override {
    return {0.0, HUGE_VAL, false, ">= 0 (above 1 at grazing views: the model gains energy there)"};
  }
  std::vector<LimitClaim> Limits(const BakeSettings &) const override {
    LimitClaim c;
    c.subject = std::string(Name()) + " as sigma -> 0";
    c.formula = "1 (Lambert)";
    c.axis = 1;
    // At sigma = 1e-4 the model departs from Lambert by terms in sigma^2 =
    // 1e-8, times tan(theta_o) <= 64 at the first texel centre mu = 1/64.
    c.near = 1e-4;
    c.slack = 1e-5;
    c.slackText = "1e-5 (terms in sigma^2, times tan(theta_o) at grazing)";
    c.value = [](double, double) { return 1.0; };
    return {c};
  }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    text.notes.push_back("Oren-Nayar diffuse, " + ModelName() + ", reflectance 1.");
    text.notes.push_back(
        "sigma: the standard deviation of the facet slope angle, in radians, in [0, pi/2].");
    text.lookupComment = "Directional albedo at view cosine mu and roughness sigma (radians).";
    const std::string name = table.Name();
    text.helpers = [name](const std::string &lookup) {
      return "// The lobe normalised at the view: f / E(NdotV, sigma) has directional albedo\n"
             "// 1 (white furnace) at that view.\n"
             "inline float normalisation_" +
             name + "(float NdotV, float sigma) {\n  const float e = " + lookup +
             "(NdotV, sigma);\n  return e > 0.0f ? 1.0f / e : 1.0f;\n}\n\n";
    };
    return text;
  }

 private:
  // The reference: integral over theta_i in [0, pi/2] and dphi in [0, pi]
  // (f is even in dphi) of 2 f mu_i sin(theta_i), the inner estimate
  // carried as the outer's second channel.
  QuadratureResultN<2> Reference(double mu, double sigma) const {
    const double s_o = std::sqrt((1.0 - mu) * (1.0 + mu));
    const Vec3 o{s_o, 0.0, mu};
    const double theta_o = std::acos(mu);
    std::vector<double> outerBreaks = {0.0, kMaxSigma};
    if (theta_o > 0.0 && theta_o < kMaxSigma) outerBreaks = {0.0, theta_o, kMaxSigma};
    return IntegrateAdaptiveN<2>(
        [&](double theta_i) {
          const double st = std::sin(theta_i), ct = std::cos(theta_i);
          const QuadratureResultN<1> inner = IntegrateAdaptiveN<1>(
              [&](double dphi) {
                const Vec3 i{st * std::cos(dphi), st * std::sin(dphi), ct};
                return std::array<double, 1>{OrenNayarBrdf(variant_, sigma, o, i)};
              },
              {0.0, 0.5 * kPi, kPi}, 1e-13);
          const double w = 2.0 * ct * st;
          return std::array<double, 2>{w * inner.value[0], w * inner.error[0]};
        },
        outerBreaks, 1e-12);
  }

  const char *name_;
  uint64_t seedId_;
};

}  // namespace

const TableDefinition &OrenNayarAlbedoTable() {
  static const OrenNayarAlbedo table("oren_nayar_E", 10, OrenNayarVariant::kQualitative);
  return table;
}

const TableDefinition &OrenNayarFullAlbedoTable() {
  static const OrenNayarAlbedo table("oren_nayar_full_E", 11, OrenNayarVariant::kFull);
  return table;
}

}  // namespace lutbake
