#include "lutbake/plans/manifest.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <vector>

#include "plans/json_input.h"

namespace lutbake {

using json_input::Json;
using json_input::Member;
using json_input::Place;

namespace {

constexpr size_t kMaxManifestBytes = size_t{1} << 28;

// A number, a list of numbers, or {"min": a, "max": b} with a <= b.
ParameterUse Parameter(const Json &v, const Place &place, double lo, double hi) {
  ParameterUse out;
  if (v.is_number()) {
    out.values.push_back(json_input::Number(v, place, lo, hi));
  } else if (v.is_array()) {
    if (v.empty()) place.Fail("an empty list; give at least one value");
    for (size_t i = 0; i < v.size(); ++i)
      out.values.push_back(json_input::Number(v[i], place.Child(i), lo, hi));
  } else if (v.is_object()) {
    json_input::OnlyKeys(v, place, {"min", "max"});
    const Json *a = Member(v, "min"), *b = Member(v, "max");
    if (!a || !b) place.Fail("a range needs both \"min\" and \"max\"");
    out.min = json_input::Number(*a, place.Child("min"), lo, hi);
    out.max = json_input::Number(*b, place.Child("max"), lo, hi);
    if (out.max < out.min)
      place.Fail("min " + json_input::Describe(*a) + " is above max " + json_input::Describe(*b));
  } else {
    place.Fail("expected a number, a list of numbers or {\"min\", \"max\"}, found " +
               json_input::Describe(v));
  }
  return out;
}

// The perceptual roughness of one specular layer, as uses of `layer`
// appended to *uses: one exact use per listed value, or one range; values
// below 1e-12 are snapped to the mirror (SnapToMirror) with a note saying
// `what`.
void Roughness(const Json &v, const Place &place, const char *layer, const std::string &what,
               MaterialSpec &material, std::vector<RoughnessUse> *uses) {
  const ParameterUse r = Parameter(v, place, 0.0, 1.0);
  const auto snap = [&](double x) { return SnapToMirror(x, material, what); };
  if (r.range())
    uses->push_back({layer, snap(r.min), snap(r.max)});
  else
    for (double x : r.values) {
      const double exact = snap(x);
      uses->push_back({layer, exact, exact});
    }
}

std::optional<bool> Lighting(const Json &object, const char *key, const Place &place) {
  const Json *v = Member(object, key);
  if (!v) return std::nullopt;
  return json_input::Boolean(*v, place.Child(key));
}

MaterialSpec ReadMaterial(const Json &m, const Place &place, size_t index,
                          const std::string &name) {
  json_input::RequireObject(m, place);
  json_input::OnlyKeys(m, place,
                       {"name", "ndf", "smith", "roughness", "fresnel", "ibl", "compensation",
                        "unlit", "sheenRoughness", "coat"});
  MaterialSpec out;
  out.source = name;
  out.where = place.Text();
  out.name = "materials[" + std::to_string(index) + "]";
  if (const Json *n = Member(m, "name")) out.name = json_input::String(*n, place.Child("name"));
  if (const Json *v = Member(m, "unlit")) out.unlit = json_input::Boolean(*v, place.Child("unlit"));
  if (const Json *v = Member(m, "ndf")) {
    const std::string s = json_input::String(*v, place.Child("ndf"));
    if (s == "ggx")
      out.ndf = NdfKind::kGgx;
    else if (s == "beckmann")
      out.ndf = NdfKind::kBeckmann;
    else
      place.Child("ndf").Fail("\"" + s + "\" is not an NDF; accepted: ggx, beckmann");
  }
  if (const Json *v = Member(m, "smith")) {
    const std::string s = json_input::String(*v, place.Child("smith"));
    if (s == "correlated")
      out.smith = SmithForm::kCorrelated;
    else if (s == "separable")
      out.smith = SmithForm::kSeparable;
    else
      place.Child("smith").Fail("\"" + s +
                                "\" is not a Smith form; accepted: correlated, separable");
  }
  out.ibl = Lighting(m, "ibl", place);
  out.compensation = Lighting(m, "compensation", place);

  if (const Json *v = Member(m, "roughness")) {
    Roughness(*v, place.Child("roughness"), "base", "roughness", out, &out.roughness);
  } else if (!out.unlit) {
    place.Fail("no \"roughness\": give a number, a list or {\"min\", \"max\"} in [0, 1]");
  }
  // A dielectric coat over the base: spec_E's eta axis lists exactly the
  // coat IORs used, both sides (eta from outside, 1 / eta from the base
  // beneath), so eta is a number or a list, never a range. The coat is a
  // specular layer too ("coat" in `roughness`).
  if (const Json *c = Member(m, "coat")) {
    const Place at = place.Child("coat");
    json_input::RequireObject(*c, at);
    json_input::OnlyKeys(*c, at, {"eta", "roughness"});
    const Json *eta = Member(*c, "eta"), *r = Member(*c, "roughness");
    if (!eta || !r)
      at.Fail(
          "a coat needs \"eta\", its relative IOR in (0, 10] (a number or a list), and "
          "\"roughness\" in [0, 1] (a number, a list or {\"min\", \"max\"})");
    const ParameterUse etas = Parameter(*eta, at.Child("eta"), 1e-3, 10.0);
    if (etas.range())
      at.Child("eta").Fail(
          "a range is not accepted for a coat: spec_E is baked at exactly the coat IORs "
          "used (a listed eta axis, eta and 1 / eta), so give a number or a list of numbers");
    std::set<double> sides;
    for (double e : etas.values) sides.insert({e, 1.0 / e});
    out.coatEta.assign(sides.begin(), sides.end());
    Roughness(*r, at.Child("roughness"), "coat", "coat roughness", out, &out.coatRoughness);
    out.roughness.insert(out.roughness.end(), out.coatRoughness.begin(), out.coatRoughness.end());
  }
  // A sheen layer (KHR_materials_sheen's sheenRoughness: no snapping, the
  // sheen tables take all of [0, 1]).
  if (const Json *v = Member(m, "sheenRoughness")) {
    const ParameterUse r = Parameter(*v, place.Child("sheenRoughness"), 0.0, 1.0);
    if (r.range())
      out.sheenRoughness.push_back({"sheen", r.min, r.max});
    else
      for (double x : r.values) out.sheenRoughness.push_back({"sheen", x, x});
  }

  if (const Json *f = Member(m, "fresnel")) {
    const Place at = place.Child("fresnel");
    json_input::RequireObject(*f, at);
    const Json *model = Member(*f, "model");
    if (!model) at.Fail("no \"model\"; accepted: schlick, dielectric, conductor, f82");
    const std::string s = json_input::String(*model, at.Child("model"));
    if (s == "schlick") {
      json_input::OnlyKeys(*f, at, {"model", "f0"});
      out.fresnel.model = FresnelModel::kSchlick;
      if (const Json *f0 = Member(*f, "f0")) {
        const ParameterUse p = Parameter(*f0, at.Child("f0"), 0.0, 1.0);
        out.fresnel.schlickF0 = p.values;  // a range fixes no constant
      }
    } else if (s == "dielectric") {
      json_input::OnlyKeys(*f, at, {"model", "eta"});
      out.fresnel.model = FresnelModel::kDielectric;
      const Json *eta = Member(*f, "eta");
      if (!eta) at.Fail("a dielectric needs \"eta\", the relative IOR in (0, 10]");
      out.fresnel.eta = Parameter(*eta, at.Child("eta"), 1e-3, 10.0);
    } else if (s == "conductor") {
      json_input::OnlyKeys(*f, at, {"model", "eta", "k"});
      out.fresnel.model = FresnelModel::kConductor;
      const Json *eta = Member(*f, "eta"), *k = Member(*f, "k");
      if (!eta || !k) at.Fail("a conductor needs \"eta\" in (0, 10] and \"k\" in [0, 20]");
      out.fresnel.eta = Parameter(*eta, at.Child("eta"), 1e-3, 10.0);
      out.fresnel.k = Parameter(*k, at.Child("k"), 0.0, 20.0);
    } else if (s == "f82") {
      json_input::OnlyKeys(*f, at, {"model", "f0", "tint"});
      out.fresnel.model = FresnelModel::kF82;
      const Json *f0 = Member(*f, "f0"), *tint = Member(*f, "tint");
      if (!f0 || !tint) at.Fail("an F82-tint metal needs \"f0\" and \"tint\", each in [0, 1]");
      out.fresnel.f0 = Parameter(*f0, at.Child("f0"), 0.0, 1.0);
      out.fresnel.tint = Parameter(*tint, at.Child("tint"), 0.0, 1.0);
    } else {
      at.Child("model").Fail(
          "\"" + s + "\" is not a Fresnel model; accepted: schlick, dielectric, conductor, f82");
    }
  }
  return out;
}

}  // namespace

Manifest ParseManifest(std::string_view text, const std::string &name) {
  const Json root = json_input::Parse(text, name);
  const Place top{&name, ""};
  json_input::RequireObject(root, top);
  json_input::OnlyKeys(root, top, {"lighting", "materials", "areaLights"});
  Manifest out;
  out.source = name;
  out.areaLights = Lighting(root, "areaLights", top);
  if (const Json *l = Member(root, "lighting")) {
    const Place at = top.Child("lighting");
    json_input::RequireObject(*l, at);
    json_input::OnlyKeys(*l, at, {"ibl", "compensation", "areaLights"});
    out.ibl = Lighting(*l, "ibl", at);
    out.compensation = Lighting(*l, "compensation", at);
    if (const std::optional<bool> inLighting = Lighting(*l, "areaLights", at)) {
      if (out.areaLights && *out.areaLights != *inLighting)
        throw InputError(name + ": /areaLights and /lighting/areaLights disagree");
      out.areaLights = inLighting;
    }
  }
  if (const Json *list = Member(root, "materials")) {
    const Place at = top.Child("materials");
    json_input::RequireArray(*list, at);
    for (size_t i = 0; i < list->size(); ++i)
      out.materials.push_back(ReadMaterial((*list)[i], at.Child(i), i, name));
  }
  return out;
}

Manifest ReadManifest(const std::string &path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a manifest file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open (missing or unreadable)");
  // Read in chunks and stop past the limit: a stream without end (a
  // device such as /dev/zero, a FIFO) would otherwise be read until memory
  // runs out.
  std::string text;
  std::vector<char> chunk(size_t{1} << 16);
  while (file.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || file.gcount() > 0) {
    text.append(chunk.data(), static_cast<size_t>(file.gcount()));
    if (text.size() > kMaxManifestBytes)
      throw InputError(path + ": more than " + std::to_string(kMaxManifestBytes) +
                       " bytes; manifests are read up to " + std::to_string(kMaxManifestBytes));
  }
  return ParseManifest(text, path);
}

}  // namespace lutbake
