// Manifest reading: the documented keys, and every kind of mistake refused
// with the file, the JSON pointer and what is accepted.
#include "lutbake/plans/manifest.h"

#include <gtest/gtest.h>

namespace lutbake {
namespace {

const std::string kPlans = std::string(LUTBAKE_TEST_DATA) + "/plans/";

std::string ErrorOf(const std::string &text) {
  try {
    ParseManifest(text, "inline.json");
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

TEST(Manifest, ReadsMaterialsAndLighting) {
  const Manifest m = ReadManifest(kPlans + "dielectric.json");
  EXPECT_EQ(m.ibl, std::optional<bool>(true));
  EXPECT_EQ(m.compensation, std::optional<bool>(true));
  ASSERT_EQ(m.materials.size(), 4u);
  const MaterialSpec &water = m.materials[0];
  EXPECT_EQ(water.name, "water");
  ASSERT_EQ(water.roughness.size(), 2u);  // a list: two exact uses
  EXPECT_EQ(water.roughness[0].min, 0.1);
  EXPECT_EQ(water.roughness[1].max, 0.3);
  EXPECT_EQ(water.fresnel.model, FresnelModel::kDielectric);
  EXPECT_EQ(water.fresnel.eta.values, std::vector<double>{1.33});
  const MaterialSpec &gold = m.materials[2];
  EXPECT_EQ(gold.roughness.at(0).min, 0.2);  // a range
  EXPECT_EQ(gold.roughness.at(0).max, 0.4);
  EXPECT_EQ(gold.fresnel.model, FresnelModel::kConductor);
  EXPECT_EQ(gold.fresnel.k.values, std::vector<double>{2.83});
  EXPECT_EQ(gold.ibl, std::optional<bool>(false));
  EXPECT_FALSE(gold.compensation.has_value());
  EXPECT_EQ(m.materials[3].compensation, std::optional<bool>(false));

  const Manifest models = ReadManifest(kPlans + "models.json");
  EXPECT_EQ(models.materials.at(1).ndf, NdfKind::kBeckmann);
  EXPECT_EQ(models.materials.at(2).smith, SmithForm::kSeparable);
  EXPECT_FALSE(models.ibl.has_value());
}

TEST(Manifest, ReadsCoats) {
  const Manifest m = ReadManifest(kPlans + "coat.json");
  ASSERT_EQ(m.materials.size(), 3u);
  const MaterialSpec &paint = m.materials[0];
  // eta 1.5 seen from outside, 1 / 1.5 from the base beneath, in order.
  EXPECT_EQ(paint.coatEta, (std::vector<double>{1 / 1.5, 1.5}));
  ASSERT_EQ(paint.coatRoughness.size(), 1u);
  EXPECT_EQ(paint.coatRoughness[0].layer, "coat");
  EXPECT_EQ(paint.coatRoughness[0].min, 0.1);
  EXPECT_EQ(paint.coatRoughness[0].max, 0.1);
  // The coat is a specular layer of the material too, after the base.
  ASSERT_EQ(paint.roughness.size(), 2u);
  EXPECT_EQ(paint.roughness[0].layer, "base");
  EXPECT_EQ(paint.roughness[0].min, 0.4);
  EXPECT_EQ(paint.roughness[1].layer, "coat");
  EXPECT_EQ(paint.roughness[1].min, 0.1);
  EXPECT_EQ(paint.fresnel.model, FresnelModel::kSchlick);
  EXPECT_EQ(m.materials[1].coatEta, (std::vector<double>{1 / 1.5, 1 / 1.33, 1.33, 1.5}));
  EXPECT_EQ(m.materials[1].fresnel.eta.values, std::vector<double>{1.5});  // the base's
  EXPECT_TRUE(m.materials[2].coatEta.empty());
  EXPECT_TRUE(m.materials[2].coatRoughness.empty());

  // A range of coat roughness; eta 1 is its own inverse; a coat roughness
  // below 1e-12 is the mirror, with a note.
  const Manifest r = ParseManifest(
      R"({"materials": [{"roughness": 0.5, "coat": {"eta": 1, "roughness": {"min": 1e-13, "max": 0.3}}}]})",
      "inline.json");
  const MaterialSpec &coat = r.materials.at(0);
  EXPECT_EQ(coat.coatEta, std::vector<double>{1.0});
  ASSERT_EQ(coat.coatRoughness.size(), 1u);
  EXPECT_EQ(coat.coatRoughness[0].min, 0.0);
  EXPECT_EQ(coat.coatRoughness[0].max, 0.3);
  ASSERT_EQ(coat.notes.size(), 1u);
  EXPECT_EQ(coat.notes[0], "coat roughness 1e-13 is below 1e-12: baked as the mirror, r = 0");
}

TEST(Manifest, ReadsF82Metals) {
  const Manifest m = ReadManifest(kPlans + "f82.json");
  ASSERT_EQ(m.materials.size(), 4u);
  const MaterialSpec &brass = m.materials[0];
  EXPECT_EQ(brass.fresnel.model, FresnelModel::kF82);
  EXPECT_EQ(brass.fresnel.f0.values, (std::vector<double>{0.91, 0.78}));
  EXPECT_EQ(brass.fresnel.tint.values, std::vector<double>{0.7});
  EXPECT_TRUE(brass.fresnel.eta.values.empty());  // no IOR
  const MaterialSpec &chrome = m.materials[1];
  EXPECT_EQ(chrome.fresnel.f0.values, std::vector<double>{0.55});
  EXPECT_TRUE(chrome.fresnel.tint.range());
  EXPECT_EQ(chrome.fresnel.tint.min, 0.5);
  EXPECT_EQ(chrome.fresnel.tint.max, 0.75);
  EXPECT_EQ(m.materials[2].ibl, std::optional<bool>(false));
}

TEST(Manifest, MistakesNameTheirPlace) {
  const auto has = [](const std::string &message, const std::string &fragment) {
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  };
  has(ErrorOf(R"({"materials": [{"roughness": 0.5, "roughnes": 0.4}]})"),
      "inline.json: /materials/0/roughnes: unknown key \"roughnes\"; accepted here: name");
  has(ErrorOf(R"({"lighting": {"ibl": "yes"}})"), "/lighting/ibl: expected true or false");
  has(ErrorOf(R"({"lighting": {"shadows": true}})"), "/lighting/shadows: unknown key");
  has(ErrorOf(R"({"scenes": []})"), "/scenes: unknown key");
  has(ErrorOf(R"({"materials": [{"name": "x"}]})"), "/materials/0: no \"roughness\"");
  has(ErrorOf(R"({"materials": [{"roughness": 7}]})"), "/materials/0/roughness: 7 is outside");
  has(ErrorOf(R"({"materials": [{"roughness": [0.1, "a"]}]})"),
      "/materials/0/roughness/1: expected a number");
  has(ErrorOf(R"({"materials": [{"roughness": []}]})"), "an empty list");
  has(ErrorOf(R"({"materials": [{"roughness": {"min": 0.1}}]})"), "both \"min\" and \"max\"");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "ndf": "phong"}]})"),
      "/materials/0/ndf: \"phong\" is not an NDF; accepted: ggx, beckmann");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "smith": "uncorrelated"}]})"),
      "accepted: correlated, separable");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "cook"}}]})"),
      "/materials/0/fresnel/model");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "dielectric"}}]})"),
      "a dielectric needs \"eta\"");
  has(ErrorOf(
          R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "conductor", "eta": 1}}]})"),
      "a conductor needs");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "schlick", "eta": 1}}]})"),
      "/materials/0/fresnel/eta: unknown key");
  // Coats: eta listed (spec_E's eta axis lists exactly the coat IORs), never a range.
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": {"eta": {"min": 1.3, "max": 1.6},
                                                                "roughness": 0.1}}]})"),
      "inline.json: /materials/0/coat/eta: a range is not accepted for a coat: spec_E is baked "
      "at exactly the coat IORs used (a listed eta axis, eta and 1 / eta), so give a number or a "
      "list of numbers");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": {"eta": 1.5}}]})"),
      "/materials/0/coat: a coat needs \"eta\"");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": {"ior": 1.5, "roughness": 0}}]})"),
      "/materials/0/coat/ior: unknown key \"ior\"; accepted here: eta, roughness");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": {"eta": 0, "roughness": 0}}]})"),
      "/materials/0/coat/eta: 0 is outside the accepted range [0.001, 10]");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": {"eta": [1.5], "roughness": 2}}]})"),
      "/materials/0/coat/roughness: 2 is outside");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "coat": 1.5}]})"),
      "/materials/0/coat: expected an object");
  // F82 tint: f0 and tint, each in [0, 1].
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "f82", "f0": 0.9}}]})"),
      "/materials/0/fresnel: an F82-tint metal needs \"f0\" and \"tint\"");
  has(ErrorOf(
          R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "f82", "f0": 0.9, "tint": 1.5}}]})"),
      "/materials/0/fresnel/tint: 1.5 is outside the accepted range [0, 1]");
  has(ErrorOf(
          R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "f82", "f0": 0.9, "tint": 1, "eta": 1}}]})"),
      "/materials/0/fresnel/eta: unknown key \"eta\"; accepted here: model, f0, tint");
  has(ErrorOf(R"({"materials": [{"roughness": 0.1, "fresnel": {"model": "cook"}}]})"),
      "accepted: schlick, dielectric, conductor, f82");
  has(ErrorOf(R"([1, 2])"), "expected an object");
  has(ErrorOf("{\n  \"materials\": [\n    {\"roughness\": 0.1,}\n  ]\n}"), "line 3");
  has(ErrorOf(R"({"materials": [{"roughness": NaN}]})"), "malformed JSON");
  // An unlit material needs no roughness.
  EXPECT_EQ(ErrorOf(R"({"materials": [{"name": "ui", "unlit": true}]})"), "");

  try {
    ReadManifest(kPlans + "bad_key.json");
    ADD_FAILURE() << "bad_key.json was accepted";
  } catch (const InputError &e) {
    has(e.what(), "bad_key.json: /materials/0/roughnes");
  }
  EXPECT_THROW(ReadManifest(kPlans + "missing.json"), InputError);
}

}  // namespace
}  // namespace lutbake
