#include "dielectric_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lutbake/integrators/dielectric_estimator.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/models/ndf.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/set_claim.h"
#include "microfacet_table.h"
#include "sampled_texel.h"

namespace lutbake {

namespace {

// The relative IORs of water, glass and diamond, and their inverses: nodes
// of every default eta axis.
constexpr double kMaterialEtas[] = {1.33, 1.5, 2.42};

}  // namespace

namespace {

class Dielectric final : public TableModel {
 public:
  explicit Dielectric(DielectricLobes lobes) : lobes_(lobes) {}
  std::vector<std::string> Options() const override { return MicrofacetModel().Options(); }
  Metadata Records(const BakeSettings &s) const override {
    const bool transmission = lobes_ == DielectricLobes::kReflectionAndTransmission;
    Metadata m = MicrofacetModel().Records(s);
    m.back().second = "dielectric (exact, unpolarised, at o.h)";  // fresnel
    m.emplace_back("lobes", std::string(ToString(lobes_)));
    m.emplace_back("transmission", transmission
                                       ? "the fraction of the energy arriving along o that "
                                         "passes: without the eta^2 radiance factor"
                                       : "none");
    return m;
  }
  std::string Alpha(const BakeSettings &s) const override { return MicrofacetModel().Alpha(s); }
  std::string Describe(const BakeSettings &s) const override {
    return MicrofacetModel().Describe(s) + ", " + std::string(ToString(lobes_));
  }
  void Read(const Table &table, BakeSettings *s,
            std::vector<std::string> *problems) const override {
    MicrofacetModel().Read(table, s, problems);
    if (RequiredMetadata(table, "lobes", problems) != ToString(lobes_))
      problems->push_back("lobes is not '" + std::string(ToString(lobes_)) + "'");
  }
  bool Same(const BakeSettings &a, const BakeSettings &b) const override {
    return MicrofacetModel().Same(a, b);
  }

 private:
  DielectricLobes lobes_;
};

}  // namespace

const TableModel &DielectricModel(DielectricLobes lobes) {
  static const Dielectric reflection(DielectricLobes::kReflection),
      both(DielectricLobes::kReflectionAndTransmission);
  return lobes == DielectricLobes::kReflection ? reflection : both;
}

bool DielectricTable::ReadModel(const Table &table, BakeSettings *s,
                                std::vector<std::string> *problems) const {
  const size_t before = problems->size();
  ModelPart().Read(table, s, problems);
  // 3D: (mu, r, eta); the averages: (r, eta).
  const bool threeD = PlannedRoughnessAxis() == 1;
  const Axis &r = threeD ? table.y : table.x;
  const Axis &eta = threeD ? table.z : table.y;
  if (r.name != "perceptualRoughness" || r.min < 0.0 || r.max > 1.0)
    problems->push_back("the roughness axis is not perceptualRoughness within [0, 1]");
  if (eta.name != "eta" || !(eta.min > 0.0))
    problems->push_back("the " + std::string(threeD ? "z" : "y") + " axis is not eta > 0");
  if (threeD && (table.x.name != "mu" || table.x.min < 0.0 || table.x.max > 1.0))
    problems->push_back("axis x is not mu within [0, 1]");
  if (threeD && !table.is3D()) problems->push_back(table.Name() + " is not 3D");
  if (!threeD && (table.is3D() || !table.is2D())) problems->push_back(table.Name() + " is not 2D");
  return problems->size() == before;
}

std::string DielectricTable::QuadratureDescription(const BakeSettings &s) const {
  return s.estimator == Estimator::kAdaptiveQuadrature
             ? "adaptive Gauss-Kronrod quadrature over the light direction"
             : "panel Gauss-Legendre quadrature over the half vector, panels at the kinks of "
               "the facet weight, two orders";
}

std::string DielectricTable::QuadratureBound(const BakeSettings &s) const {
  if (s.estimator == Estimator::kAdaptiveQuadrature)
    return "16 x the Gauss-Kronrod estimates of both levels";
  return "quadrature texels: twice the panel rule's difference between two orders plus its "
         "floor (dielectric_quadrature.h)";
}

std::string DielectricTable::EstimatorProblem(Estimator e) const {
  if (e == Estimator::kCosine || e == Estimator::kUniform || e == Estimator::kNdf)
    return std::string(Name()) +
           " samples visible normals only (its weight is then at most 1); accepted: "
           "quadrature, adaptive, vndf, vndf-random";
  return "";
}

// check's reference. The adaptive Gauss-Kronrod rule over the light
// direction (IntegrateDielectricAlbedoAdaptive) costs 20 to 80 times the
// bake's panel rule a texel (7.4 ms against 0.35 ms for glass_E at 1e-8; a
// default glass_E + spec_E check took 482 CPU-s, 97% of it there, against
// 12 CPU-s for their bake), and its 16x bound let glass_E's texels pass at
// 6.8e-8 from it, twice their errorMax. The panel rule at tolerance tau
// bounds its own error by tau max(1, value) where it converges (its bound is
// an estimate, validated against the adaptive rule and an independent
// numpy rule: dielectric_quadrature.h, GlassTables tests); check adds that
// bound to each texel's allowance, so a pass shows every stored value within
// its own bound + twice the reference's: at 1/16 of the stated errorMax
// (2.3e-9 for a default bake, which asks 1e-8: other numbers than the
// bake's), within its bound + 1/8 of errorMax; and a texel moved by 3x its
// bound fails (GlassTables tests). Cost
// on 1024 texels of each 3D table (one thread, the loaded build machine):
// 1.05 to 1.12x the bake's rule from 2.3e-9 down to 4e-10; the averages 1.6
// to 1.75x at 2e-9 (2.6x at 1e-9, 7x at 6e-10: why 1/16 and not 1/64).
// Below 4e-10 the albedo stops converging (its bound has a floor of 1e-10
// + 0.2 tau): at 3e-10 6 texels of 1024 did not, at 2e-10 217, at twice the
// cost. What stays independent of the rule: the closed forms at eta = 1 and
// r -> 0, reciprocity, the averages against the 3D tables' rows, 64 texels
// of each 3D table that check also holds to the adaptive rule
// (CheckIndependent: 1 CPU-s for glass_E and spec_E together; within 0.05
// of eta = 1 that rule falls back to the panel one), and the adaptive
// reference in report and the tests. The random points judge
// nothing (check.cpp): their truth is the rule at the bake's default
// tolerance, 1e-8 (3 digits of any deviation above 1e-5).
namespace {
constexpr double kPanelReferenceFloor = 4e-10;
}  // namespace

TableDefinition::CheckReference DielectricTable::ReferenceForCheck(double statedErrorMax,
                                                                   double optionTolerance) const {
  CheckReference r;
  r.estimator = Estimator::kQuadrature;
  r.tolerance =
      std::clamp(statedErrorMax / 16.0, std::min(optionTolerance, kPanelReferenceFloor), 1e-6);
  r.pointTolerance = kDefaultQuadratureTolerance;
  return r;
}

Axis DielectricTable::EtaAxis(int size, bool withMaterials) {
  std::vector<double> nodes;
  const int n = std::max(size, 1);
  for (int i = 0; i < n; ++i) {
    // s in [-1/2, 1/2]; a single slice at s = 0 (eta = 1).
    const double s = n == 1 ? 0.0 : -0.5 + static_cast<double>(i) / (n - 1);
    nodes.push_back((1.0 + s) / (1.0 - s));
  }
  if (withMaterials) {
    nodes.push_back(1.0);
    for (double eta : kMaterialEtas) {
      nodes.push_back(eta);
      nodes.push_back(1.0 / eta);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  // Values closer than 1e-9 relative are one node (eta = 1 from an odd n).
  std::vector<double> unique;
  for (double v : nodes)
    if (unique.empty() || v > unique.back() * (1.0 + 1e-9)) unique.push_back(v);
  return ListedAxis("eta", std::move(unique));
}

PointCoordinate DielectricTable::RoughnessCoordinate() {
  PointCoordinate c;
  c.option = "roughness";
  c.min = 0.0;
  c.max = 1.0;
  c.accepted = "comma-separated numbers in [0, 1] (0: the smooth interface, exact)";
  return c;
}

PointCoordinate DielectricTable::MuCoordinate() {
  PointCoordinate c;
  c.option = "mu";
  c.accepted = "comma-separated numbers in [0, 1]";
  return c;
}

PointCoordinate DielectricTable::EtaCoordinate() {
  PointCoordinate c;
  c.option = "eta";
  c.min = kMinRelativeIor;
  c.max = kMaxRelativeIor;
  c.accepted =
      "comma-separated relative IORs from 1/128 to 128 (eta < 1: leaving the denser "
      "medium)";
  return c;
}

double DielectricTable::AlphaOf(double r) {
  if (!(r >= 0.0 && r <= 1.0))
    throw std::domain_error("roughness " + FormatDouble(r) + " is outside [0, 1]");
  return r * r;
}

void DielectricTable::CheckEta(double eta) {
  if (!(eta >= kMinRelativeIor && eta <= kMaxRelativeIor))
    throw std::domain_error("eta " + FormatDouble(eta) + " is outside [1/128, 128]");
}

PointValue DielectricTable::FromIntegral(const DielectricIntegral &q) {
  PointValue out;
  out.value[0] = q.value;
  out.error[0] = q.bound;
  out.evaluations = q.evaluations;
  out.quadrature = true;
  out.exact = q.exact;
  return out;
}

PointValue DielectricTable::EvaluateAlbedo(const BakeSettings &s, double mu, double r,
                                           double eta) const {
  const double alpha = AlphaOf(r);
  CheckEta(eta);
  if (!(mu >= 0.0 && mu <= 1.0))
    throw std::domain_error("mu " + FormatDouble(mu) + " is outside [0, 1]");
  const DielectricLobes lobes = Lobes();
  // Grazing and index-matched: the closed form's limit (the integrators see
  // i_t = -o on the horizon, where G2 is 0; dielectric_quadrature.cpp).
  if (mu == 0.0 && eta == 1.0 && alpha > 0.0)
    return FromIntegral(IntegrateDielectricAlbedo(s.ndf, s.smith, lobes, alpha, mu, eta, 1e-8));
  // The adaptive rule integrates over the light direction, where the
  // transmitted lobe narrows to a delta at -o as eta -> 1: it cannot find it
  // there. Within 0.05 of eta = 1 the panel rule (over the half vector, where
  // nothing narrows; validated against the closed form at eta = 1 and for
  // continuity, dielectric_quadrature.h) answers for it.
  if (s.estimator == Estimator::kAdaptiveQuadrature && alpha > 0.0 && mu > 0.0 &&
      std::abs(eta - 1.0) >= 0.05)
    return FromIntegral(IntegrateDielectricAlbedoAdaptive(s.ndf, s.smith, lobes, alpha, mu, eta,
                                                          AdaptiveTolerance(s)));
  if (IsQuadrature(s.estimator) || alpha == 0.0)
    return FromIntegral(
        IntegrateDielectricAlbedo(s.ndf, s.smith, lobes, alpha, mu, eta, PanelTolerance(s)));
  const DielectricAlbedoEstimator estimator(s.ndf, s.smith, lobes, alpha, mu, eta);
  const uint64_t seed = SampleSeed(
      SeedId(), s, PointSeed(SeedId(), mu, alpha, PointSeed(SeedId(), eta, 0.0, s.seed)));
  PointValue out;
  const bool sampled = SampleTexel<2, 1>(
      s,
      [&](const PointView &p, double *w[]) {
        for (size_t k = 0; k < p.n; ++k) w[0][k] = estimator.Weight(p.u[0][k], p.u[1][k]);
      },
      s.samples, seed, &out, estimator.MaxWeight());
  if (sampled) return out;
  PointValue q = FromIntegral(
      IntegrateDielectricAlbedo(s.ndf, s.smith, lobes, alpha, mu, eta, PanelTolerance(s)));
  q.samples = out.samples;  // the rounds spent before switching still count
  return q;
}

PointValue DielectricTable::EvaluateAverage(const BakeSettings &s, double r, double eta) const {
  const double alpha = AlphaOf(r);
  CheckEta(eta);
  const DielectricLobes lobes = Lobes();
  if (IsQuadrature(s.estimator) || alpha == 0.0)
    return FromIntegral(
        IntegrateDielectricAverage(s.ndf, s.smith, lobes, alpha, eta, PanelTolerance(s)));
  const DielectricAverageEstimator estimator(s.ndf, s.smith, lobes, alpha, eta);
  const uint64_t seed = SampleSeed(SeedId(), s, PointSeed(SeedId(), alpha, eta, s.seed));
  PointValue out;
  const bool sampled = SampleTexel<3, 1>(
      s,
      [&](const PointView &p, double *w[]) {
        for (size_t k = 0; k < p.n; ++k)
          w[0][k] = estimator.Weight(p.u[0][k], p.u[1][k], p.u[2][k]);
      },
      SamplesPerTexel(s), seed, &out, estimator.MaxWeight());
  if (sampled) return out;
  PointValue q = FromIntegral(
      IntegrateDielectricAverage(s.ndf, s.smith, lobes, alpha, eta, PanelTolerance(s)));
  q.samples = out.samples;
  return q;
}

void DielectricTable::AddNotes(HeaderText *text) const {
  text->notes.push_back("Roughness is perceptual roughness r; the NDF width is alpha = r^2.");
  text->notes.push_back(
      "eta = (IOR on the far side) / (IOR on the side of the view): eta > 1 entering the "
      "denser medium, eta < 1 leaving it (total internal reflection included).");
  text->notes.push_back(
      "Fresnel: the exact unpolarised dielectric reflectance at the microfacet, F(o.h).");
  if (Lobes() == DielectricLobes::kReflectionAndTransmission)
    text->notes.push_back(
        "Transmission counts energy: without the eta^2 radiance factor, so a smooth interface "
        "gives exactly 1.");
  text->constants.push_back("inline constexpr bool kAlphaIsPerceptualRoughnessSquared = true;");
}

void DielectricAlbedoTable::Axes(const BakeSettings &, int size, Axis *x, Axis *y) const {
  *x = MuAxis(size);
  *y = RoughnessAxis(size);
}

std::vector<PointCoordinate> DielectricAlbedoTable::Coordinates(const BakeSettings &) const {
  return {MuCoordinate(), RoughnessCoordinate(), EtaCoordinate()};
}

void DielectricAverageTable::Axes(const BakeSettings &s, int size, Axis *x, Axis *y) const {
  *x = RoughnessAxis(size);
  *y = EtaAxis(s.depthSize > 0 ? s.depthSize : kDefaultEtaSize, s.depthSize == 0);
}

std::vector<PointCoordinate> DielectricAverageTable::Coordinates(const BakeSettings &) const {
  return {RoughnessCoordinate(), EtaCoordinate()};
}

uint64_t DielectricAverageTable::SamplesPerTexel(const BakeSettings &s) const {
  return IsQuadrature(s.estimator) ? 0 : s.samples * kAverageSampleFactor;
}

TableRelations DielectricAverageTable::Relations() const {
  TableRelations r;
  r.averageOf = identity_.averageOf;
  return r;
}

namespace {

// The transmitted part T = this - minus (glass_Eavg - spec_Eavg) obeys
// T(eta) = eta^2 T(1 / eta) over the eta axis (reciprocity of the BTDF,
// docs/tables.md "Rough glass"), at every pair of slices eta, 1 / eta that
// both tables hold, within the four texels' bounds. glass_Eavg's slices at
// eta < 1 are baked from this identity (IntegrateDielectricAverage), so for
// a set baked together it shows that the files agree as stored; what holds
// glass_Eavg to an independent integral is the average of glass_E's rows
// (AverageOfClaim) and the tests.
class Reciprocity final : public SetClaim {
 public:
  explicit Reciprocity(std::string minus) : minus_(std::move(minus)) {}
  int Order() const override { return 5; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    using namespace claim_text;
    const CheckedTable &g = self;

    const std::string &minusName = minus_;
    const CheckedTable *sp = set.Usable(minusName);
    if (!sp || !g.usable) return;
    const std::string subject = std::string(g.def->Name()) + "-" + minusName + set.Suffix();
    if (!set.SameModel(g, *sp, subject, "reciprocity")) return;
    const Table &tg = g.table, &ts = sp->table;
    if (!(tg.x.count == ts.x.count && tg.x.min == ts.x.min && tg.x.max == ts.x.max &&
          tg.x.name == ts.x.name && tg.x.nodes == ts.x.nodes && tg.y.nodes == ts.y.nodes &&
          tg.y.count == ts.y.count && tg.y.min == ts.y.min && tg.y.max == ts.y.max)) {
      set.Add(subject, "reciprocity", ClaimStatus::kSkipped,
              "the two tables do not share their axes: nothing to compare texel by texel");
      return;
    }
    const auto rounding = [&](const CheckedTable &t, double v) {
      return t.boundsCoverStorage ? 0.0 : FloatRounding(v);
    };
    Worst worst;
    int pairs = 0;
    for (int j = 0; j < tg.height(); ++j) {
      const double eta = tg.y.TexelCenter(j);
      if (!(eta > 1.0)) continue;
      int partner = -1;
      for (int k = 0; k < tg.height(); ++k)
        if (std::abs(eta * tg.y.TexelCenter(k) - 1.0) < 1e-12) partner = k;
      if (partner < 0) continue;
      for (int x = 0; x < tg.width(); ++x) {
        const size_t a = tg.index(x, j, 0), b = tg.index(x, partner, 0);
        const double gA = tg.values[a], sA = ts.values[a], gB = tg.values[b], sB = ts.values[b];
        const double dev = std::abs((gA - sA) - eta * eta * (gB - sB));
        const double allowed =
            std::max(g.statedErrorMax, g.Bound(a)) + std::max(sp->statedErrorMax, sp->Bound(a)) +
            rounding(g, gA) + rounding(*sp, sA) +
            eta * eta *
                (std::max(g.statedErrorMax, g.Bound(b)) +
                 std::max(sp->statedErrorMax, sp->Bound(b)) + rounding(g, gB) + rounding(*sp, sB));
        ++pairs;
        worst.Note(dev, allowed, At(tg, tg.x.TexelCenter(x), eta));
      }
    }
    const std::string claim =
        "T = " + std::string(g.def->Name()) + " - " + minusName + " obeys T(eta) = eta^2 T(1/eta)";
    if (pairs == 0)
      set.Add(subject, "reciprocity", ClaimStatus::kSkipped,
              claim + ": the eta axis holds no pair eta, 1/eta");
    else if (worst.failed())
      set.Add(subject, "reciprocity", ClaimStatus::kFail,
              claim + ", but it is off by " + Short(worst.excessDeviation) + " at " +
                  Where(worst.atExcess) + ", more than the " + Short(worst.excessAllowed) +
                  " the four texels' bounds allow",
              worst.excessDeviation, worst.excessAllowed, worst.atExcess);
    else
      set.Add(subject, "reciprocity", ClaimStatus::kPass,
              claim + " at " + std::to_string(pairs) +
                  " texel pairs, within the four texels' bounds: max |T(eta) - eta^2 T(1/eta)| " +
                  Short(worst.deviation) + " at " + Where(worst.at),
              worst.deviation, 0.0, worst.at);
  }

 private:
  std::string minus_;
};

}  // namespace

std::vector<std::shared_ptr<const SetClaim>> DielectricAverageTable::Claims() const {
  std::vector<std::shared_ptr<const SetClaim>> claims{AverageOfClaim(identity_.averageOf)};
  if (*identity_.reciprocalMinus)
    claims.push_back(std::make_shared<Reciprocity>(identity_.reciprocalMinus));
  return claims;
}

double DielectricTable::IndexMatchedAlbedo(const BakeSettings &s, double mu, double r) const {
  if (Lobes() == DielectricLobes::kReflection) return 0.0;
  // G2(o, -o) / G1(o) with L = mu Lambda(mu): correlated (mu + L) / (mu + 2 L),
  // separable G1 = mu / (mu + L); 1 at r = 0 and at normal view.
  const double L = Ndf{s.ndf, AlphaOf(r)}.MuLambda(mu);
  if (mu == 0.0) return s.smith == SmithForm::kCorrelated ? 0.5 : 0.0;
  return s.smith == SmithForm::kCorrelated ? (mu + L) / (mu + 2.0 * L) : mu / (mu + L);
}

double DielectricTable::IndexMatchedAverage(const BakeSettings &s, double r) const {
  if (Lobes() == DielectricLobes::kReflection) return 0.0;
  // Breaks graded toward mu = 0, where Lambda varies on the scale alpha.
  std::vector<double> breaks = {0.0};
  for (double m = std::max(AlphaOf(r), 1e-6); m < 1.0; m *= 4.0) breaks.push_back(m);
  breaks.push_back(1.0);
  const QuadratureResultN<1> q = IntegrateAdaptiveN<1>(
      [&](double mu) { return std::array<double, 1>{2.0 * mu * IndexMatchedAlbedo(s, mu, r)}; },
      breaks, 1e-13);
  return q.value[0];
}

std::optional<SliceClosedForm> DielectricAlbedoTable::SliceClosed(const BakeSettings &s) const {
  SliceClosedForm f;
  f.subject = std::string(Name()) + " at eta = 1";
  f.axis = 2;
  f.at = 1.0;
  if (Lobes() == DielectricLobes::kReflection) {
    f.formula = "0 (F = 0 on every facet)";
  } else {
    f.formula =
        s.smith == SmithForm::kCorrelated
            ? "(1 + Lambda(mu)) / (1 + 2 Lambda(mu)) (every facet passes o straight through)"
            : "G1(mu) (every facet passes o straight through)";
  }
  f.value = [this, s](double mu, double r) { return IndexMatchedAlbedo(s, mu, r); };
  return f;
}

std::vector<LimitClaim> DielectricAlbedoTable::Limits(const BakeSettings &) const {
  LimitClaim c;
  c.subject = std::string(Name()) + " as r -> 0";
  c.formula = Lobes() == DielectricLobes::kReflection
                  ? "F(mu, eta), the smooth interface's reflectance"
                  : "1 (a smooth interface reflects F and transmits 1 - F)";
  c.axis = 1;
  // alpha = 1e-6: the facets tilt by ~1e-6, which moves the albedo by about
  // that much, except within ~sqrt(alpha) of the critical cosine, where the
  // smooth reflectance has a square-root branch point (left out).
  c.near = 1e-3;
  c.slack = 1e-6;
  c.slackText = "alpha = 1e-6, the facets' tilt";
  const DielectricLobes lobes = Lobes();
  c.value = [lobes](double mu, double eta) { return DielectricSmoothAlbedo(lobes, eta, mu); };
  c.excluded = [](double mu, double eta) {
    if (eta >= 1.0) return false;
    return std::abs(mu - std::sqrt((1.0 - eta) * (1.0 + eta))) < 1e-3;
  };
  return {c};
}

std::optional<SliceClosedForm> DielectricAverageTable::SliceClosed(const BakeSettings &s) const {
  SliceClosedForm f;
  f.subject = std::string(Name()) + " at eta = 1";
  f.axis = 1;
  f.at = 1.0;
  f.formula = Lobes() == DielectricLobes::kReflection
                  ? "0 (F = 0 on every facet)"
                  : "2 integral_0^1 G2(o, -o) / G1(o) mu dmu (every facet passes o straight "
                    "through)";
  f.value = [this, s](double r, double) { return IndexMatchedAverage(s, r); };
  return f;
}

HeaderText DielectricAverageTable::Header(const Table &table) const {
  HeaderText text;
  AddNotes(&text);
  text.lookupComment = identity_.lookupComment;
  const std::string name = table.Name();
  if (Lobes() == DielectricLobes::kReflection) {
    // A coat under uniform (cosine-weighted) light passes 1 - spec_Eavg of it
    // to the base: 2 integral (1 - spec_E) mu dmu.
    text.helpers = [name](const std::string &lookup) {
      return "// The fraction of uniform (cosine-weighted) light that a dielectric coat lets\n"
             "// through to the layer beneath: 1 - Eavg = 2 integral (1 - E(mu)) mu dmu.\n"
             "inline float diffuse_transmittance_" +
             name + "(float r, float eta) {\n  return 1.0f - " + lookup + "(r, eta);\n}\n\n";
    };
  } else {
    // The Kulla-Conty lobe built from glass_E and this average: its cosine
    // integral over a hemisphere of light directions is exactly 1 - E_o.
    text.helpers = [name](const std::string &lookup) {
      return "// The Kulla-Conty multiple-scattering lobe of rough glass, from E = glass_E at\n"
             "// the view (E_o) and the light (E_i) and this average:\n"
             "//   f_ms = (1 - E_o) (1 - E_i) / (pi (1 - Eavg)),\n"
             "// whose integral of f_ms |mu_i| over a hemisphere of i is exactly 1 - E_o, the\n"
             "// energy single scattering loses. How it is split between the reflected and the\n"
             "// transmitted hemisphere is the engine's choice. 0 where Eavg = 1 (nothing lost).\n"
             "inline float ms_lobe_" +
             name + "(float E_o, float E_i, float r, float eta) {\n  const float lost = 1.0f - " +
             lookup +
             "(r, eta);\n  return lost > 0.0f ? (1.0f - E_o) * (1.0f - E_i) / "
             "(3.14159265358979f * lost) : 0.0f;\n}\n\n";
    };
  }
  return text;
}

}  // namespace lutbake
