// Table Favg: the cosine-weighted average of a Fresnel reflectance,
//   F_avg = 2 integral_0^1 F(mu) mu dmu,
// the colour of Kulla and Conty's multiple-scattering lobe (F_ms =
// F_avg^2 E_avg / (1 - F_avg (1 - E_avg))). One table per Fresnel model:
//   schlick     x = F0 in [0, 1]; exactly 20/21 F0 + 1/21 (check asserts it)
//   dielectric  x = eta in [1, 3]
//   conductor   x = eta in [0, 4], y = k in [0, 10]
//   f82         x = F0 in [0, 1], y = F82 tint in [0, 1]; in closed form,
//               20/21 F0 + 1/21 - a / 126 (fresnel_average.h), per channel
// 32 texels per axis by default. Integrated by adaptive Gauss-Kronrod over
// mu (integrators/fresnel_average.h), never sampled; f82 is the closed form.
#include <cmath>

#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/tables/bake.h"
#include "microfacet_table.h"

namespace lutbake {

PointValue EvaluateFresnelAverage(FresnelModel model, double x, double y) {
  FresnelAverageResult r;
  switch (model) {
    case FresnelModel::kSchlick: r = SchlickFresnelAverage(x); break;
    case FresnelModel::kDielectric: r = ExactFresnelAverage(x, 0.0); break;
    case FresnelModel::kConductor: r = ExactFresnelAverage(x, y); break;
    case FresnelModel::kF82: r = F82TintFresnelAverage(x, y); break;
  }
  PointValue out;
  out.value[0] = r.value;
  out.error[0] = r.error;
  out.quadrature = true;
  out.exact = model == FresnelModel::kF82;  // the closed form, error 0
  return out;
}

namespace {

PointCoordinate Coordinate(const char *option, double min, double max, const char *accepted,
                           const char *meaning) {
  PointCoordinate c;
  c.option = option;
  c.meaning = meaning;
  c.min = min;
  c.max = max;
  c.accepted = accepted;
  return c;
}

// The Fresnel model part: option fresnel, metadata ndf and smith "none"
// and fresnel; read back from the metadata together with the axes each
// Fresnel model's table has (F0; eta; eta and k; F0 and tint).
class FresnelPart final : public TableModel {
 public:
  std::vector<std::string> Options() const override { return {"fresnel"}; }
  Metadata Records(const BakeSettings &s) const override {
    return {{"ndf", "none"}, {"smith", "none"}, {"fresnel", std::string(ToString(s.fresnel))}};
  }
  std::string Alpha(const BakeSettings &) const override { return "n/a"; }
  std::string Describe(const BakeSettings &s) const override {
    return "fresnel " + std::string(ToString(s.fresnel));
  }
  void Read(const Table &table, BakeSettings *s,
            std::vector<std::string> *problems) const override {
    const std::string fresnel = RequiredMetadata(table, "fresnel", problems);
    if (fresnel == "schlick" && table.x.name == "F0" && !table.is2D() && table.x.min >= 0.0 &&
        table.x.max <= 1.0)
      s->fresnel = FresnelModel::kSchlick;
    else if (fresnel == "dielectric" && table.x.name == "eta" && !table.is2D() &&
             table.x.min >= 0.0)
      s->fresnel = FresnelModel::kDielectric;
    else if (fresnel == "conductor" && table.x.name == "eta" && table.y.name == "k" &&
             table.x.min >= 0.0 && table.y.min >= 0.0)
      s->fresnel = FresnelModel::kConductor;
    else if (fresnel == "f82" && table.x.name == "F0" && table.y.name == "tint" &&
             table.x.min >= 0.0 && table.x.max <= 1.0 && table.y.min >= 0.0 && table.y.max <= 1.0)
      s->fresnel = FresnelModel::kF82;
    else
      problems->push_back("fresnel '" + fresnel + "' with axes " + table.x.name + ", " +
                          (table.y.name.empty() ? "none" : table.y.name) +
                          " is not a Favg lutbake writes");
  }
  bool Same(const BakeSettings &a, const BakeSettings &b) const override {
    return a.fresnel == b.fresnel;
  }
};

class FresnelAverage final : public TableDefinition {
 public:
  const char *Name() const override { return "Favg"; }
  uint64_t SeedId() const override { return 2; }
  std::string Summary() const override {
    return "average Fresnel F_avg = 2 integral F(mu) mu dmu of a Fresnel model (--fresnel)";
  }
  void Axes(const BakeSettings &s, int size, Axis *x, Axis *y) const override {
    FresnelAxes(s.fresnel, size, x, y);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &s) const override {
    const PointCoordinate eta =
        Coordinate("eta", 1e-3, 1e3, "comma-separated numbers from 1e-3 to 1000",
                   "relative index of refraction (dielectric eta < 1: light inside the denser "
                   "medium, total internal reflection)");
    switch (s.fresnel) {
      case FresnelModel::kSchlick:
        return {Coordinate("f0", 0.0, 1.0, "comma-separated numbers in [0, 1]",
                           "reflectance at normal incidence")};
      case FresnelModel::kDielectric: return {eta};
      case FresnelModel::kConductor: {
        PointCoordinate k = Coordinate("k", 0.0, 1e3, "comma-separated numbers from 0 to 1000",
                                       "a conductor's extinction coefficient (default 0)");
        k.required = false;
        return {eta, k};
      }
      case FresnelModel::kF82:
        return {Coordinate("f0", 0.0, 1.0, "comma-separated numbers in [0, 1]",
                           "reflectance at normal incidence"),
                Coordinate("tint", 0.0, 1.0, "comma-separated numbers in [0, 1]",
                           "the F82 tint (F at mu = 1/7 over Schlick's there)")};
    }
    return {};
  }
  std::vector<std::string> CoordinateOptions() const override { return {"f0", "eta", "k", "tint"}; }

  const TableModel &ModelPart() const override {
    static const FresnelPart model;
    return model;
  }
  Metadata PointLabels(const BakeSettings &s) const override {
    return {{"fresnel", std::string(ToString(s.fresnel))}};
  }
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override {
    const size_t before = problems->size();
    ModelPart().Read(table, s, problems);
    return problems->size() == before;
  }

  bool Sampled() const override { return false; }
  PointValue Evaluate(const BakeSettings &s, double x, double y) const override {
    return EvaluateFresnelAverage(s.fresnel, x, y);
  }
  uint64_t SamplesPerTexel(const BakeSettings &) const override { return 0; }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "Gauss-Kronrod error estimate";
  }

  std::optional<MonotonicClaim> Monotonic(const BakeSettings &s) const override {
    MonotonicClaim claim;
    switch (s.fresnel) {
      case FresnelModel::kSchlick:
        claim.direction = +1;
        claim.claim = "F_avg increasing in F0";
        break;
      case FresnelModel::kDielectric:
        claim.direction = +1;
        claim.from = 1.0;
        claim.claim = "F_avg increasing in eta for eta >= 1";
        break;
      case FresnelModel::kConductor:
        claim.skipped =
            "conductor F_avg is not monotonic in k for small eta (eta 0.1: it falls as k grows "
            "from 0), so nothing is claimed";
        break;
      case FresnelModel::kF82:
        // dF_avg/dF0 = 20/21 - (1 - tint) (1 - (6/7)^5) 7^7 / (126 6^6)
        // >= 20/21 - 0.0753 > 0.
        claim.direction = +1;
        claim.claim = "F82 F_avg increasing in F0 at every tint";
        break;
    }
    return claim;
  }
  std::optional<ClosedForm> Closed(const BakeSettings &s) const override {
    if (s.fresnel == FresnelModel::kF82)
      return ClosedForm{"F82-tint F_avg", "20/21 F0 + 1/21 - a / 126", [](double f0, double tint) {
                          return F82TintFresnelAverage(f0, tint).value;
                        }};
    if (s.fresnel != FresnelModel::kSchlick) return {};
    return ClosedForm{"Schlick F_avg", "20/21 F0 + 1/21",
                      [](double f0, double) { return f0 * (20.0 / 21.0) + 1.0 / 21.0; }};
  }
  ValueClaim Range(const BakeSettings &s) const override {
    if (s.fresnel == FresnelModel::kF82)
      return {-13.0 / 756.0, 1.0, false,
              "in [-13/756, 1] (the unclamped F82 Fresnel dips below 0 for small F0 and tint)"};
    return {0.0, 1.0, false, "in [0, 1]"};
  }

  PlanRole Role() const override { return PlanRole::kFresnelAverage; }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    if (table.y.name == "tint") {
      text.notes.push_back(
          "F82-tint Fresnel, per colour channel: F(mu) = F0 + (1 - F0) (1 - mu)^5 "
          "- a mu (1 - mu)^6,");
      text.notes.push_back(
          "a = Schlick(F0, 1/7) (1 - tint) 7^7 / 6^6; F_avg = 20/21 F0 + 1/21 - "
          "a / 126 (unclamped).");
    }
    text.lookupComment = "Average Fresnel F_avg at the Fresnel parameter(s) " + table.x.name +
                         (table.is2D() ? " and " + table.y.name : std::string()) + ".";
    return text;
  }
};

}  // namespace

const TableDefinition &FresnelAverageTable() {
  static const FresnelAverage table;
  return table;
}

}  // namespace lutbake
