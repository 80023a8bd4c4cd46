// Table burley_E: the directional albedo of Burley's diffuse BRDF (Disney
// 2012, "Physically-Based Shading at Disney", base colour 1):
//   f_d(v, l) = (1/pi) F(mu_l) F(mu_v),  F(u) = 1 + (F_D90 - 1) (1 - u)^5,
//   F_D90 = 0.5 + 2 r cos^2(theta_d),  cos(theta_d) = l.h,
// h the half vector of v and l, r the perceptual roughness (no NDF, no
// alpha: r enters F_D90 alone), and
//   burley_E(mu, r) = integral over the upper hemisphere of f_d(v, l) mu_l d omega_l,
// mu = mu_v. Axes: x = mu in [0, 1], y = r in [0, 1], 32 x 32.
//
// The closed form. 2 cos^2(theta_d) = 1 + v.l, so g = F_D90 - 1 = r - 1/2 +
// r (v.l) and F(mu_l) F(mu_v) = 1 + g (a + b) + g^2 a b, a = (1 - mu_l)^5,
// b = (1 - mu)^5: a quadratic in v.l = mu mu_l + s s_l cos(phi), whose
// azimuthal averages are <v.l> = mu mu_l and <(v.l)^2> = mu^2 mu_l^2 +
// (1 - mu^2)(1 - mu_l^2) / 2. What is left is 2 int_0^1 mu_l (...) dmu_l
// of a polynomial of degree 8 in mu_l, with the moments int_0^1 x^n (1 -
// x)^5 dx = n! 5! / (n + 6)! (1/42, 1/168, 1/504 for n = 1, 2, 3):
//   burley_E = (492 + 6 r (4 + mu)
//               + (1 - mu)^5 (-246 + 6 r (80 + 55 mu) + r^2 (35 + 12 mu - 9 mu^2))) / 504.
// Checks: mu = 1 gives 41/42 + 5 r / 84, 29/28 = 1.0357142857 at r = 1 (the
// 1.03571 by which Unity HDRP's DisneyDiffuseNoPI divides); r = 0, where the
// BRDF separates, gives (41/42)(1 - (1 - mu)^5 / 2); the lowest value is
// 41/84 (mu = 0, r = 0) and the highest 785/504 = 1.5575 (mu = 0, r = 1):
// dE/dr > 0 everywhere (35 + 12 mu - 9 mu^2 > 0), and at r = 1, 6 mu + (1 -
// mu)^5 (269 + 342 mu - 9 mu^2) <= 6 mu + 269 e^(-3.728 mu) <= 269 on [0, 1]
// (convex, equal to 269 at mu = 0). E exceeds 1 at grazing views of rough
// surfaces: Burley's diffuse is not energy conserving.
//
// Integrators: the closed form (the default; exact up to rounding: as
// written below, every monomial of E meets at most 13 roundings of relative
// size 2^-53 (4 in (1 - mu)^5, 6 in the bracket, the product, two sums and
// the division), and the monomials' absolute values sum to at most 1634 /
// 504 < 3.25, so the double is within 13 x 2^-53 x 3.25 < 4.7e-15 of E; the
// bound stated is 1e-14, to which a file adds the rounding of its storage),
// and, for `check` and
// --estimator adaptive, an independent reference: nested adaptive
// Gauss-Kronrod over (theta_l, phi) of the BRDF itself, with cos(theta_d)
// from the normalised half vector (not the identity above).
//
// Uses: Unity HDRP's diffuse FGD (preset unity-hdrp's channel
// "disney_diffuse" is burley_E / 1.03571, read from this table). No bake
// plan needs it: plans' materials (glTF, manifests) have no Burley diffuse.
#include <array>
#include <cmath>
#include <stdexcept>

#include "burley_model.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/models/burley.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

// The closed form above, and the bound of its double evaluation.
constexpr double kClosedFormRounding = 1e-14;
double BurleyAlbedoClosedForm(double mu, double r) {
  const double t = 1.0 - mu, t2 = t * t;
  const double b = t2 * t2 * t;  // (1 - mu)^5
  const double view = 6.0 * r * (4.0 + mu);
  const double lobe =
      -246.0 + 6.0 * r * (80.0 + 55.0 * mu) + r * r * (35.0 + 12.0 * mu - 9.0 * mu * mu);
  return (492.0 + view + b * lobe) / 504.0;
}

class BurleyAlbedo final : public BurleyModelTable {
 public:
  const char *Name() const override { return "burley_E"; }
  uint64_t SeedId() const override { return 12; }
  std::string Summary() const override {
    return "directional albedo of Burley's (Disney 2012) diffuse, base colour 1, over (mu, r); "
           "closed form";
  }
  // Deterministic only: the closed form, or the reference below.
  bool Sampled() const override { return false; }
  uint64_t SamplesPerTexel(const BakeSettings &) const override { return 0; }
  std::string QuadratureDescription(const BakeSettings &s) const override {
    return s.estimator == Estimator::kAdaptiveQuadrature
               ? "adaptive Gauss-Kronrod over (theta_l, phi) of the BRDF"
               : "closed form: (492 + 6 r (4 + mu) + (1 - mu)^5 (-246 + 6 r (80 + 55 mu) + r^2 "
                 "(35 + 12 mu - 9 mu^2))) / 504";
  }
  std::string QuadratureBound(const BakeSettings &s) const override {
    return s.estimator == Estimator::kAdaptiveQuadrature
               ? "16 x the Gauss-Kronrod estimate + 1e-13"
               : "1e-14: the rounding of the closed form in double (< 4.7e-15)";
  }
  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    if (!(mu >= 0.0 && mu <= 1.0))
      throw std::domain_error("mu " + FormatDouble(mu) + " is outside [0, 1]");
    if (!(r >= 0.0 && r <= 1.0))
      throw std::domain_error("roughness " + FormatDouble(r) + " is outside [0, 1]");
    PointValue out;
    out.quadrature = true;
    if (s.estimator == Estimator::kAdaptiveQuadrature) {
      const QuadratureResultN<2> q = Reference(mu, r);
      out.value[0] = q.value[0];
      out.error[0] = kQuadratureErrorFactor * (q.error[0] + q.value[1]) + 1e-13;
      out.evaluations = static_cast<uint64_t>(q.evaluations);
      return out;
    }
    out.value[0] = BurleyAlbedoClosedForm(mu, r);
    out.error[0] = kClosedFormRounding;
    out.exact = true;
    return out;
  }

  // The extremes 41/84 and 785/504 are not representable: a stored value
  // may round across them (half at --size 4096 stores 1.5576 for 1.55716),
  // so the claim is widened to the next round numbers outside both.
  ValueClaim Range(const BakeSettings &) const override {
    return {0.488, 1.558, false,
            "in [0.488, 1.558] (the integral's extremes, 41/84 and 785/504, widened by storage "
            "rounding; above 1 at grazing views of rough surfaces: Burley's diffuse gains energy "
            "there)"};
  }
  std::optional<MonotonicClaim> Monotonic(const BakeSettings &) const override {
    MonotonicClaim claim;
    claim.skipped =
        "burley_E rises with mu at small r and falls with it at large r (785/504 at mu = 0 to "
        "29/28 at mu = 1 for r = 1), so nothing is claimed along mu";
    return claim;
  }
  std::optional<ClosedForm> Closed(const BakeSettings &) const override {
    return ClosedForm{"Burley diffuse albedo",
                      "(492 + 6 r (4 + mu) + (1 - mu)^5 (-246 + 6 r (80 + 55 mu) + r^2 (35 + 12 "
                      "mu - 9 mu^2))) / 504",
                      BurleyAlbedoClosedForm};
  }

  HeaderText Header(const Table &table) const override {
    HeaderText text;
    text.notes.push_back(
        "Burley (Disney 2012) diffuse, base colour 1: f = F(NdotL) F(NdotV) / pi, F(u) = 1 +");
    text.notes.push_back(
        "(F_D90 - 1) (1 - u)^5, F_D90 = 0.5 + 2 r LdotH^2, r = perceptual roughness.");
    text.notes.push_back("E exceeds 1 at grazing views and large r (785/504 at NdotV = 0, r = 1).");
    text.lookupComment = "Directional albedo E at view cosine mu and perceptual roughness r.";
    const std::string name = table.Name();
    text.helpers = [name](const std::string &lookup) {
      return "// Unity HDRP's diffuse FGD: its DisneyDiffuseNoPI divides the BRDF by 1.03571\n"
             "// (the albedo at NdotV = 1, r = 1), so its albedo is E / 1.03571 (HDRP stores\n"
             "// that minus 0.5).\n"
             "inline float hdrp_diffuse_fgd_" +
             name + "(float NdotV, float r) {\n  return " + lookup +
             "(NdotV, r) / 1.03571f;\n}\n\n"
             "// The lobe normalised at the view: f / E(NdotV, r) has directional albedo 1\n"
             "// (white furnace) at that view.\n"
             "inline float normalisation_" +
             name + "(float NdotV, float r) {\n  return 1.0f / " + lookup + "(NdotV, r);\n}\n\n";
    };
    return text;
  }

 private:
  // The reference: integral over theta_l in [0, pi/2] and phi in [0, pi] (f
  // is even in phi) of 2 f mu_l sin(theta_l), the inner estimate carried as
  // the outer's second channel. The integrand is smooth: no breaks.
  static QuadratureResultN<2> Reference(double mu, double r) {
    const Vec3 v = ViewDirection(mu);
    return IntegrateAdaptiveN<2>(
        [&](double theta) {
          const double st = std::sin(theta), ct = std::cos(theta);
          const QuadratureResultN<1> inner = IntegrateAdaptiveN<1>(
              [&](double phi) {
                const Vec3 l{st * std::cos(phi), st * std::sin(phi), ct};
                return std::array<double, 1>{BurleyDiffuseBrdf(r, v, l)};
              },
              {0.0, kPi}, 1e-14);
          const double w = 2.0 * ct * st;
          return std::array<double, 2>{w * inner.value[0], w * inner.error[0]};
        },
        {0.0, 0.5 * kPi}, 1e-13);
  }
};

}  // namespace

const TableDefinition &BurleyAlbedoTable() {
  static const BurleyAlbedo table;
  return table;
}

}  // namespace lutbake
