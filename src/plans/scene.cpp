#include "lutbake/plans/scene.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lutbake/tables/table.h"
#include "plans/json_input.h"

namespace lutbake {

using json_input::Json;
using json_input::Member;
using json_input::Place;

namespace {

// Larger than any glTF JSON we know of by two orders of magnitude; a file
// this big is not a materials description.
constexpr size_t kMaxSceneBytes = size_t{1} << 30;

uint32_t U32(std::string_view bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

// The JSON chunk of a GLB container (glTF 2.0, section 4.4): a 12-byte
// header (magic "glTF", version 2, total length), then chunks of (length,
// type, data); the first chunk is the JSON.
std::string_view GlbJson(std::string_view bytes, const std::string &name) {
  const auto fail = [&](const std::string &what) -> std::string_view {
    throw InputError(name + ": bad GLB: " + what);
  };
  if (bytes.size() < 12)
    return fail(std::to_string(bytes.size()) + " bytes, shorter than the 12-byte header");
  const uint32_t version = U32(bytes, 4), length = U32(bytes, 8);
  if (version != 2)
    return fail("header version " + std::to_string(version) + " (glTF 2.0 GLB has version 2)");
  if (length != bytes.size())
    return fail("header says " + std::to_string(length) + " bytes, the file has " +
                std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated)" : ""));
  if (bytes.size() < 20) return fail("no chunk after the header (truncated)");
  const uint32_t chunkLength = U32(bytes, 12), chunkType = U32(bytes, 16);
  if (chunkType != 0x4E4F534Au)  // "JSON"
    return fail("the first chunk (at byte 12) is not of type JSON");
  if (chunkLength > bytes.size() - 20)
    return fail("the JSON chunk says " + std::to_string(chunkLength) + " bytes, " +
                std::to_string(bytes.size() - 20) + " remain (truncated chunk)");
  return bytes.substr(20, chunkLength);
}

// glTF's textureInfo: an object with a non-negative integer "index".
bool Texture(const Json &parent, const char *key, const Place &place) {
  const Json *t = Member(parent, key);
  if (!t) return false;
  const Place at = place.Child(key);
  json_input::RequireObject(*t, at);
  const Json *index = Member(*t, "index");
  if (!index || !index->is_number_integer() || index->get<int64_t>() < 0)
    at.Child("index").Fail("a texture needs a non-negative integer index, found " +
                           (index ? json_input::Describe(*index) : std::string("nothing")));
  return true;
}

double Factor(const Json &parent, const char *key, const Place &place, double fallback,
              double lo = 0.0, double hi = 1.0) {
  const Json *v = Member(parent, key);
  return v ? json_input::Number(*v, place.Child(key), lo, hi) : fallback;
}

struct Extension {
  const char *name;
  const char *factor;  // the factor that switches it off at 0 (with no texture)
  const char *texture;
  double fallback;  // the factor's default
};

// Extensions whose lobes need tables lutbake does not bake.
constexpr Extension kUnsupported[] = {
    {"KHR_materials_anisotropy", "anisotropyStrength", "anisotropyTexture", 0.0},
    {"KHR_materials_iridescence", "iridescenceFactor", "iridescenceTexture", 0.0},
};

// Extensions that change nothing lutbake bakes.
constexpr const char *kHarmless[] = {"KHR_materials_emissive_strength", "KHR_texture_transform",
                                     "KHR_materials_variants", "KHR_materials_dispersion",
                                     "KHR_materials_diffuse_transmission"};

// Is an unsupported extension switched off by its own factor? (Reported all
// the same, with a note: refusing to bake is the safe side.)
bool SwitchedOff(const Json &ext, const Extension &e) {
  if (Member(ext, e.texture)) return false;
  const Json *f = Member(ext, e.factor);
  if (!f) return e.fallback == 0.0;
  if (f->is_number()) return f->get<double>() == 0.0;
  if (f->is_array()) {
    for (const Json &c : *f)
      if (!c.is_number() || c.get<double>() != 0.0) return false;
    return true;
  }
  return false;
}

MaterialSpec ReadMaterial(const Json &m, const Place &place, size_t index,
                          const std::string &name) {
  json_input::RequireObject(m, place);
  MaterialSpec out;
  out.source = name;
  out.where = place.Text();
  out.name = "materials[" + std::to_string(index) + "]";
  if (const Json *n = Member(m, "name")) out.name = json_input::String(*n, place.Child("name"));

  double roughnessFactor = 1.0, metallicFactor = 1.0;
  bool roughnessTexture = false;
  if (const Json *pbr = Member(m, "pbrMetallicRoughness")) {
    const Place at = place.Child("pbrMetallicRoughness");
    json_input::RequireObject(*pbr, at);
    roughnessFactor = Factor(*pbr, "roughnessFactor", at, 1.0);
    metallicFactor = Factor(*pbr, "metallicFactor", at, 1.0);
    roughnessTexture = Texture(*pbr, "metallicRoughnessTexture", at);
    Texture(*pbr, "baseColorTexture", at);
  }

  const Json *extensions = Member(m, "extensions");
  const Place extPlace = place.Child("extensions");
  if (extensions) json_input::RequireObject(*extensions, extPlace);
  const auto ext = [&](const char *key) { return extensions ? Member(*extensions, key) : nullptr; };

  if (const Json *unlit = ext("KHR_materials_unlit")) {
    json_input::RequireObject(*unlit, extPlace.Child("KHR_materials_unlit"));
    out.unlit = true;
    out.notes.push_back("KHR_materials_unlit: no lighting, needs no table");
    return out;
  }

  // Specular-glossiness (archived, still in use) replaces metallic-roughness.
  if (const Json *sg = ext("KHR_materials_pbrSpecularGlossiness")) {
    const Place at = extPlace.Child("KHR_materials_pbrSpecularGlossiness");
    json_input::RequireObject(*sg, at);
    const double glossiness = Factor(*sg, "glossinessFactor", at, 1.0);
    const bool texture = Texture(*sg, "specularGlossinessTexture", at);
    const double r = SnapToMirror(1.0 - glossiness, out, "roughness 1 - glossinessFactor");
    out.roughness.push_back({"base", r, texture ? 1.0 : r});
    out.notes.push_back("KHR_materials_pbrSpecularGlossiness: roughness = 1 - glossiness");
  } else {
    bool lobe = true;
    // glTF's dielectric Fresnel is Schlick's with F0 = ((ior - 1) / (ior +
    // 1))^2 (ior 1.5 by default: 0.04; ior 0 means F0 = 1), scaled by
    // KHR_materials_specular: F0 = min(F0 specularColorFactor, 1)
    // specularFactor per channel, F90 = specularFactor.
    double ior = 1.5, specularFactor = 1.0;
    double specularColor[3] = {1.0, 1.0, 1.0};
    if (const Json *iorExt = ext("KHR_materials_ior")) {
      const Place at = extPlace.Child("KHR_materials_ior");
      json_input::RequireObject(*iorExt, at);
      if (const Json *v = Member(*iorExt, "ior")) {
        ior = json_input::Number(*v, at.Child("ior"), 0.0, 1e6);
        if (ior > 0.0 && ior < 1.0)
          at.Child("ior").Fail(FormatDouble(ior) +
                               " is not accepted: KHR_materials_ior takes ior >= 1, or 0 (F0 = 1)");
      }
    }
    if (const Json *spec = ext("KHR_materials_specular")) {
      const Place at = extPlace.Child("KHR_materials_specular");
      json_input::RequireObject(*spec, at);
      specularFactor = Factor(*spec, "specularFactor", at, 1.0);
      Texture(*spec, "specularTexture", at);
      Texture(*spec, "specularColorTexture", at);
      if (const Json *c = Member(*spec, "specularColorFactor")) {
        const Place cp = at.Child("specularColorFactor");
        json_input::RequireArray(*c, cp);
        if (c->size() != 3) cp.Fail("expected 3 numbers, found " + std::to_string(c->size()));
        for (size_t i = 0; i < 3; ++i)
          specularColor[i] = json_input::Number((*c)[i], cp.Child(i), 0.0, 1e30);
      }
      // F0 and F90 of the dielectric part both scale with specularFactor
      // (its texture multiplies it, so 0 stays 0); metallicFactor 0 leaves
      // no metal either (its texture multiplies it too): nothing reflects
      // specularly.
      if (specularFactor == 0.0 && metallicFactor == 0.0) {
        lobe = false;
        out.notes.push_back(
            "no specular lobe: metallicFactor 0 and KHR_materials_specular specularFactor 0");
      }
    }
    const double f0 = ior == 0.0 ? 1.0 : ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
    for (double c : specularColor)
      out.fresnel.schlickF0.push_back(std::min(f0 * c, 1.0) * specularFactor);
    out.fresnel.schlickF90 = specularFactor;
    if (lobe) {
      const double r = SnapToMirror(roughnessFactor, out, "roughnessFactor");
      out.roughness.push_back({"base", roughnessTexture ? 0.0 : r, r});
    }
    // KHR_materials_transmission: the base lobe also refracts, through an
    // interface of relative IOR ior entering and 1 / ior leaving (a volume
    // or a thin wall, light crosses both), with the base roughness; its
    // texture multiplies transmissionFactor, so factor 0 is off.
    if (const Json *tr = ext("KHR_materials_transmission")) {
      const Place at = extPlace.Child("KHR_materials_transmission");
      json_input::RequireObject(*tr, at);
      const double factor = Factor(*tr, "transmissionFactor", at, 0.0);
      const bool texture = Texture(*tr, "transmissionTexture", at);
      if (factor <= 0.0) {
        out.notes.push_back(std::string("KHR_materials_transmission with transmissionFactor 0") +
                            (texture ? " (the texture multiplies it)" : "") +
                            ": no transmission lobe");
      } else if (ior == 0.0) {
        out.notes.push_back(
            "KHR_materials_transmission with KHR_materials_ior ior 0 (F0 = 1): every facet "
            "reflects, nothing is transmitted");
      } else {
        const double r = SnapToMirror(roughnessFactor, out, "roughnessFactor");
        out.transmissionRoughness.push_back({"transmission", roughnessTexture ? 0.0 : r, r});
        out.transmissionEta.push_back(1.0 / ior);
        if (ior != 1.0) out.transmissionEta.push_back(ior);
      }
    }
    if (const Json *volume = ext("KHR_materials_volume")) {
      const Place at = extPlace.Child("KHR_materials_volume");
      json_input::RequireObject(*volume, at);
      const double thickness = Factor(*volume, "thicknessFactor", at, 0.0, 0.0, 1e30);
      Texture(*volume, "thicknessTexture", at);
      out.notes.push_back(thickness > 0.0
                              ? "KHR_materials_volume: light crosses the interface both ways "
                                "(glass_E at ior and 1 / ior); its absorption needs no table"
                              : "KHR_materials_volume with thicknessFactor 0: a thin wall");
    }
  }

  if (const Json *coat = ext("KHR_materials_clearcoat")) {
    const Place at = extPlace.Child("KHR_materials_clearcoat");
    json_input::RequireObject(*coat, at);
    const double coatFactor = Factor(*coat, "clearcoatFactor", at, 0.0);
    const bool coatTexture = Texture(*coat, "clearcoatTexture", at);
    const double coatRoughness = Factor(*coat, "clearcoatRoughnessFactor", at, 0.0);
    const bool coatRoughnessTexture = Texture(*coat, "clearcoatRoughnessTexture", at);
    Texture(*coat, "clearcoatNormalTexture", at);
    // clearcoatTexture multiplies clearcoatFactor: factor 0 is off either way.
    // The coat is a dielectric of fixed IOR 1.5 (the extension has no IOR
    // of its own; KHR_materials_ior sets the base's): layering it
    // energy-conservingly over the base needs spec_E at eta = 1.5 (light
    // arriving from outside) and 1 / 1.5 (from the base beneath).
    if (coatFactor > 0.0) {
      const double r = SnapToMirror(coatRoughness, out, "clearcoatRoughnessFactor");
      out.roughness.push_back({"clearcoat", coatRoughnessTexture ? 0.0 : r, r});
      out.coatRoughness.push_back(out.roughness.back());
      out.coatEta = {1.0 / 1.5, 1.5};
    } else {
      out.notes.push_back(std::string("KHR_materials_clearcoat with clearcoatFactor 0") +
                          (coatTexture ? " (the texture multiplies it)" : "") +
                          ": no clearcoat layer");
    }
  }

  // KHR_materials_sheen: the sheen layer needs sheen_E over its roughness.
  // Its colour texture multiplies sheenColorFactor and the roughness
  // texture's alpha multiplies sheenRoughnessFactor: factor 0 is off (no
  // sheen) or covers [0, factor] with a texture.
  if (const Json *sheen = ext("KHR_materials_sheen")) {
    const Place at = extPlace.Child("KHR_materials_sheen");
    json_input::RequireObject(*sheen, at);
    double color[3] = {0.0, 0.0, 0.0};
    if (const Json *c = Member(*sheen, "sheenColorFactor")) {
      const Place cp = at.Child("sheenColorFactor");
      json_input::RequireArray(*c, cp);
      if (c->size() != 3) cp.Fail("expected 3 numbers, found " + std::to_string(c->size()));
      for (size_t i = 0; i < 3; ++i) color[i] = json_input::Number((*c)[i], cp.Child(i), 0.0, 1.0);
    }
    const bool colorTexture = Texture(*sheen, "sheenColorTexture", at);
    const double r = Factor(*sheen, "sheenRoughnessFactor", at, 0.0);
    const bool roughnessTexture = Texture(*sheen, "sheenRoughnessTexture", at);
    if (color[0] > 0.0 || color[1] > 0.0 || color[2] > 0.0)
      out.sheenRoughness.push_back({"sheen", roughnessTexture ? 0.0 : r, r});
    else
      out.notes.push_back(std::string("KHR_materials_sheen with sheenColorFactor 0") +
                          (colorTexture ? " (the texture multiplies it)" : "") +
                          ": no sheen layer");
  }

  if (extensions) {
    for (const Extension &e : kUnsupported)
      if (const Json *v = ext(e.name)) {
        json_input::RequireObject(*v, extPlace.Child(e.name));
        out.unsupported.push_back(e.name);
        if (SwitchedOff(*v, e))
          out.notes.push_back(std::string(e.name) + " is present but its " + e.factor +
                              " is 0 with no texture: --skip-unsupported loses nothing");
      }
    for (auto it = extensions->begin(); it != extensions->end(); ++it) {
      const std::string &key = it.key();
      bool known = key == "KHR_materials_unlit" || key == "KHR_materials_ior" ||
                   key == "KHR_materials_specular" || key == "KHR_materials_clearcoat" ||
                   key == "KHR_materials_pbrSpecularGlossiness" || key == "KHR_materials_sheen" ||
                   key == "KHR_materials_transmission" || key == "KHR_materials_volume";
      for (const Extension &e : kUnsupported) known = known || key == e.name;
      bool harmless = false;
      for (const char *h : kHarmless) harmless = harmless || key == h;
      if (harmless)
        out.notes.push_back(key + ": does not change the specular lobe");
      else if (!known)
        out.notes.push_back(key + ": unknown extension, ignored");
    }
  }
  return out;
}

}  // namespace

std::vector<MaterialSpec> ParseSceneMaterials(std::string_view bytes, const std::string &name) {
  const bool glb = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  const bool glbName = name.size() >= 4 && (name.compare(name.size() - 4, 4, ".glb") == 0 ||
                                            name.compare(name.size() - 4, 4, ".GLB") == 0);
  if (glbName && !glb)
    throw InputError(name + ": not a GLB file: it does not start with the magic \"glTF\"");
  const Json root = json_input::Parse(glb ? GlbJson(bytes, name) : bytes, name);
  const Place top{&name, ""};
  if (!root.is_object())
    throw InputError(name + ": not a glTF file: the JSON is " + json_input::Describe(root) +
                     ", not an object with \"asset\"");
  const Json *asset = Member(root, "asset");
  const Json *version = asset && asset->is_object() ? Member(*asset, "version") : nullptr;
  if (!version || !version->is_string())
    throw InputError(name + ": not a glTF file: no string /asset/version");
  if (version->get<std::string>().rfind("2.", 0) != 0)
    throw InputError(name + ": /asset/version is " + version->dump() + "; lutbake reads glTF 2.x");

  std::vector<MaterialSpec> materials;
  if (const Json *list = Member(root, "materials")) {
    const Place at = top.Child("materials");
    json_input::RequireArray(*list, at);
    for (size_t i = 0; i < list->size(); ++i)
      materials.push_back(ReadMaterial((*list)[i], at.Child(i), i, name));
  }
  // Primitives without a material are drawn with glTF's default material
  // (section 3.9.6): metallic 1, roughness 1, no textures.
  std::string defaultUser;  // the first primitive without a material
  if (const Json *meshes = Member(root, "meshes"); meshes && meshes->is_array())
    for (size_t i = 0; i < meshes->size() && defaultUser.empty(); ++i) {
      const Json &mesh = (*meshes)[i];
      const Json *primitives = mesh.is_object() ? Member(mesh, "primitives") : nullptr;
      if (!primitives || !primitives->is_array()) continue;
      for (size_t j = 0; j < primitives->size() && defaultUser.empty(); ++j) {
        const Json &p = (*primitives)[j];
        if (p.is_object() && !Member(p, "material"))
          defaultUser = top.Child("meshes").Child(i).Child("primitives").Child(j).Text();
      }
    }
  if (!defaultUser.empty()) {
    MaterialSpec d;
    d.name = "(default material)";
    d.source = name;
    d.where = defaultUser;
    d.roughness.push_back({"base", 1.0, 1.0});
    d.notes.push_back("glTF's default material (roughness 1, metallic 1), used by " + defaultUser +
                      ", a primitive without a material");
    materials.push_back(d);
  }
  return materials;
}

std::vector<MaterialSpec> ReadSceneMaterials(const std::string &path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a .gltf or .glb file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open (missing or unreadable)");
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  if (size < 0) throw InputError(path + ": cannot read (not a regular file?)");
  if (static_cast<uint64_t>(size) > kMaxSceneBytes)
    throw InputError(path + ": " + std::to_string(size) + " bytes; lutbake reads scenes up to " +
                     std::to_string(kMaxSceneBytes) + " bytes");
  file.seekg(0);
  std::string bytes(static_cast<size_t>(size), '\0');
  file.read(bytes.data(), size);
  if (!file) throw InputError(path + ": cannot read");
  return ParseSceneMaterials(bytes, path);
}

}  // namespace lutbake
