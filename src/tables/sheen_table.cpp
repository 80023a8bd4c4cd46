#include "sheen_table.h"

#include <cmath>
#include <stdexcept>

namespace lutbake {

std::string_view ToString(SheenAlpha mapping) {
  return mapping == SheenAlpha::kSquared ? "squared" : "linear";
}

bool ParseSheenAlpha(std::string_view text, SheenAlpha *mapping) {
  if (text == "linear")
    *mapping = SheenAlpha::kLinear;
  else if (text == "squared")
    *mapping = SheenAlpha::kSquared;
  else
    return false;
  return true;
}

namespace {

const char *kAlphaLinear = "alpha = sheenRoughness";
const char *kAlphaSquared = "alpha = sheenRoughness^2";

class Sheen final : public TableModel {
 public:
  std::vector<std::string> Options() const override { return {"sheen-visibility", "sheen-alpha"}; }
  Metadata Records(const BakeSettings &s) const override {
    return {{"ndf", "charlie"},
            {"visibility", std::string(ToString(s.sheenVisibility))},
            {"sheenColor", "1"},
            {"fresnel", "none (F = 1)"}};
  }
  std::string Alpha(const BakeSettings &s) const override {
    return s.sheenAlpha == SheenAlpha::kSquared ? kAlphaSquared : kAlphaLinear;
  }
  std::string Describe(const BakeSettings &s) const override {
    return "Charlie NDF, " + std::string(ToString(s.sheenVisibility)) + " visibility, " + Alpha(s);
  }
  void Read(const Table &table, BakeSettings *s,
            std::vector<std::string> *problems) const override {
    if (RequiredMetadata(table, "ndf", problems) != "charlie")
      problems->push_back("ndf is not charlie");
    const std::string visibility = RequiredMetadata(table, "visibility", problems);
    if (!ParseSheenVisibility(visibility, &s->sheenVisibility))
      problems->push_back("visibility '" + visibility + "' unknown");
    const std::string alpha = RequiredMetadata(table, "alpha", problems);
    if (alpha == kAlphaLinear)
      s->sheenAlpha = SheenAlpha::kLinear;
    else if (alpha == kAlphaSquared)
      s->sheenAlpha = SheenAlpha::kSquared;
    else
      problems->push_back("alpha '" + alpha + "' is neither sheenRoughness nor sheenRoughness^2");
  }
  bool Same(const BakeSettings &a, const BakeSettings &b) const override {
    return a.sheenVisibility == b.sheenVisibility && a.sheenAlpha == b.sheenAlpha;
  }
};

}  // namespace

const TableModel &SheenModel() {
  static const Sheen model;
  return model;
}

Metadata SheenTable::PointLabels(const BakeSettings &s) const {
  return {{"sheen-visibility", std::string(ToString(s.sheenVisibility))},
          {"sheen-alpha", std::string(ToString(s.sheenAlpha))}};
}

bool SheenTable::ReadModel(const Table &table, BakeSettings *s,
                           std::vector<std::string> *problems) const {
  const size_t before = problems->size();
  SheenModel().Read(table, s, problems);
  const bool twoD = PlannedRoughnessAxis() == 1;
  const Axis &r = twoD ? table.y : table.x;
  if (r.name != "sheenRoughness" || r.min < 0.0 || r.max > 1.0)
    problems->push_back("the roughness axis is not sheenRoughness within [0, 1]");
  if (twoD && (table.x.name != "mu" || table.x.min < 0.0 || table.x.max > 1.0))
    problems->push_back("axis x is not mu within [0, 1]");
  if (!twoD && table.is2D()) problems->push_back(std::string(Name()) + " is not 1D");
  if (twoD && !table.is2D()) problems->push_back(table.Name() + " is not 2D");
  return problems->size() == before;
}

std::string SheenTable::QuadratureDescription(const BakeSettings &s) const {
  return s.estimator == Estimator::kAdaptiveQuadrature
             ? "adaptive Gauss-Kronrod quadrature over the half vector"
             : "panel Gauss-Legendre quadrature over the light direction, two orders";
}

std::string SheenTable::QuadratureBound(const BakeSettings &s) const {
  if (s.estimator == Estimator::kAdaptiveQuadrature)
    return "16 x the Gauss-Kronrod estimates of both levels";
  return "quadrature texels: the panel rule's difference between two orders plus its floor "
         "(sheen_quadrature.h)";
}

std::string SheenTable::EstimatorProblem(Estimator e) const {
  if (e == Estimator::kCosine)
    return std::string(Name()) +
           " has no cosine-weighted sampler: with the Charlie visibility its weight grows as "
           "1 / mu_i at the horizon (infinite variance); accepted: quadrature, adaptive, ndf, "
           "vndf (both sample the Charlie lobe), vndf-random, uniform";
  return "";
}

double SheenTable::AlphaOf(const BakeSettings &s, double r) {
  // Written so that NaN fails too.
  if (!(r >= 0.0 && r <= 1.0))
    throw std::domain_error("sheen roughness " + FormatDouble(r) + " is outside [0, 1]");
  return s.sheenAlpha == SheenAlpha::kSquared ? r * r : r;
}

PointCoordinate SheenTable::RoughnessCoordinate() {
  PointCoordinate c;
  c.option = "roughness";
  c.accepted = "comma-separated numbers in [0, 1] (sheenRoughness; 0 is the limit)";
  return c;
}

PointValue SheenTable::FromIntegral(const SheenIntegral &q) {
  PointValue out;
  out.value[0] = q.value;
  out.error[0] = q.bound;
  out.evaluations = q.evaluations;
  out.quadrature = true;
  out.exact = q.exact;
  return out;
}

void SheenTable::AddModelNotes(const Table &table, HeaderText *text) {
  const std::string *visibility = table.FindMetadata("visibility");
  const std::string *alpha = table.FindMetadata("alpha");
  const bool squared = alpha && *alpha == kAlphaSquared;
  text->notes.push_back(
      "Charlie sheen (Estevez and Kulla 2017; glTF KHR_materials_sheen), sheen colour 1:");
  text->notes.push_back("  D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi), visibility " +
                        (visibility ? *visibility : std::string("?")) + ".");
  text->notes.push_back(std::string("Roughness is glTF's sheenRoughness r; alpha = ") +
                        (squared ? "r^2." : "r."));
  text->constants.push_back(std::string("inline constexpr bool kSheenAlphaIsRoughnessSquared = ") +
                            (squared ? "true;" : "false;"));
}

}  // namespace lutbake
