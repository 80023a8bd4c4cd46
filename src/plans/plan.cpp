#include "lutbake/plans/plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "lutbake/integrators/fresnel_average.h"

namespace lutbake {

namespace {

// The uses of one parameter, gathered from several materials.
struct Uses {
  std::set<double> exact;
  std::vector<std::pair<double, double>> ranges;
  std::vector<std::string> materials;

  void AddMaterial(const std::string &name) {
    if (std::find(materials.begin(), materials.end(), name) == materials.end())
      materials.push_back(name);
  }
  void Add(double lo, double hi) {
    if (lo == hi)
      exact.insert(lo);
    else
      ranges.emplace_back(lo, hi);
  }
  void Add(const ParameterUse &p) {
    if (p.range())
      Add(p.min, p.max);
    else
      for (double v : p.values) exact.insert(v);
  }

  // What a table must cover, and the axis that covers it: listed when every
  // use is exact and there are few, else linear over the hull with
  // `fullCount * width / fullWidth` texels (at least 2).
  CoveredRange Cover(int maxListed) const {
    CoveredRange c;
    c.min = HUGE_VAL;
    c.max = -HUGE_VAL;
    for (double v : exact) c.min = std::min(c.min, v), c.max = std::max(c.max, v);
    for (const auto &[lo, hi] : ranges) c.min = std::min(c.min, lo), c.max = std::max(c.max, hi);
    if (ranges.empty() && static_cast<int>(exact.size()) <= maxListed)
      c.values.assign(exact.begin(), exact.end());
    return c;
  }
};

Axis AxisOver(const std::string &name, const CoveredRange &c, int fullCount, double fullWidth) {
  if (!c.values.empty()) return ListedAxis(name, c.values);
  const double share = (c.max - c.min) / fullWidth;
  const int count =
      std::max(2, static_cast<int>(std::ceil(static_cast<double>(fullCount) * share - 1e-9)));
  return LinearAxis(name, c.min, c.max, count);
}

std::string Suffix(NdfKind ndf, SmithForm smith) {
  return std::string(ndf == NdfKind::kBeckmann ? "_beckmann" : "") +
         (smith == SmithForm::kSeparable ? "_separable" : "");
}

// An axis for people: 6 significant digits (the metadata keeps all 17).
std::string ShortAxis(const Axis &axis) {
  const auto num = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return std::string(buffer);
  };
  std::string text = axis.name + (axis.listed() ? " at " : " linear [");
  if (axis.listed())
    for (size_t i = 0; i < axis.nodes.size(); ++i) text += (i ? ", " : "") + num(axis.nodes[i]);
  else
    text += num(axis.min) + ", " + num(axis.max) + "]";
  return text + " (" + std::to_string(axis.count) + (axis.count == 1 ? " texel)" : " texels)");
}

// The tables that serve a purpose, in the registry's order.
std::vector<const TableDefinition *> TablesFor(PlanRole role) {
  std::vector<const TableDefinition *> tables;
  for (const TableDefinition *t : AllTables())
    if (t->Role() == role) tables.push_back(t);
  return tables;
}

int SizeFor(const PlanOptions &o, const TableDefinition &table) {
  BakeSettings s;
  s.size = o.size;
  s.tableSizes = o.tableSizes;
  return s.SizeFor(table.Name(), table.DefaultSize());
}

std::string JoinNames(const std::vector<std::string> &names) {
  std::string out;
  for (const std::string &n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

BakePlan MakePlan(const std::vector<MaterialSpec> &materials, const PlanOptions &options) {
  BakePlan plan;
  plan.materials = materials;

  // (ndf, smith) -> uses of roughness by compensated / IBL materials.
  using Model = std::pair<NdfKind, SmithForm>;
  std::map<Model, Uses> compensated, ibl;
  // (ndf, smith) -> roughness of the lit materials, when area lights are asked for.
  std::map<Model, Uses> area;
  // The parameters of the Favg axes: eta (and k), or F0 and tint (f82).
  std::map<FresnelModel, std::pair<Uses, Uses>> fresnel;
  // (ndf, smith) -> roughness of the IBL-lit materials with the F82-tint Fresnel.
  std::map<Model, Uses> f82;
  bool f82Used = false;  // a lit material has the F82-tint Fresnel
  // (ndf, smith) -> roughness of the compensated materials' coats, and their
  // relative IORs, both sides.
  std::map<Model, Uses> coat;
  std::map<Model, std::set<double>> coatEtas;
  bool coatOff = false;        // a material with a coat, without compensation
  Uses sheen;                  // sheen roughness of the materials with a sheen layer
  Uses glass;                  // roughness of the compensated materials with transmission
  std::set<double> glassEtas;  // their relative IORs, both sides
  bool glassOff = false;       // a transmitting material without compensation
  int lit = 0, litSchlickCompensated = 0;
  for (const MaterialSpec &m : materials) {
    if (m.unlit) continue;
    for (const std::string &f : m.unsupported) plan.unsupported.push_back({m.name, f});
    for (const RoughnessUse &r : m.sheenRoughness)
      sheen.Add(r.min, r.max), sheen.AddMaterial(m.name);
    if (!m.transmissionEta.empty()) {
      if (options.compensation &&
          m.compensation.value_or(options.defaultCompensation.value_or(true))) {
        for (const RoughnessUse &r : m.transmissionRoughness) glass.Add(r.min, r.max);
        glass.AddMaterial(m.name);
        glassEtas.insert(m.transmissionEta.begin(), m.transmissionEta.end());
      } else {
        glassOff = true;
      }
    }
    if (m.roughness.empty()) continue;  // no specular lobe
    ++lit;
    const bool usesIbl = options.ibl && m.ibl.value_or(options.defaultIbl.value_or(true));
    const bool usesCompensation =
        options.compensation && m.compensation.value_or(options.defaultCompensation.value_or(true));
    const Model model{m.ndf, m.smith};
    for (const RoughnessUse &r : m.roughness) {
      if (usesIbl) ibl[model].Add(r.min, r.max), ibl[model].AddMaterial(m.name);
      if (options.areaLights.value_or(false))
        area[model].Add(r.min, r.max), area[model].AddMaterial(m.name);
      if (usesCompensation)
        compensated[model].Add(r.min, r.max), compensated[model].AddMaterial(m.name);
    }
    if (usesCompensation) {
      if (m.fresnel.model == FresnelModel::kSchlick) {
        ++litSchlickCompensated;
      } else {
        auto &[x, y] = fresnel[m.fresnel.model];
        const bool tinted = m.fresnel.model == FresnelModel::kF82;
        x.Add(tinted ? m.fresnel.f0 : m.fresnel.eta);
        x.AddMaterial(m.name);
        if (tinted)
          y.Add(m.fresnel.tint);
        else if (m.fresnel.model == FresnelModel::kConductor)
          y.Add(m.fresnel.k);
      }
    }
    // The F82 term C of the split sum (f82), beside dfg: over the base
    // layer's roughness only, since a coat's Fresnel is its own.
    if (m.fresnel.model == FresnelModel::kF82) {
      f82Used = true;
      if (usesIbl)
        for (const RoughnessUse &r : m.roughness)
          if (r.layer == "base") f82[model].Add(r.min, r.max), f82[model].AddMaterial(m.name);
    }
    // A coat: energy-conserving layering over the base, part of energy
    // compensation.
    if (!m.coatEta.empty()) {
      if (usesCompensation) {
        for (const RoughnessUse &r : m.coatRoughness) coat[model].Add(r.min, r.max);
        coat[model].AddMaterial(m.name);
        coatEtas[model].insert(m.coatEta.begin(), m.coatEta.end());
      } else {
        coatOff = true;
      }
    }
  }

  // Plain names unless the plan needs two variants of a table.
  std::set<Model> models;
  for (const auto &[model, uses] : compensated) models.insert(model);
  for (const auto &[model, uses] : ibl) models.insert(model);
  const bool variants = models.size() > 1;
  // A table over the roughness its materials use: its default axes, the
  // roughness axis narrowed (or listed).
  const auto roughnessTable = [&](const TableDefinition &table, const Model &model,
                                  const Uses &uses, bool modelSuffix = true) {
    PlannedTable t;
    t.definition = &table;
    t.name = std::string(table.Name()) +
             (variants && modelSuffix ? Suffix(model.first, model.second) : "");
    t.ndf = model.first;
    t.smith = model.second;
    t.roughness = uses.Cover(options.maxListedRoughness);
    t.materials = uses.materials;
    const int full = SizeFor(options, table);
    table.Axes(PlannedSettings(t, BakeSettings{}), full, &t.x, &t.y);
    Axis &r = table.PlannedRoughnessAxis() == 0 ? t.x : t.y;
    r = AxisOver(r.name, t.roughness, full, 1.0);
    plan.tables.push_back(t);
  };
  for (const auto &[model, uses] : compensated)
    for (const TableDefinition *table : TablesFor(PlanRole::kEnergyCompensation))
      roughnessTable(*table, model, uses);
  for (const TableDefinition *table : TablesFor(PlanRole::kFresnelAverage))
    for (const auto &[model, uses] : fresnel) {
      PlannedTable t;
      t.definition = table;
      t.fresnel = model;
      t.name = std::string(table->Name()) +
               (fresnel.size() > 1 ? "_" + std::string(ToString(model)) : std::string());
      const int full = SizeFor(options, *table);
      t.materials = uses.first.materials;
      if (model == FresnelModel::kF82) {
        // F0 and tint are reflectances: the full table spans [0, 1] on both,
        // and a narrowed range keeps its texel spacing, as roughness does.
        t.f0 = uses.first.Cover(options.maxListedRoughness);
        t.tint = uses.second.Cover(options.maxListedRoughness);
        table->Axes(PlannedSettings(t, BakeSettings{}), full, &t.x, &t.y);
        t.x = AxisOver(t.x.name, t.f0, full, t.x.max - t.x.min);
        t.y = AxisOver(t.y.name, t.tint, full, t.y.max - t.y.min);
        plan.tables.push_back(t);
        continue;
      }
      const Uses &eta = uses.first, &k = uses.second;
      t.eta = eta.Cover(options.maxListedRoughness);
      // Linear ranges get the full table's texel count: the F_avg axes have no
      // fixed full width to share (section 1 of the SPEC leaves them open).
      t.x = AxisOver("eta", t.eta, full, t.eta.max - t.eta.min);
      t.y = LinearAxis("", 0.0, 1.0, 1);
      if (model == FresnelModel::kConductor) {
        t.k = k.Cover(options.maxListedRoughness);
        t.y = AxisOver("k", t.k, full, t.k.max - t.k.min);
      }
      plan.tables.push_back(t);
    }
  for (const auto &[model, uses] : ibl)
    for (const TableDefinition *table : TablesFor(PlanRole::kImageBasedLighting))
      roughnessTable(*table, model, uses);
  // The F82-tint metals' third split-sum term, F0 A + F90 B - a C: f82 at
  // dfg's texels (same model, the F82 materials' base roughness).
  for (const auto &[model, uses] : f82)
    for (const TableDefinition *table : TablesFor(PlanRole::kF82ImageBasedLighting))
      roughnessTable(*table, model, uses);
  // The sheen tables do not depend on the base layer's model: one of each,
  // over every sheen roughness (the bake's --sheen-visibility and
  // --sheen-alpha choose their model).
  if (!sheen.materials.empty())
    for (const TableDefinition *table : TablesFor(PlanRole::kSheenAlbedoScaling))
      roughnessTable(*table, Model{NdfKind::kGgx, SmithForm::kCorrelated}, sheen, false);

  // Area lights: the LTC fit of each specular lobe, over its roughness, and
  // of the sheen lobe over every sheen roughness.
  for (const auto &[model, uses] : area)
    for (const TableDefinition *table : TablesFor(PlanRole::kAreaLights))
      roughnessTable(*table, model, uses);
  if (options.areaLights.value_or(false) && !sheen.materials.empty())
    for (const TableDefinition *table : TablesFor(PlanRole::kSheenAreaLights))
      roughnessTable(*table, Model{NdfKind::kGgx, SmithForm::kCorrelated}, sheen, false);

  // Rough transmission: over the roughness used, and a listed eta axis at
  // exactly the IORs used, both sides (the third axis of glass_E, the
  // second of glass_Eavg).
  if (!glass.materials.empty())
    for (const TableDefinition *table : TablesFor(PlanRole::kGlassCompensation)) {
      roughnessTable(*table, Model{NdfKind::kGgx, SmithForm::kCorrelated}, glass, false);
      PlannedTable &t = plan.tables.back();
      t.etas.assign(glassEtas.begin(), glassEtas.end());
      (table->PlannedRoughnessAxis() == 1 ? t.z : t.y) = ListedAxis("eta", t.etas);
    }
  // Coats: spec_E and spec_Eavg over the coat roughness and, as for glass, a
  // listed eta axis at exactly the coat IORs, both sides (a glTF clearcoat,
  // IOR 1.5: the slices 1/1.5 and 1.5).
  for (const auto &[model, uses] : coat)
    for (const TableDefinition *table : TablesFor(PlanRole::kDielectricLayering)) {
      roughnessTable(*table, model, uses);
      PlannedTable &t = plan.tables.back();
      t.etas.assign(coatEtas[model].begin(), coatEtas[model].end());
      (table->PlannedRoughnessAxis() == 1 ? t.z : t.y) = ListedAxis("eta", t.etas);
    }

  // Why each table that is not planned is left out.
  const auto has = [&](PlanRole role) {
    for (const PlannedTable &t : plan.tables)
      if (t.definition->Role() == role) return true;
    return false;
  };
  const auto omit = [&](PlanRole role, const std::string &reason) {
    for (const TableDefinition *table : TablesFor(role))
      plan.omitted.push_back({table->Name(), reason});
  };
  std::string nothingLit;
  if (materials.empty())
    nothingLit = "the scenes and manifests hold no materials";
  else if (lit == 0)
    nothingLit = "no material needs it: each of the " + std::to_string(materials.size()) +
                 " is unlit or has no specular lobe";
  // A term is off because of the command line, the manifest's lighting, or
  // the own setting of every material that would need the table (`who`).
  const auto offReason = [&](bool commandLine, const std::optional<bool> &manifest,
                             const char *flag, const char *what,
                             const char *who = "every lit material") {
    if (!nothingLit.empty()) return nothingLit;
    if (!commandLine) return std::string(what) + " is off (" + flag + ")";
    if (manifest.has_value() && !*manifest)
      return std::string(what) + " is off (the manifest's \"lighting\" sets it false)";
    return std::string(what) + " is off for " + who + " (each sets it false)";
  };
  if (!has(PlanRole::kEnergyCompensation))
    omit(PlanRole::kEnergyCompensation, offReason(options.compensation, options.defaultCompensation,
                                                  "--no-compensation", "energy compensation"));
  if (!has(PlanRole::kFresnelAverage)) {
    if (!has(PlanRole::kEnergyCompensation)) {
      omit(PlanRole::kFresnelAverage,
           "F_avg serves energy compensation only, and no material uses it");
    } else {
      plan.schlickFavgFunction = litSchlickCompensated > 0;
      omit(PlanRole::kFresnelAverage,
           "every compensated material uses Schlick's Fresnel, whose F_avg = 20/21 F0 + 1/21 F90 "
           "exactly: the Favg.h header carries that function instead of a table");
    }
  }
  if (!has(PlanRole::kImageBasedLighting))
    omit(PlanRole::kImageBasedLighting,
         offReason(options.ibl, options.defaultIbl, "--no-ibl", "image-based lighting"));
  if (!has(PlanRole::kF82ImageBasedLighting))
    omit(PlanRole::kF82ImageBasedLighting,
         !nothingLit.empty() || f82Used
             ? offReason(options.ibl, options.defaultIbl, "--no-ibl", "image-based lighting",
                         "every material with the F82-tint Fresnel")
             : "no material uses the F82-tint Fresnel (a manifest's \"fresnel\": {\"model\": "
               "\"f82\"}); the split sum of the others is F0 A + F90 B, dfg alone");
  if (!has(PlanRole::kGlassCompensation))
    omit(PlanRole::kGlassCompensation,
         !nothingLit.empty() && !glassOff ? nothingLit
         : glassOff ? "energy compensation is off for every material with transmission"
                    : "no material transmits (KHR_materials_transmission with a "
                      "transmissionFactor above 0)");
  if (!has(PlanRole::kDielectricLayering))
    omit(PlanRole::kDielectricLayering,
         !nothingLit.empty() || coatOff
             ? offReason(options.compensation, options.defaultCompensation, "--no-compensation",
                         "energy compensation (and with it energy-conserving layering)",
                         "every material with a coat")
             : "no material has a coat (KHR_materials_clearcoat with a clearcoatFactor above 0, "
               "or a manifest's \"coat\")");
  if (!has(PlanRole::kSheenAlbedoScaling))
    omit(PlanRole::kSheenAlbedoScaling,
         !nothingLit.empty() ? nothingLit
                             : "no material has a sheen layer (KHR_materials_sheen with a "
                               "sheenColorFactor above 0, or a manifest's \"sheenRoughness\")");
  if (!has(PlanRole::kAreaLights))
    omit(PlanRole::kAreaLights,
         !nothingLit.empty() ? nothingLit
         : options.areaLights.has_value()
             ? "area lights are off (the manifest's \"areaLights\" sets it false)"
             : "no manifest asks for area lights (\"areaLights\": true)");
  if (!has(PlanRole::kSheenAreaLights))
    omit(PlanRole::kSheenAreaLights,
         !nothingLit.empty() ? nothingLit
         : !options.areaLights.value_or(false)
             ? "no manifest asks for area lights (\"areaLights\": true), or it sets them false"
             : "no material has a sheen layer (KHR_materials_sheen with a sheenColorFactor above "
               "0, or a manifest's \"sheenRoughness\")");
  return plan;
}

BakeSettings PlannedSettings(const PlannedTable &table, const BakeSettings &base) {
  BakeSettings s = base;
  s.ndf = table.ndf;
  s.smith = table.smith;
  s.fresnel = table.fresnel;
  return s;
}

namespace {

nlohmann::ordered_json CoveredJson(const CoveredRange &c) {
  nlohmann::ordered_json j;
  j["min"] = c.min;
  j["max"] = c.max;
  if (!c.values.empty()) j["values"] = c.values;
  return j;
}

}  // namespace

std::string PlanJson(const BakePlan &plan) {
  using Json = nlohmann::ordered_json;
  Json out;
  out["tables"] = Json::array();
  for (const PlannedTable &t : plan.tables) {
    Json j;
    j["name"] = t.name;
    j["table"] = t.definition->Name();
    const PlanRole role = t.definition->Role();
    if (role == PlanRole::kFresnelAverage) {
      j["fresnel"] = ToString(t.fresnel);
      if (t.fresnel == FresnelModel::kF82) {
        j["F0"] = CoveredJson(t.f0);
        j["tint"] = CoveredJson(t.tint);
      } else {
        j["eta"] = CoveredJson(t.eta);
        if (t.fresnel == FresnelModel::kConductor) j["k"] = CoveredJson(t.k);
      }
    } else if (role == PlanRole::kSheenAlbedoScaling || role == PlanRole::kSheenAreaLights) {
      j["sheenRoughness"] = CoveredJson(t.roughness);
    } else if (role == PlanRole::kGlassCompensation || role == PlanRole::kDielectricLayering) {
      j["ndf"] = ToString(t.ndf);
      j["smith"] = ToString(t.smith);
      j["roughness"] = CoveredJson(t.roughness);
      j["eta"] = t.etas;
    } else {
      j["ndf"] = ToString(t.ndf);
      j["smith"] = ToString(t.smith);
      j["roughness"] = CoveredJson(t.roughness);
    }
    j["axisX"] = DescribeAxis(t.x);
    j["axisY"] = t.y.name.empty() ? "none (1D table)" : DescribeAxis(t.y);
    if (!t.z.name.empty()) {
      j["axisZ"] = DescribeAxis(t.z);
      j["size"] = {t.x.count, t.y.count, t.z.count};
    } else {
      j["size"] = {t.x.count, t.y.count};
    }
    j["materials"] = t.materials;
    out["tables"].push_back(j);
  }
  if (plan.estimate)
    out["estimate"] = {{"seconds", plan.estimate->seconds},
                       {"cpuSeconds", plan.estimate->cpuSeconds},
                       {"threads", plan.estimate->threads},
                       {"texels", plan.estimate->texels},
                       {"timedTexels", plan.estimate->timedTexels}};
  out["omitted"] = Json::array();
  for (const OmittedTable &o : plan.omitted)
    out["omitted"].push_back({{"name", o.name}, {"reason", o.reason}});
  out["unsupported"] = Json::array();
  for (const UnsupportedFeature &u : plan.unsupported)
    out["unsupported"].push_back({{"material", u.material}, {"feature", u.feature}});
  out["materials"] = Json::array();
  for (const MaterialSpec &m : plan.materials) {
    Json j;
    j["name"] = m.name;
    j["source"] = m.source;
    j["where"] = m.where;
    j["unlit"] = m.unlit;
    j["ndf"] = ToString(m.ndf);
    j["smith"] = ToString(m.smith);
    j["fresnel"] = ToString(m.fresnel.model);
    if (!m.fresnel.schlickF0.empty()) {
      // Schlick's F_avg = 20/21 F0 + 1/21 F90, per channel: a constant, no table.
      Json favg = Json::array();
      for (double f0 : m.fresnel.schlickF0)
        favg.push_back(f0 * (20.0 / 21.0) + m.fresnel.schlickF90 / 21.0);
      j["F0"] = m.fresnel.schlickF0;
      j["F90"] = m.fresnel.schlickF90;
      j["Favg"] = favg;
    } else if (m.fresnel.model != FresnelModel::kSchlick && !m.fresnel.eta.range() &&
               m.fresnel.eta.values.size() == 1 &&
               (m.fresnel.model == FresnelModel::kDielectric ||
                (!m.fresnel.k.range() && m.fresnel.k.values.size() == 1))) {
      const double k = m.fresnel.model == FresnelModel::kConductor ? m.fresnel.k.values[0] : 0.0;
      j["eta"] = m.fresnel.eta.values[0];
      if (m.fresnel.model == FresnelModel::kConductor) j["k"] = k;
      j["Favg"] = EvaluateFresnelAverage(m.fresnel.model, m.fresnel.eta.values[0], k).value[0];
    } else if (m.fresnel.model == FresnelModel::kF82 && m.fresnel.f0.values.size() == 1 &&
               m.fresnel.tint.values.size() == 1) {
      // The closed form 20/21 F0 + 1/21 - a / 126 (fresnel_average.h).
      const double f0 = m.fresnel.f0.values[0], tint = m.fresnel.tint.values[0];
      j["F0"] = f0;
      j["tint"] = tint;
      j["Favg"] = EvaluateFresnelAverage(FresnelModel::kF82, f0, tint).value[0];
    }
    j["roughness"] = Json::array();
    for (const RoughnessUse &r : m.roughness)
      j["roughness"].push_back({{"layer", r.layer}, {"min", r.min}, {"max", r.max}});
    if (!m.coatEta.empty()) {
      Json coat;
      coat["eta"] = m.coatEta;
      coat["roughness"] = Json::array();
      for (const RoughnessUse &r : m.coatRoughness)
        coat["roughness"].push_back({{"min", r.min}, {"max", r.max}});
      j["coat"] = coat;
    }
    if (!m.sheenRoughness.empty()) {
      j["sheenRoughness"] = Json::array();
      for (const RoughnessUse &r : m.sheenRoughness)
        j["sheenRoughness"].push_back({{"min", r.min}, {"max", r.max}});
    }
    j["unsupported"] = m.unsupported;
    j["notes"] = m.notes;
    out["materials"].push_back(j);
  }
  return out.dump(2);
}

std::string DescribePlan(const BakePlan &plan) {
  std::ostringstream s;
  size_t unlit = 0;
  for (const MaterialSpec &m : plan.materials) unlit += m.unlit ? 1 : 0;
  s << plan.materials.size() << " material" << (plan.materials.size() == 1 ? "" : "s");
  if (unlit) s << " (" << unlit << " unlit)";
  s << "; " << plan.tables.size() << " table" << (plan.tables.size() == 1 ? "" : "s") << " to bake"
    << (plan.tables.empty() ? ": nothing to bake" : ":") << "\n";
  for (const PlannedTable &t : plan.tables) {
    s << "  " << t.name << "  " << t.x.count;
    if (!t.y.name.empty()) s << " x " << t.y.count;
    if (!t.z.name.empty()) s << " x " << t.z.count;
    s << "  (";
    if (t.definition->Role() == PlanRole::kFresnelAverage)
      s << ToString(t.fresnel);
    else if (t.definition->Role() == PlanRole::kSheenAlbedoScaling ||
             t.definition->Role() == PlanRole::kSheenAreaLights)
      s << "charlie sheen";
    else
      s << ToString(t.ndf) << ", " << ToString(t.smith);
    s << ")\n    " << ShortAxis(t.x);
    if (!t.y.name.empty()) s << "\n    " << ShortAxis(t.y);
    if (!t.z.name.empty()) s << "\n    " << ShortAxis(t.z);
    s << "\n    for " << JoinNames(t.materials) << "\n";
  }
  if (plan.estimate && !plan.tables.empty())
    s << "estimated bake: " << DescribeEstimate(*plan.estimate) << "\n";
  if (!plan.omitted.empty()) s << "left out:\n";
  for (const OmittedTable &o : plan.omitted) s << "  " << o.name << ": " << o.reason << "\n";
  if (!plan.unsupported.empty()) s << "unsupported (needs tables lutbake does not bake):\n";
  for (const UnsupportedFeature &u : plan.unsupported)
    s << "  " << u.material << ": " << u.feature << "\n";
  bool notes = false;
  for (const MaterialSpec &m : plan.materials)
    for (const std::string &n : m.notes) {
      if (!notes) s << "notes:\n";
      notes = true;
      s << "  " << m.name << ": " << n << "\n";
    }
  return s.str();
}

}  // namespace lutbake
