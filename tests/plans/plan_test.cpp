// Bake plans: each rule of plan.h on the test scenes and manifests, the
// narrowed and listed tables against the full tables and the quadrature,
// and lutbake::Plan / lutbake::Bake with scenes and manifests end to end
// (what `lutbake plan` and `lutbake bake --scene` call; their exit statuses
// and messages are tests/cli/bake_cli_test.cpp).
#include "lutbake/plans/plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/lutbake.h"
#include "lutbake/plans/manifest.h"
#include "lutbake/plans/scene.h"
#include "lutbake/validation/check.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::Scratch;

const std::string kPlans = std::string(LUTBAKE_TEST_DATA) + "/plans/";
const std::string kScenes = std::string(LUTBAKE_TEST_DATA) + "/scenes/";

BakePlan PlanOf(const std::vector<std::string> &scenes, const PlanOptions &options = {}) {
  std::vector<MaterialSpec> all;
  for (const std::string &s : scenes) {
    const auto ms = ReadSceneMaterials(s);
    all.insert(all.end(), ms.begin(), ms.end());
  }
  return MakePlan(all, options);
}

const PlannedTable *Find(const BakePlan &plan, const std::string &name) {
  for (const PlannedTable &t : plan.tables)
    if (t.name == name) return &t;
  return nullptr;
}

std::string Omitted(const BakePlan &plan, const std::string &name) {
  for (const OmittedTable &o : plan.omitted)
    if (o.name == name) return o.reason;
  return "";
}

TEST(Plan, FewExactRoughnessValuesGetListedRows) {
  const BakePlan plan = PlanOf({kPlans + "listed.gltf"});
  ASSERT_EQ(plan.tables.size(), 3u);
  for (const char *name : {"E", "Eavg", "dfg"}) {
    const PlannedTable *t = Find(plan, name);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->roughness.values, (std::vector<double>{0.25, 0.5})) << name;
    const Axis &r = t->definition == &TableNamed("Eavg") ? t->x : t->y;
    EXPECT_TRUE(r.listed());
    EXPECT_EQ(r.TexelCenter(0), 0.25);
    EXPECT_EQ(r.TexelCenter(1), 0.5);
    // The unlit material needs nothing.
    EXPECT_EQ(t->materials, (std::vector<std::string>{"paint", "steel", "steel copy"}));
  }
  EXPECT_EQ(Find(plan, "dfg")->x.count, 128);
  EXPECT_EQ(Find(plan, "E")->x.count, 32);
  EXPECT_NE(Omitted(plan, "Favg").find("20/21 F0 + 1/21 F90"), std::string::npos);
  EXPECT_TRUE(plan.schlickFavgFunction);
  EXPECT_TRUE(plan.unsupported.empty());
}

TEST(Plan, TexturesNarrowToZeroToFactorKeepingTheTexelSpacing) {
  const BakePlan plan = PlanOf({kPlans + "textured.gltf"});
  const PlannedTable *e = Find(plan, "E");
  ASSERT_NE(e, nullptr);
  EXPECT_TRUE(e->roughness.values.empty());
  EXPECT_EQ(e->roughness.min, 0.0);
  EXPECT_EQ(e->roughness.max, 0.5);
  EXPECT_FALSE(e->y.listed());
  EXPECT_EQ(e->y.min, 0.0);
  EXPECT_EQ(e->y.max, 0.5);
  EXPECT_EQ(e->y.count, 16);                  // half of 32
  EXPECT_EQ(Find(plan, "dfg")->y.count, 64);  // half of 128
  EXPECT_EQ(Find(plan, "Eavg")->x.count, 16);
}

TEST(Plan, ClearcoatAndManyValues) {
  // Base 0.4, coat 0.1 and a textured coat [0, 0.2]: the hull [0, 0.4].
  const BakePlan coat = PlanOf({kPlans + "clearcoat.gltf"});
  EXPECT_EQ(Find(coat, "E")->roughness.min, 0.0);
  EXPECT_EQ(Find(coat, "E")->roughness.max, 0.4);
  // The coats (glTF's clearcoat IOR is 1.5) get spec_E and spec_Eavg at eta
  // = 1/1.5 and 1.5 over the coat roughness alone: 0.1 and [0, 0.2] make
  // [0, 0.2], ceil(32 x 0.2) = 7 rows.
  for (const char *name : {"spec_E", "spec_Eavg"}) {
    const PlannedTable *t = Find(coat, name);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->etas, (std::vector<double>{1 / 1.5, 1.5}));
    EXPECT_EQ((t->definition == &TableNamed("spec_E") ? t->z : t->y).nodes, t->etas);
    const Axis &r = t->definition == &TableNamed("spec_E") ? t->y : t->x;
    EXPECT_EQ(r.min, 0.0);
    EXPECT_EQ(r.max, 0.2);
    EXPECT_EQ(r.count, 7);
    EXPECT_EQ(t->materials, (std::vector<std::string>{"car paint", "textured coat"}));
  }
  // More distinct exact values than kMaxListedRoughness: a linear hull.
  std::vector<MaterialSpec> many;
  for (int i = 0; i <= kMaxListedRoughness; ++i) {
    MaterialSpec m;
    m.name = "m" + std::to_string(i);
    const double r = 0.2 + 0.01 * i;
    m.roughness.push_back({"base", r, r});
    many.push_back(m);
  }
  const BakePlan hull = MakePlan(many, {});
  EXPECT_TRUE(Find(hull, "E")->roughness.values.empty());
  EXPECT_EQ(Find(hull, "E")->y.min, 0.2);
  EXPECT_FALSE(Find(hull, "E")->y.listed());
  many.pop_back();
  EXPECT_EQ(Find(MakePlan(many, {}), "E")->roughness.values.size(),
            static_cast<size_t>(kMaxListedRoughness));
}

TEST(Plan, LightingSwitchesTablesOff) {
  PlanOptions noIbl;
  noIbl.ibl = false;
  const BakePlan a = PlanOf({kPlans + "listed.gltf"}, noIbl);
  EXPECT_EQ(Find(a, "dfg"), nullptr);
  EXPECT_NE(Omitted(a, "dfg").find("--no-ibl"), std::string::npos);
  ASSERT_NE(Find(a, "E"), nullptr);

  PlanOptions noCompensation;
  noCompensation.compensation = false;
  const BakePlan b = PlanOf({kPlans + "listed.gltf"}, noCompensation);
  ASSERT_EQ(b.tables.size(), 1u);
  EXPECT_EQ(b.tables[0].name, "dfg");
  EXPECT_NE(Omitted(b, "E").find("--no-compensation"), std::string::npos);
  EXPECT_NE(Omitted(b, "Eavg").find("--no-compensation"), std::string::npos);
  EXPECT_FALSE(Omitted(b, "Favg").empty());
  EXPECT_FALSE(b.schlickFavgFunction);

  // The manifest's lighting, as lutbake plan applies it.
  const Manifest m = ReadManifest(kPlans + "no_ibl.json");
  PlanOptions fromManifest;
  fromManifest.defaultIbl = m.ibl;
  const BakePlan c = PlanOf({kPlans + "listed.gltf"}, fromManifest);
  EXPECT_EQ(Find(c, "dfg"), nullptr);
  EXPECT_NE(Omitted(c, "dfg").find("manifest"), std::string::npos);
}

// "areaLights": true adds the LTC fit of each lit lobe over its roughness
// (a variant per model, as for the other tables); without it ltc_ggx is left
// out and the plan says how to ask for it; the two places that may say it
// must agree.
TEST(Plan, AreaLightsAddTheLtcTableOfEachLobe) {
  const Manifest m = ParseManifest(
      R"({"areaLights": true, "materials": [
            {"name": "floor", "roughness": {"min": 0.2, "max": 0.6}},
            {"name": "chrome", "ndf": "beckmann", "roughness": 0.1}]})",
      "area.json");
  ASSERT_EQ(m.areaLights, std::optional<bool>(true));
  PlanOptions options;
  options.areaLights = m.areaLights;
  const BakePlan plan = MakePlan(m.materials, options);
  const PlannedTable *ggx = Find(plan, "ltc_ggx");
  const PlannedTable *beckmann = Find(plan, "ltc_ggx_beckmann");
  ASSERT_NE(ggx, nullptr);
  ASSERT_NE(beckmann, nullptr);
  // The roughness axis narrowed to what the materials use.
  EXPECT_DOUBLE_EQ(ggx->roughness.min, 0.2);
  EXPECT_DOUBLE_EQ(ggx->roughness.max, 0.6);
  EXPECT_EQ(ggx->materials, std::vector<std::string>{"floor"});
  EXPECT_EQ(beckmann->materials, std::vector<std::string>{"chrome"});
  EXPECT_EQ(beckmann->ndf, NdfKind::kBeckmann);

  const BakePlan without = MakePlan(m.materials, PlanOptions{});
  EXPECT_EQ(Find(without, "ltc_ggx"), nullptr);
  EXPECT_NE(Omitted(without, "ltc_ggx").find("\"areaLights\": true"), std::string::npos);
  PlanOptions off;
  off.areaLights = false;
  EXPECT_NE(Omitted(MakePlan(m.materials, off), "ltc_ggx").find("sets it false"),
            std::string::npos);

  const Manifest inLighting =
      ParseManifest(R"({"lighting": {"areaLights": true}, "materials": []})", "l.json");
  EXPECT_EQ(inLighting.areaLights, std::optional<bool>(true));
  EXPECT_THROW(
      ParseManifest(R"({"areaLights": true, "lighting": {"areaLights": false}})", "x.json"),
      InputError);
}

// With area lights, a material with a sheen layer adds ltc_sheen over the
// sheen roughness used (one table, as sheen_E); without a sheen, or without
// area lights, it is left out and the plan says why.
TEST(Plan, AreaLightsAddTheSheenLtcWhereAMaterialHasSheen) {
  const Manifest m = ParseManifest(
      R"({"areaLights": true, "materials": [
            {"name": "velvet", "roughness": 0.5, "sheenRoughness": {"min": 0.3, "max": 0.7}},
            {"name": "floor", "roughness": 0.4}]})",
      "sheen_area.json");
  PlanOptions options;
  options.areaLights = m.areaLights;
  const BakePlan plan = MakePlan(m.materials, options);
  const PlannedTable *sheen = Find(plan, "ltc_sheen");
  ASSERT_NE(sheen, nullptr);
  EXPECT_DOUBLE_EQ(sheen->roughness.min, 0.3);
  EXPECT_DOUBLE_EQ(sheen->roughness.max, 0.7);
  EXPECT_EQ(sheen->materials, std::vector<std::string>{"velvet"});
  EXPECT_EQ(sheen->y.name, "sheenRoughness");
  EXPECT_NE(Find(plan, "ltc_ggx"), nullptr);
  EXPECT_NE(Find(plan, "sheen_E"), nullptr);
  EXPECT_NE(PlanJson(plan).find("\"sheenRoughness\""), std::string::npos);

  EXPECT_EQ(Find(MakePlan(m.materials, PlanOptions{}), "ltc_sheen"), nullptr);
  EXPECT_NE(Omitted(MakePlan(m.materials, PlanOptions{}), "ltc_sheen").find("areaLights"),
            std::string::npos);
  const Manifest plain = ParseManifest(
      R"({"areaLights": true, "materials": [{"name": "floor", "roughness": 0.4}]})", "p.json");
  const BakePlan noSheen = MakePlan(plain.materials, options);
  EXPECT_EQ(Find(noSheen, "ltc_sheen"), nullptr);
  EXPECT_NE(Omitted(noSheen, "ltc_sheen").find("no material has a sheen layer"), std::string::npos);
}

TEST(Plan, NothingNeededIsSaidSo) {
  for (const char *scene : {"unlit.gltf", "no_lobe.gltf"}) {
    const BakePlan plan = PlanOf({kPlans + scene});
    EXPECT_TRUE(plan.empty()) << scene;
    // E, Eavg, Favg, dfg, sheen_E (issue 14), glass_E, glass_Eavg, f82,
    // spec_E and spec_Eavg (issue 15), ltc_ggx and ltc_sheen (issue 28).
    EXPECT_EQ(plan.omitted.size(), 12u) << scene;
    for (const char *name : {"glass_E", "f82", "spec_E", "spec_Eavg"})
      EXPECT_NE(Omitted(plan, name).find("unlit or has no specular lobe"), std::string::npos)
          << name;
    EXPECT_NE(Omitted(plan, "E").find("unlit or has no specular lobe"), std::string::npos);
    EXPECT_NE(Omitted(plan, "sheen_E").find("unlit or has no specular lobe"), std::string::npos);
    EXPECT_NE(Omitted(plan, "ltc_ggx").find("unlit or has no specular lobe"), std::string::npos);
  }
}

TEST(Plan, OtherFresnelModelsGetTablesOverTheirIors) {
  const Manifest m = ReadManifest(kPlans + "dielectric.json");
  PlanOptions options;
  options.defaultIbl = m.ibl;
  options.defaultCompensation = m.compensation;
  const BakePlan plan = MakePlan(m.materials, options);
  const PlannedTable *dielectric = Find(plan, "Favg_dielectric");
  const PlannedTable *conductor = Find(plan, "Favg_conductor");
  ASSERT_NE(dielectric, nullptr);
  ASSERT_NE(conductor, nullptr);
  EXPECT_EQ(dielectric->x.nodes, (std::vector<double>{1.33, 1.5}));
  EXPECT_EQ(dielectric->materials, (std::vector<std::string>{"water", "glass"}));
  EXPECT_EQ(conductor->x.nodes, std::vector<double>{0.47});
  EXPECT_EQ(conductor->y.nodes, std::vector<double>{2.83});
  // gold has ibl false; plastic has compensation false.
  EXPECT_EQ(Find(plan, "dfg")->roughness.values, (std::vector<double>{0.1, 0.3, 0.5}));
  EXPECT_EQ(Find(plan, "E")->roughness.min, 0.1);
  EXPECT_EQ(Find(plan, "E")->roughness.max, 0.4);
  EXPECT_EQ(Find(plan, "E")->materials, (std::vector<std::string>{"water", "glass", "gold"}));
  EXPECT_FALSE(plan.schlickFavgFunction);
}

// A manifest's coats: spec_E and spec_Eavg over the coat roughness and a
// listed eta axis at exactly the coat IORs, both sides (1.5 and 1.33 from
// outside, 1/1.5 and 1/1.33 from the base beneath); the coat is also a
// specular layer of E, Eavg and dfg.
TEST(Plan, CoatsGetSpecularAlbedoAtExactlyTheirIorsBothSides) {
  const Manifest m = ReadManifest(kPlans + "coat.json");
  const BakePlan plan = MakePlan(m.materials, {});
  const std::vector<double> etas{1 / 1.5, 1 / 1.33, 1.33, 1.5};
  const PlannedTable *e = Find(plan, "spec_E"), *average = Find(plan, "spec_Eavg");
  ASSERT_NE(e, nullptr);
  ASSERT_NE(average, nullptr);
  EXPECT_EQ(e->definition, &TableNamed("spec_E"));
  EXPECT_EQ(e->etas, etas);
  EXPECT_EQ(e->x.name, "mu");
  EXPECT_EQ(e->x.count, 32);
  EXPECT_EQ(e->y.nodes, std::vector<double>{0.1});  // both coats at 0.1
  EXPECT_TRUE(e->z.listed());
  EXPECT_EQ(e->z.name, "eta");
  EXPECT_EQ(e->z.nodes, etas);
  EXPECT_EQ(average->x.nodes, std::vector<double>{0.1});
  EXPECT_TRUE(average->y.listed());
  EXPECT_EQ(average->y.nodes, etas);
  EXPECT_EQ(e->materials, (std::vector<std::string>{"car paint", "lacquered wood"}));
  EXPECT_EQ(average->materials, e->materials);
  EXPECT_EQ(Find(plan, "E")->roughness.values, (std::vector<double>{0.1, 0.3, 0.4, 0.6}));
  EXPECT_EQ(Find(plan, "dfg")->roughness.values, (std::vector<double>{0.1, 0.3, 0.4, 0.6}));
  EXPECT_EQ(Omitted(plan, "spec_E"), "");

  // Layering is part of energy compensation: off with it, and said why.
  PlanOptions off;
  off.compensation = false;
  const BakePlan none = MakePlan(m.materials, off);
  EXPECT_EQ(Find(none, "spec_E"), nullptr);
  EXPECT_EQ(Omitted(none, "spec_Eavg"),
            "energy compensation (and with it energy-conserving layering) is off "
            "(--no-compensation)");
  std::vector<MaterialSpec> own{m.materials[0], m.materials[2]};
  own[0].compensation = false;
  EXPECT_EQ(Omitted(MakePlan(own, {}), "spec_E"),
            "energy compensation (and with it energy-conserving layering) is off for every "
            "material with a coat (each sets it false)");
  const BakePlan bare = MakePlan({m.materials[2]}, {});
  EXPECT_EQ(Find(bare, "spec_E"), nullptr);
  EXPECT_EQ(Omitted(bare, "spec_E"),
            "no material has a coat (KHR_materials_clearcoat with a clearcoatFactor above 0, "
            "or a manifest's \"coat\")");

  // The JSON: the listed etas, and each coated material's coat.
  const auto j = nlohmann::json::parse(PlanJson(plan));
  const auto &spec = j["tables"][j["tables"].size() - 2];
  EXPECT_EQ(spec["name"], "spec_E");
  EXPECT_EQ(spec["eta"], etas);
  EXPECT_EQ(spec["roughness"]["values"], std::vector<double>{0.1});
  EXPECT_EQ(spec["size"], (std::vector<int>{32, 1, 4}));
  EXPECT_EQ(j["tables"].back()["name"], "spec_Eavg");
  EXPECT_EQ(j["tables"].back()["size"], (std::vector<int>{1, 4}));
  EXPECT_EQ(j["materials"][0]["coat"]["eta"], (std::vector<double>{1 / 1.5, 1.5}));
  EXPECT_EQ(j["materials"][0]["coat"]["roughness"][0]["max"], 0.1);
  EXPECT_FALSE(j["materials"][2].contains("coat"));
}

// F82-tint metals: f82 (the split sum's C) over the base roughness of those
// lit by IBL, beside dfg; Favg over the F0 and tint of those compensated,
// F0 x tint as the f82 variant of Favg takes them.
TEST(Plan, F82MetalsGetTheF82TermAndTheirFavg) {
  const Manifest m = ReadManifest(kPlans + "f82.json");
  const BakePlan plan = MakePlan(m.materials, {});
  const PlannedTable *c = Find(plan, "f82");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->definition, &TableNamed("f82"));
  // brass 0.25, chrome 0.1 and 0.3; matte gold has ibl false.
  EXPECT_EQ(c->roughness.values, (std::vector<double>{0.1, 0.25, 0.3}));
  EXPECT_EQ(c->y.nodes, (std::vector<double>{0.1, 0.25, 0.3}));
  EXPECT_EQ(c->x.count, 128);  // dfg's texels
  EXPECT_EQ(c->materials, (std::vector<std::string>{"brass", "chrome"}));
  // dfg (water too) covers the same roughness: C sits at dfg's texels.
  EXPECT_EQ(Find(plan, "dfg")->y.nodes, c->y.nodes);

  // Two Fresnel models: Favg_f82 and Favg_dielectric.
  const PlannedTable *favg = Find(plan, "Favg_f82");
  ASSERT_NE(favg, nullptr);
  ASSERT_NE(Find(plan, "Favg_dielectric"), nullptr);
  EXPECT_EQ(favg->fresnel, FresnelModel::kF82);
  EXPECT_EQ(favg->x.name, "F0");
  EXPECT_EQ(favg->x.nodes, (std::vector<double>{0.55, 0.78, 0.9, 0.91}));
  // Tints 0.7, 0.8 and the range [0.5, 0.75]: linear over [0.5, 0.8] with
  // the full [0, 1] axis's spacing, ceil(32 x 0.3) = 10 texels.
  EXPECT_EQ(favg->y.name, "tint");
  EXPECT_FALSE(favg->y.listed());
  EXPECT_EQ(favg->y.min, 0.5);
  EXPECT_EQ(favg->y.max, 0.8);
  EXPECT_EQ(favg->y.count, 10);
  EXPECT_EQ(favg->materials, (std::vector<std::string>{"brass", "chrome", "matte gold"}));
  EXPECT_FALSE(plan.schlickFavgFunction);

  const auto j = nlohmann::json::parse(PlanJson(plan));
  nlohmann::json favgJson;
  for (const auto &t : j["tables"])
    if (t["name"] == "Favg_f82") favgJson = t;
  EXPECT_EQ(favgJson["fresnel"], "f82");
  EXPECT_EQ(favgJson["F0"]["values"], (std::vector<double>{0.55, 0.78, 0.9, 0.91}));
  EXPECT_EQ(favgJson["tint"]["min"], 0.5);
  EXPECT_FALSE(favgJson["tint"].contains("values"));
  // One F0 and one tint: the material's F_avg, 20/21 F0 + 1/21 - a / 126
  // with a = Schlick(F0, 1/7) (1 - tint) / ((1/7) (6/7)^6).
  const auto &gold = j["materials"][2];
  const double schlick = 0.9 + 0.1 * std::pow(6.0 / 7.0, 5);
  const double a = schlick * (1.0 - 0.8) / (std::pow(6.0 / 7.0, 6) / 7.0);
  EXPECT_EQ(gold["F0"], 0.9);
  EXPECT_EQ(gold["tint"], 0.8);
  EXPECT_NEAR(gold["Favg"].get<double>(), 0.9 * 20.0 / 21.0 + 1.0 / 21.0 - a / 126.0, 1e-15);
  EXPECT_FALSE(j["materials"][0].contains("Favg"));  // brass: two F0

  // Without IBL: no f82, and why; without F82 metals: why not.
  PlanOptions noIbl;
  noIbl.ibl = false;
  EXPECT_EQ(Find(MakePlan(m.materials, noIbl), "f82"), nullptr);
  EXPECT_EQ(Omitted(MakePlan(m.materials, noIbl), "f82"), "image-based lighting is off (--no-ibl)");
  std::vector<MaterialSpec> noIblMetal{m.materials[2], m.materials[3]};
  EXPECT_EQ(Omitted(MakePlan(noIblMetal, {}), "f82"),
            "image-based lighting is off for every material with the F82-tint Fresnel (each "
            "sets it false)");
  EXPECT_NE(Omitted(MakePlan({m.materials[3]}, {}), "f82").find("no material uses the F82-tint"),
            std::string::npos);
}

TEST(Plan, VariantsOfOneTableGetSuffixes) {
  const Manifest m = ReadManifest(kPlans + "models.json");
  const BakePlan plan = MakePlan(m.materials, {});
  for (const char *name : {"E", "Eavg", "dfg", "E_beckmann", "Eavg_beckmann", "dfg_beckmann",
                           "E_separable", "Eavg_separable", "dfg_separable"})
    EXPECT_NE(Find(plan, name), nullptr) << name;
  EXPECT_EQ(Find(plan, "E_beckmann")->ndf, NdfKind::kBeckmann);
  EXPECT_EQ(Find(plan, "E_separable")->smith, SmithForm::kSeparable);
  EXPECT_EQ(Find(plan, "E")->roughness.values, std::vector<double>{0.6});
  // One variant alone keeps the plain name.
  std::vector<MaterialSpec> beckmannOnly{m.materials[1]};
  EXPECT_EQ(MakePlan(beckmannOnly, {}).tables.at(0).name, "E");
}

TEST(Plan, UnsupportedFeaturesAreListedAndTheRestPlanned) {
  const BakePlan plan = PlanOf({kPlans + "unsupported.gltf"});
  // KHR_materials_sheen is baked now (sheen_E, issue 14), and so are
  // KHR_materials_transmission and _volume (glass_E, issue 15): two remain.
  ASSERT_EQ(plan.unsupported.size(), 2u);
  EXPECT_EQ(plan.unsupported[0].material, "brushed");
  EXPECT_EQ(plan.unsupported[0].feature, "KHR_materials_anisotropy");
  ASSERT_NE(Find(plan, "glass_E"), nullptr);
  EXPECT_EQ(Find(plan, "glass_E")->etas, (std::vector<double>{1 / 1.5, 1.5}));
  EXPECT_EQ(Find(plan, "glass_E")->roughness.values, std::vector<double>{0.05});
  EXPECT_EQ(Find(plan, "glass_E")->materials, std::vector<std::string>{"glass"});
  ASSERT_NE(Find(plan, "sheen_E"), nullptr);
  EXPECT_EQ(Find(plan, "sheen_E")->roughness.values, std::vector<double>{0.3});
  EXPECT_EQ(Find(plan, "sheen_E")->materials, std::vector<std::string>{"velvet"});
  EXPECT_EQ(Find(plan, "E")->roughness.values, (std::vector<double>{0.0, 0.05, 0.1, 0.35, 0.8}));
}

TEST(Plan, SeveralScenesAreTheirUnion) {
  const BakePlan plan = PlanOf({kPlans + "listed.gltf", kPlans + "textured.gltf"});
  // {0.25, 0.5} and [0, 0.5] with 0.3: the hull [0, 0.5].
  EXPECT_EQ(Find(plan, "E")->roughness.min, 0.0);
  EXPECT_EQ(Find(plan, "E")->roughness.max, 0.5);
  EXPECT_EQ(Find(plan, "E")->materials.size(), 5u);
}

// A narrowed axis [0, 0.5] with half the rows puts its texel centres on the
// full table's rows 0..N/2-1 exactly (0.5 (i + 0.5) / 16 = (i + 0.5) / 32 in
// binary floating point), and each texel is seeded from its coordinates: the
// narrowed table must equal the full one there, bit for bit, sampled.
TEST(PlanBake, NarrowedTableEqualsTheFullTableOnSharedTexels) {
  const BakePlan plan = PlanOf({kPlans + "textured.gltf"}, [] {
    PlanOptions o;
    o.tableSizes = {{"dfg", 16}};
    return o;
  }());
  BakeSettings s;
  s.samples = 1024;
  s.tableSizes = {{"E", 32}, {"Eavg", 32}, {"dfg", 16}};
  for (const PlannedTable &t : plan.tables) {
    const Table narrow = BakeTableOn(*t.definition, PlannedSettings(t, s), t.x, t.y);
    const Table full = BakeTable(*t.definition, s);
    const bool average = t.definition == &TableNamed("Eavg");
    const int rows = average ? narrow.width() : narrow.height();
    ASSERT_EQ(rows * 2, average ? full.width() : full.height()) << t.name;
    for (int r = 0; r < rows; ++r)
      for (int x = 0; x < (average ? 1 : narrow.width()); ++x)
        for (int c = 0; c < narrow.channels; ++c) {
          const size_t a = average ? narrow.index(r, 0, c) : narrow.index(x, r, c);
          const size_t b = average ? full.index(r, 0, c) : full.index(x, r, c);
          ASSERT_EQ(narrow.values[a], full.values[b]) << t.name << " row " << r << " x " << x;
          ASSERT_EQ(narrow.errors[a], full.errors[b]);
        }
  }
}

// Listed rows sit at exactly the materials' roughness: each texel against
// the quadrature at that (mu, r), within its own bound and the quadrature's.
TEST(PlanBake, ListedRowsMatchTheQuadratureWithinTheirBounds) {
  const BakePlan plan = PlanOf({kPlans + "listed.gltf"}, [] {
    PlanOptions o;
    o.tableSizes = {{"dfg", 16}, {"E", 16}};
    return o;
  }());
  BakeSettings s;
  s.samples = 4096;
  s.tableSizes = {{"dfg", 16}, {"E", 16}};
  BakeSettings reference = s;
  reference.estimator = Estimator::kQuadrature;
  for (const PlannedTable &t : plan.tables) {
    const Table table = BakeTableOn(*t.definition, PlannedSettings(t, s), t.x, t.y);
    double worst = 0.0;
    for (int y = 0; y < table.height(); ++y)
      for (int x = 0; x < table.width(); ++x) {
        PointValue truth;
        if (t.definition == &TableNamed("Eavg")) {
          const double r = table.x.TexelCenter(x);
          truth = EvaluateAlbedoAverage(reference, r * r, 0);
        } else {
          const double r = table.y.TexelCenter(y);
          truth = EvaluateAlbedo(*t.definition, reference, table.x.TexelCenter(x), r * r, 0);
        }
        for (int c = 0; c < table.channels; ++c) {
          const size_t i = table.index(x, y, c);
          const double diff = std::abs(table.values[i] - truth.value[c]);
          worst = std::max(worst, diff);
          // Each texel's 99% bound; the few texels that may exceed it are
          // not expected at this size (checked loosely: 2x).
          EXPECT_LE(diff, 2.0 * table.errors[i] + truth.error[c]) << t.name << " " << x << "," << y;
        }
      }
    EXPECT_LE(worst, table.MaxError() + 1e-9) << t.name;
  }
}

// lutbake::Plan over scenes and a manifest, as `lutbake plan --json` and
// `lutbake plan` print it (PlanJson, DescribePlan).
TEST(Plan, JsonHasTheDocumentedShape) {
  PlanRequest request;
  request.scenes = {kPlans + "listed.gltf", kPlans + "unsupported.gltf"};
  request.manifests = {kPlans + "no_ibl.json"};
  const auto j = nlohmann::json::parse(PlanJson(Plan(request)));
  ASSERT_TRUE(j["tables"].is_array());
  // E, Eavg; sheen_E for unsupported.gltf's velvet (issue 14); glass_E and
  // glass_Eavg for its glass (issue 15).
  ASSERT_EQ(j["tables"].size(), 5u);
  EXPECT_EQ(j["tables"][2]["name"], "sheen_E");
  EXPECT_EQ(j["tables"][2]["sheenRoughness"]["values"], (std::vector<double>{0.3}));
  EXPECT_EQ(j["tables"][3]["name"], "glass_E");
  EXPECT_EQ(j["tables"][3]["eta"], (std::vector<double>{1 / 1.5, 1.5}));
  EXPECT_EQ(j["tables"][3]["size"], (std::vector<int>{32, 1, 2}));
  EXPECT_EQ(j["tables"][4]["name"], "glass_Eavg");
  EXPECT_EQ(j["tables"][0]["name"], "E");
  EXPECT_EQ(j["tables"][0]["roughness"]["min"], 0.0);
  EXPECT_EQ(j["tables"][0]["roughness"]["max"], 0.8);
  EXPECT_EQ(j["tables"][0]["roughness"]["values"],
            (std::vector<double>{0.0, 0.05, 0.1, 0.25, 0.35, 0.5, 0.8}));
  EXPECT_EQ(j["tables"][1]["name"], "Eavg");
  EXPECT_TRUE(j["tables"][0]["materials"].is_array());
  std::vector<std::string> omitted;
  for (const auto &o : j["omitted"]) {
    omitted.push_back(o["name"]);
    EXPECT_FALSE(o["reason"].get<std::string>().empty());
  }
  // No F82 metal, no coat, no area lights.
  EXPECT_EQ(omitted, (std::vector<std::string>{"Favg", "dfg", "f82", "spec_E", "spec_Eavg",
                                               "ltc_ggx", "ltc_sheen"}));
  // Transmission and volume are baked now (issue 15): anisotropy and
  // iridescence remain.
  ASSERT_EQ(j["unsupported"].size(), 2u);
  EXPECT_EQ(j["unsupported"][0]["material"], "brushed");
  EXPECT_EQ(j["unsupported"][0]["feature"], "KHR_materials_anisotropy");
  // Per-material Schlick constants: F_avg = 20/21 F0 + 1/21 F90 with glTF's F0 = 0.04.
  const auto &paint = j["materials"][0];
  EXPECT_EQ(paint["name"], "paint");
  EXPECT_NEAR(paint["Favg"][0].get<double>(), 0.04 * 20.0 / 21.0 + 1.0 / 21.0, 1e-16);

  PlanRequest textured;
  textured.scenes = {kPlans + "textured.gltf"};
  const std::string human = DescribePlan(Plan(textured));
  EXPECT_NE(human.find("perceptualRoughness linear [0, 0.5] (16 texels)"), std::string::npos)
      << human;
  EXPECT_NE(human.find("left out:"), std::string::npos);
}

TEST(PlanBake, WritesExactlyThePlanAndChecks) {
  const fs::path out = Scratch("plan_bake");
  BakeRequest request = test::BakeRequestFor(out);  // --scene listed.glb --size 16 --samples 4096
  request.scenes = {kPlans + "listed.glb"};
  request.size = 16;
  request.sampling.samples = 4096;
  Bake(request);
  EXPECT_EQ(test::FileNames(out),
            (std::vector<std::string>{"E.bin", "E.exr", "E.h", "Eavg.bin", "Eavg.exr", "Eavg.h",
                                      "Favg.h", "dfg.bin", "dfg.exr", "dfg.h", "kulla_conty.h",
                                      "lutbake-set.json"}));
  const Table e = ReadExrTable((out / "E.exr").string());
  EXPECT_TRUE(e.y.listed());
  EXPECT_EQ(e.y.nodes, (std::vector<double>{0.25, 0.5}));
  ASSERT_NE(e.FindMetadata("planMaterials"), nullptr);
  EXPECT_EQ(*e.FindMetadata("planMaterials"), "paint, steel, steel copy");
  const Table bin = ReadBinaryTable((out / "dfg.bin").string());
  EXPECT_EQ(bin.y.nodes, (std::vector<double>{0.25, 0.5}));
  // CheckBakedSet reads the listed axes and passes the set (check --points 64
  // --furnace-grid 33).
  CheckOptions options;
  options.randomPoints = 64;
  options.furnaceGrid = 33;
  const CheckReport check = CheckBakedSet(out.string(), options);
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  EXPECT_TRUE(std::any_of(check.results.begin(), check.results.end(), [](const CheckResult &c) {
    return c.check == "closed form";
  })) << test::Describe(check);

  // The headers: lookups take the roughness a shader has; at a listed value
  // (as a float) they return that row exactly; Favg.h is the closed form.
  std::string checks;
  char line[256];
  for (int y = 0; y < e.height(); ++y)
    for (int x = 0; x < e.width(); ++x) {
      std::snprintf(line, sizeof line, "  fail += lutbake_luts::lookup_E(%.9gf, %.9gf) != %.9gf;\n",
                    static_cast<float>(e.x.TexelCenter(x)), static_cast<float>(e.y.nodes[y]),
                    static_cast<float>(e.value(x, y)));
      checks += line;
    }
  // Halfway between the rows: the average of the rows (linear in r).
  std::snprintf(line, sizeof line,
                "  fail += std::fabs(lutbake_luts::lookup_E(%.9gf, 0.375f) - %.9gf) > 1e-6f;\n",
                static_cast<float>(e.x.TexelCenter(3)), 0.5 * (e.value(3, 0) + e.value(3, 1)));
  checks += line;
  checks += "  fail += lutbake_luts::lookup_E(0.5f, 0.9f) != lutbake_luts::lookup_E(0.5f, 0.5f);\n";
  checks +=
      "  fail += std::fabs(lutbake_luts::lookup_Favg(0.04f) - (0.04f * 20.0f + 1.0f) / "
      "21.0f) > 1e-7f;\n";
  std::ofstream(out / "main.cpp")
      << "#include <cmath>\n#include <cstdio>\n#include \"E.h\"\n"
         "#include \"Eavg.h\"\n#include \"Favg.h\"\n#include \"dfg.h\"\n"
         "int main() {\n  int fail = 0;\n"
      << checks
      << "  std::printf(\"%d failures\\n\", fail);\n"
         "  return fail == 0 ? 0 : 1;\n}\n";
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(out, "c++17");
  fs::remove_all(out);
}

// Two manifests needing GGX, Beckmann and separable variants and both
// exact Fresnel models: every variant is written under its own name, lutbake
// check checks each set, and all headers compile together in one program.
TEST(PlanBake, VariantsBakeCheckAndCompileTogether) {
  const fs::path out = Scratch("plan_variants");
  BakeRequest request = test::BakeRequestFor(out);
  request.manifests = {kPlans + "models.json", kPlans + "dielectric.json"};
  request.size = 8;
  request.sampling.tolerance = 1e-5;
  Bake(request);
  std::string includes;
  size_t headers = 0;
  for (const auto &e : fs::directory_iterator(out))
    if (e.path().extension() == ".h") {
      includes += "#include \"" + e.path().filename().string() + "\"\n";
      ++headers;
    }
  // 3 x (E, Eavg, dfg, kulla_conty) + Favg_dielectric + Favg_conductor
  EXPECT_EQ(headers, 14u);
  CheckOptions options;  // check --points 16 --furnace-grid 17
  options.randomPoints = 16;
  options.furnaceGrid = 17;
  const CheckReport check = CheckBakedSet(out.string(), options);
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  for (const std::string subject :
       {"E_beckmann", "dfg_separable", "Favg_conductor", "E+Eavg_beckmann"})
    EXPECT_TRUE(std::any_of(check.results.begin(), check.results.end(),
                            [&](const CheckResult &c) { return c.subject == subject; }))
        << subject << "\n"
        << test::Describe(check);
  std::ofstream(out / "main.cpp")
      << includes
      << "int main() {\n"
         "  const float a = lutbake_luts::lookup_E_beckmann(0.5f, 0.3f);\n"
         "  const float b = lutbake_luts::lookup_dfg_separable(0.5f, 0.2f)[0];\n"
         "  const float c = lutbake_luts::lookup_Favg_dielectric(1.5f);\n"
         "  const float d = lutbake_luts::lookup_Favg_conductor(0.47f, 2.83f);\n"
         "  const float e = lutbake_luts::f_ms_beckmann(0.5f, 0.5f, 0.3f);\n"
         "  return a > 0.0f && b > 0.0f && c > 0.0f && d > 0.0f && e > 0.0f ? 0 : 1;\n}\n";
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(out, "c++17");
  fs::remove_all(out);
}

// --tables with a scene selects among the planned tables (what
// lutbake_add_luts(TABLES ... SCENE ...) passes), and a table the plan
// leaves out stops the bake with the plan's reason and writes nothing.
TEST(PlanBake, TablesSelectAmongThePlannedOnes) {
  const fs::path out = Scratch("plan_tables");
  BakeRequest request = test::BakeRequestFor(out);
  request.scenes = {kPlans + "listed.gltf"};
  request.tables = {"E", "Eavg"};
  request.formats = {"header"};
  request.size = 8;
  request.sampling.samples = 256;
  Bake(request);
  EXPECT_EQ(test::FileNames(out),
            (std::vector<std::string>{"E.h", "Eavg.h", "kulla_conty.h", "lutbake-set.json"}));
  const HeaderValues e = ReadHeaderValues((out / "E.h").string());
  EXPECT_EQ(e.height, 2);  // the scene's two listed roughness values
  fs::remove_all(out);

  // --no-ibl --tables E,dfg: a runtime failure (exit status 1) naming dfg.
  request.noIbl = true;
  request.tables = {"E", "dfg"};
  request.formats.reset();
  const std::optional<Error> refused = test::BakeError(request);
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->kind(), Error::Kind::kRuntime) << refused->what();
  const std::string message = refused->what();
  EXPECT_NE(message.find("  dfg: "), std::string::npos) << message;
  EXPECT_EQ(message.find("  E: "), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(out));
}

TEST(PlanBake, UnsupportedStopsTheBakeUnlessSkipped) {
  const fs::path out = Scratch("plan_unsupported");
  BakeRequest request = test::BakeRequestFor(out);
  request.scenes = {kPlans + "unsupported.gltf"};
  request.size = 4;
  request.sampling.samples = 64;
  const std::optional<Error> stop = test::BakeError(request);
  ASSERT_TRUE(stop.has_value());
  EXPECT_EQ(stop->kind(), Error::Kind::kRuntime) << stop->what();  // exit status 1
  EXPECT_NE(std::string(stop->what()).find("brushed: KHR_materials_anisotropy"), std::string::npos)
      << stop->what();
  EXPECT_FALSE(fs::exists(out));
  request.skipUnsupported = true;
  request.formats = {"exr"};
  Bake(request);
  EXPECT_TRUE(fs::exists(out / "E.exr"));
  fs::remove_all(out);
}

// A plan that needs nothing: Bake says so (the command line prints "the plan
// needs no tables", tests/cli/bake_cli_test.cpp) and creates nothing.
TEST(PlanBake, NothingNeededBakesNothing) {
  const fs::path out = Scratch("plan_nothing");
  BakeRequest request = test::BakeRequestFor(out);
  request.scenes = {kPlans + "unlit.gltf"};
  const BakeResult result = Bake(request);
  EXPECT_TRUE(result.planNeedsNothing);
  EXPECT_FALSE(result.nothingToBake.empty());
  EXPECT_TRUE(result.files.empty());
  EXPECT_FALSE(fs::exists(out));
}

TEST(Plan, CarriesABakeEstimateOnlyWhenAsked) {
  PlanRequest request;
  request.scenes = {kPlans + "listed.gltf", kPlans + "glass.gltf"};
  const BakePlan plain = Plan(request);
  EXPECT_FALSE(plain.estimate.has_value());
  EXPECT_FALSE(nlohmann::json::parse(PlanJson(plain)).contains("estimate"));
  request.estimate = true;
  const BakePlan timed = Plan(request);
  ASSERT_TRUE(timed.estimate.has_value());
  size_t texels = 0;
  for (const PlannedTable &t : timed.tables)
    texels += static_cast<size_t>(t.x.count) * t.y.count * t.z.count;
  EXPECT_EQ(timed.estimate->texels, texels);
  const auto j = nlohmann::json::parse(PlanJson(timed));
  EXPECT_EQ(j["estimate"]["texels"].get<size_t>(), texels);
  EXPECT_NE(DescribePlan(timed).find("estimated bake: "), std::string::npos);
}

}  // namespace
}  // namespace lutbake
