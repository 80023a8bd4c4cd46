// glTF / GLB material reading: each rule of scene.h on a small scene written
// for it (tests/data/plans/), real Khronos sample scenes (tests/data/scenes/),
// and broken files, each refused with a message naming the file and where.
#include "lutbake/plans/scene.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace lutbake {
namespace {

const std::string kPlans = std::string(LUTBAKE_TEST_DATA) + "/plans/";
const std::string kScenes = std::string(LUTBAKE_TEST_DATA) + "/scenes/";

const MaterialSpec &Named(const std::vector<MaterialSpec> &ms, const std::string &name) {
  for (const MaterialSpec &m : ms)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  static const MaterialSpec none;
  return none;
}

std::string Bytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the InputError that reading `path` throws ("" if none).
std::string ErrorOf(const std::string &path) {
  try {
    ReadSceneMaterials(path);
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

TEST(SceneReader, FactorsWithoutTexturesAreExact) {
  const auto ms = ReadSceneMaterials(kPlans + "listed.gltf");
  ASSERT_EQ(ms.size(), 4u);
  const MaterialSpec &paint = Named(ms, "paint");
  ASSERT_EQ(paint.roughness.size(), 1u);
  EXPECT_EQ(paint.roughness[0].min, 0.25);
  EXPECT_EQ(paint.roughness[0].max, 0.25);
  EXPECT_EQ(paint.ndf, NdfKind::kGgx);
  EXPECT_EQ(paint.smith, SmithForm::kCorrelated);
  EXPECT_EQ(paint.fresnel.model, FresnelModel::kSchlick);
  EXPECT_EQ(paint.where, "/materials/0");
  EXPECT_TRUE(Named(ms, "sky").unlit);
  EXPECT_TRUE(Named(ms, "sky").roughness.empty());
}

TEST(SceneReader, GlbHoldsTheSameMaterialsAsGltf) {
  const auto a = ReadSceneMaterials(kPlans + "listed.gltf");
  const auto b = ReadSceneMaterials(kPlans + "listed.glb");
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].unlit, b[i].unlit);
    ASSERT_EQ(a[i].roughness.size(), b[i].roughness.size());
    for (size_t j = 0; j < a[i].roughness.size(); ++j) {
      EXPECT_EQ(a[i].roughness[j].min, b[i].roughness[j].min);
      EXPECT_EQ(a[i].roughness[j].max, b[i].roughness[j].max);
    }
  }
}

TEST(SceneReader, TextureCoversZeroToFactor) {
  const auto ms = ReadSceneMaterials(kPlans + "textured.gltf");
  const RoughnessUse &worn = Named(ms, "worn metal").roughness.at(0);
  EXPECT_EQ(worn.min, 0.0);
  EXPECT_EQ(worn.max, 0.5);
  EXPECT_TRUE(Named(ms, "plastic").roughness.at(0).exact());
}

TEST(SceneReader, ClearcoatCountsWhenItsFactorIsPositive) {
  const auto ms = ReadSceneMaterials(kPlans + "clearcoat.gltf");
  const MaterialSpec &paint = Named(ms, "car paint");
  ASSERT_EQ(paint.roughness.size(), 2u);
  EXPECT_EQ(paint.roughness[1].layer, "clearcoat");
  EXPECT_EQ(paint.roughness[1].min, 0.1);
  EXPECT_EQ(paint.roughness[1].max, 0.1);
  // The coat, a dielectric of glTF's fixed clearcoat IOR 1.5: both sides,
  // for spec_E, over its roughness alone.
  EXPECT_EQ(paint.coatEta, (std::vector<double>{1 / 1.5, 1.5}));
  ASSERT_EQ(paint.coatRoughness.size(), 1u);
  EXPECT_EQ(paint.coatRoughness[0].layer, "clearcoat");
  EXPECT_EQ(paint.coatRoughness[0].min, 0.1);
  // clearcoatFactor 0: no layer, its roughness 0.9 does not count.
  const MaterialSpec &off = Named(ms, "coat off");
  ASSERT_EQ(off.roughness.size(), 1u);
  EXPECT_EQ(off.roughness[0].layer, "base");
  EXPECT_FALSE(off.notes.empty());
  EXPECT_TRUE(off.coatEta.empty());
  EXPECT_TRUE(off.coatRoughness.empty());
  // A clearcoat roughness texture: [0, clearcoatRoughnessFactor].
  const MaterialSpec &textured = Named(ms, "textured coat");
  ASSERT_EQ(textured.roughness.size(), 2u);
  EXPECT_EQ(textured.roughness[1].min, 0.0);
  EXPECT_EQ(textured.roughness[1].max, 0.2);
  ASSERT_EQ(textured.coatRoughness.size(), 1u);
  EXPECT_EQ(textured.coatRoughness[0].min, 0.0);
  EXPECT_EQ(textured.coatRoughness[0].max, 0.2);
}

TEST(SceneReader, RecognisesWhatItCannotBake) {
  const auto ms = ReadSceneMaterials(kPlans + "unsupported.gltf");
  // KHR_materials_sheen is baked (issue 14): a sheen layer of roughness 0.3.
  EXPECT_TRUE(Named(ms, "velvet").unsupported.empty());
  ASSERT_EQ(Named(ms, "velvet").sheenRoughness.size(), 1u);
  EXPECT_EQ(Named(ms, "velvet").sheenRoughness[0].min, 0.3);
  EXPECT_EQ(Named(ms, "velvet").sheenRoughness[0].max, 0.3);
  // KHR_materials_transmission and _volume are baked (glass_E, issue 15):
  // ior 1.5 both sides, the base roughness.
  EXPECT_TRUE(Named(ms, "glass").unsupported.empty());
  EXPECT_EQ(Named(ms, "glass").transmissionEta, (std::vector<double>{1 / 1.5, 1.5}));
  ASSERT_EQ(Named(ms, "glass").transmissionRoughness.size(), 1u);
  EXPECT_EQ(Named(ms, "glass").transmissionRoughness[0].max, 0.05);
  EXPECT_EQ(Named(ms, "brushed").unsupported, std::vector<std::string>{"KHR_materials_anisotropy"});
  EXPECT_EQ(Named(ms, "soap").unsupported, std::vector<std::string>{"KHR_materials_iridescence"});
  // KHR_materials_ior and _specular only change Schlick's F0 and F90.
  const MaterialSpec &diamond = Named(ms, "diamond");
  EXPECT_TRUE(diamond.unsupported.empty());
  EXPECT_EQ(diamond.fresnel.model, FresnelModel::kSchlick);
  EXPECT_EQ(diamond.roughness.at(0).max, 0.0);
  // F0 = ((ior - 1) / (ior + 1))^2 for ior 2.42; glTF's default ior 1.5 gives 0.04.
  const double f0 = (1.42 / 3.42) * (1.42 / 3.42);
  ASSERT_EQ(diamond.fresnel.schlickF0.size(), 3u);
  EXPECT_NEAR(diamond.fresnel.schlickF0[1], f0, 1e-15);
  EXPECT_EQ(diamond.fresnel.schlickF90, 1.0);
  EXPECT_NEAR(Named(ms, "velvet").fresnel.schlickF0.at(0), 0.04, 1e-16);
  // The unsupported materials' specular lobes still need their roughness.
  EXPECT_EQ(Named(ms, "velvet").roughness.at(0).max, 0.8);
}

TEST(SceneReader, DefaultMaterialSpecularGlossinessAndNoLobe) {
  const auto d = ReadSceneMaterials(kPlans + "default_material.gltf");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1].name, "(default material)");
  EXPECT_EQ(d[1].roughness.at(0).min, 1.0);
  EXPECT_EQ(d[1].where, "/meshes/0/primitives/1");

  const auto sg = ReadSceneMaterials(kPlans + "specgloss.gltf");
  EXPECT_EQ(Named(sg, "old gloss").roughness.at(0).min, 0.25);
  EXPECT_EQ(Named(sg, "old gloss").roughness.at(0).max, 0.25);
  EXPECT_EQ(Named(sg, "old gloss textured").roughness.at(0).min, 0.5);
  EXPECT_EQ(Named(sg, "old gloss textured").roughness.at(0).max, 1.0);

  const auto chalk = ReadSceneMaterials(kPlans + "no_lobe.gltf");
  ASSERT_EQ(chalk.size(), 1u);
  EXPECT_TRUE(chalk[0].roughness.empty());
}

TEST(SceneReader, KhronosSampleScenes) {
  // CompareRoughness: a smooth logo (factor 0) and one with a texture (factor 0.5).
  const auto cr = ReadSceneMaterials(kScenes + "CompareRoughness.gltf");
  ASSERT_EQ(cr.size(), 2u);
  EXPECT_EQ(Named(cr, "glTF Logo").roughness.at(0).max, 0.0);
  EXPECT_EQ(Named(cr, "glTF Logo Roughness").roughness.at(0).min, 0.0);
  EXPECT_EQ(Named(cr, "glTF Logo Roughness").roughness.at(0).max, 0.5);
  // BoomBox: no roughnessFactor (default 1) with a texture: [0, 1].
  const auto bb = ReadSceneMaterials(kScenes + "BoomBox.gltf");
  ASSERT_EQ(bb.size(), 1u);
  EXPECT_EQ(bb[0].roughness.at(0).min, 0.0);
  EXPECT_EQ(bb[0].roughness.at(0).max, 1.0);
  // ClearCoatTest: 19 materials; coats at 0.03, and one textured at factor 1.
  const auto cc = ReadSceneMaterials(kScenes + "ClearCoatTest.gltf");
  ASSERT_EQ(cc.size(), 19u);
  EXPECT_EQ(Named(cc, "Simple_Coated").roughness.at(1).min, 0.03);
  EXPECT_EQ(Named(cc, "RoughVariations_Coated").roughness.at(1).max, 1.0);
  EXPECT_EQ(Named(cc, "RoughVariations_Coated").roughness.at(1).min, 0.0);
  // CompareSheen: a sheen layer (sheenRoughnessFactor 0.3, no roughness
  // texture), baked as sheen_E; CompareIor: transmission, baked as glass_E.
  const auto sheen = ReadSceneMaterials(kScenes + "CompareSheen.gltf");
  EXPECT_TRUE(Named(sheen, "glTF Logo Sheen").unsupported.empty());
  ASSERT_EQ(Named(sheen, "glTF Logo Sheen").sheenRoughness.size(), 1u);
  EXPECT_EQ(Named(sheen, "glTF Logo Sheen").sheenRoughness[0].max, 0.3);
  EXPECT_TRUE(Named(sheen, "glTF Logo").unsupported.empty());
  EXPECT_TRUE(Named(sheen, "glTF Logo").sheenRoughness.empty());
  const auto ior = ReadSceneMaterials(kScenes + "CompareIor.gltf");
  // Transmission with a texture: the base roughness 0.7 (no roughness
  // texture), the IOR 2.42 both sides (issue 15).
  EXPECT_TRUE(Named(ior, "glTF Logo Transmission IOR").unsupported.empty());
  EXPECT_EQ(Named(ior, "glTF Logo Transmission IOR").transmissionEta,
            (std::vector<double>{1 / 2.42, 2.42}));
}

TEST(SceneReader, BadFilesNameTheFileAndThePlace) {
  const auto expectError = [](const std::string &file, const std::string &fragment) {
    const std::string message = ErrorOf(kPlans + file);
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << file << ": " << message;
  };
  expectError("bad_roughness.gltf",
              "/materials/1/pbrMetallicRoughness/roughnessFactor: 7 is outside");
  expectError("malformed.gltf", "line 3");
  expectError("nan.gltf", "malformed JSON");
  expectError("not_gltf.json", "not a glTF file");
  expectError("gltf1.gltf", "glTF 2.x");
  expectError("bad_magic.glb", "magic");
  expectError("bad_version.glb", "version 1");
  expectError("truncated.glb", "truncated");
  expectError("bad_chunk.glb", "truncated chunk");
  expectError("no_such_file.gltf", "cannot open");
  EXPECT_NE(ErrorOf(kPlans).find("is a directory"), std::string::npos);
}

TEST(SceneReader, EveryTruncationIsRefused) {
  // Every strict prefix of a GLB is refused (its header's length no longer
  // matches); every prefix of a .gltf that stops before its closing brace is
  // malformed JSON. Both as InputError, nothing else.
  const std::string glb = Bytes(kPlans + "listed.glb");
  for (size_t n = 0; n < glb.size(); ++n)
    EXPECT_THROW(ParseSceneMaterials(glb.substr(0, n), "cut.glb"), InputError) << n;
  const std::string gltf = Bytes(kPlans + "clearcoat.gltf");
  const size_t brace = gltf.rfind('}');
  for (size_t n = 0; n <= brace; ++n)
    EXPECT_THROW(ParseSceneMaterials(gltf.substr(0, n), "cut.gltf"), InputError) << n;
  EXPECT_EQ(ParseSceneMaterials(gltf.substr(0, brace + 1), "whole.gltf").size(), 3u);
}

TEST(SceneReader, WrongTypesAreRefused) {
  const std::string head = R"({"asset": {"version": "2.0"}, "materials": )";
  const auto error = [&](const std::string &materials) {
    try {
      ParseSceneMaterials(head + materials + "}", "inline.gltf");
    } catch (const InputError &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(R"({})").find("/materials: expected an array"), std::string::npos);
  EXPECT_NE(error(R"([3])").find("/materials/0: expected an object"), std::string::npos);
  EXPECT_NE(error(R"([{"pbrMetallicRoughness": {"roughnessFactor": "0.5"}}])")
                .find("roughnessFactor: expected a number"),
            std::string::npos);
  EXPECT_NE(error(R"([{"pbrMetallicRoughness": {"roughnessFactor": -0.1}}])").find("outside"),
            std::string::npos);
  EXPECT_NE(error(R"([{"pbrMetallicRoughness": {"metallicRoughnessTexture": {}}}])")
                .find("metallicRoughnessTexture/index"),
            std::string::npos);
  EXPECT_NE(error(R"([{"extensions": {"KHR_materials_ior": {"ior": 0.5}}}])").find("ior >= 1"),
            std::string::npos);
  EXPECT_NE(
      error(R"([{"extensions": {"KHR_materials_clearcoat": {"clearcoatRoughnessFactor": 2}}}])")
          .find("clearcoatRoughnessFactor: 2 is outside"),
      std::string::npos);
  EXPECT_EQ(error(R"([{"extensions": {"KHR_materials_ior": {"ior": 0}}}])"), "");
}

}  // namespace
}  // namespace lutbake
