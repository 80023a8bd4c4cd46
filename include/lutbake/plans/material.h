// What one material needs from the tables: its microfacet model, the
// perceptual roughness each of its specular layers can take, its Fresnel
// model, and the lighting it is shaded with. The glTF reader (scene.h) and
// the manifest reader (manifest.h) both produce these; plan.h turns a list
// of them into the tables to bake.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lutbake/core/error.h"
#include "lutbake/models/fresnel.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

// A scene or manifest that cannot be used as it is: the message names the
// file and the place in it (a JSON pointer such as
// /materials/3/pbrMetallicRoughness/roughnessFactor, or a byte offset), the
// value found and what is accepted.
class InputError : public Error {
 public:
  explicit InputError(const std::string &message) : Error(Kind::kRuntime, message) {}
};

// The perceptual roughness one specular layer can take: exactly `min` when
// min == max (a factor without a texture), else any value in [min, max] (a
// texture multiplies the factor). Both in [0, 1].
struct RoughnessUse {
  std::string layer;  // "base" or "clearcoat"
  double min = 0.0;
  double max = 0.0;
  bool exact() const { return min == max; }
};

// A Fresnel parameter the material uses: listed values, or a range.
struct ParameterUse {
  std::vector<double> values;   // exact values, when not a range
  double min = 0.0, max = 0.0;  // the range, when `values` is empty
  bool range() const { return values.empty(); }
};

struct FresnelUse {
  FresnelModel model = FresnelModel::kSchlick;
  ParameterUse eta;  // dielectric and conductor: relative IOR (real part)
  ParameterUse k;    // conductor: extinction coefficient
  // F82 tint (fresnel.h): F0 and the tint, reflectances in [0, 1], of any
  // colour channel.
  ParameterUse f0;
  ParameterUse tint;
  // Schlick, when the file fixes them: F0 per colour channel (one value, or
  // r, g, b) and F90. For glTF these are the dielectric part's (from
  // KHR_materials_ior and _specular; the metal part's F0 is the base colour,
  // and textures can only scale them down). Reported, with the exact
  // F_avg = 20/21 F0 + 1/21 F90 of each: per-material constants, no table.
  std::vector<double> schlickF0;
  double schlickF90 = 1.0;
};

struct MaterialSpec {
  std::string name;    // as the file names it, or "materials[i]" when it has no name
  std::string source;  // the file it was read from
  std::string where;   // JSON pointer to it in that file
  bool unlit = false;  // KHR_materials_unlit (or "unlit": true): needs no table
  NdfKind ndf = NdfKind::kGgx;
  SmithForm smith = SmithForm::kCorrelated;
  // One entry per specular layer; empty when the material has no specular
  // lobe at all (say, glTF metallic 0 with specularFactor 0).
  std::vector<RoughnessUse> roughness;
  FresnelUse fresnel;
  // The sheen roughness (glTF KHR_materials_sheen's sheenRoughness, layer
  // "sheen") of a material with a sheen; empty without one.
  std::vector<RoughnessUse> sheenRoughness;
  // The relative IORs of a transmitting material's interface (glTF's
  // KHR_materials_transmission: its IOR from KHR_materials_ior, 1.5 by
  // default), both sides: ior entering, 1 / ior leaving. Empty without
  // transmission. Its roughness is the base layer's (transmissionRoughness).
  std::vector<double> transmissionEta;
  std::vector<RoughnessUse> transmissionRoughness;
  // A dielectric coat (a manifest's "coat", glTF's KHR_materials_clearcoat
  // at its fixed IOR 1.5): the relative IORs of its interface, both sides
  // (eta seen from outside, 1 / eta from the base beneath), and its
  // roughness. Empty without a coat. The coat is also a specular layer of
  // `roughness` (layer "coat" or "clearcoat").
  std::vector<double> coatEta;
  std::vector<RoughnessUse> coatRoughness;
  // Per-material lighting; unset means "as the manifest or command line says".
  std::optional<bool> ibl;
  std::optional<bool> compensation;
  // Features that need tables lutbake does not bake (glTF extension names).
  std::vector<std::string> unsupported;
  // Facts worth telling the user: a layer switched off by its factor, an
  // extension ignored because it does not change the specular lobe, ...
  std::vector<std::string> notes;
};

// Perceptual roughness below 1e-12 (alpha below kMinimumAlpha = 1e-24, the
// smallest the integrators take) is the mirror to within 1e-24: it is baked
// as r = 0, and a note on `material` says so. Returns the roughness to bake.
double SnapToMirror(double perceptualRoughness, MaterialSpec &material, const std::string &what);

}  // namespace lutbake
