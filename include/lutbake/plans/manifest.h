// A bake manifest: materials listed directly, and the lighting facts a glTF
// file does not carry. JSON, every key checked (an unknown key is an error
// naming its JSON pointer and the keys accepted there):
//
//   {
//     "lighting": {"ibl": true, "compensation": true,       // optional; both default true
//                  "areaLights": false},                    // optional; true: the LTC tables
//                                                           //   of the lobes used (ltc_ggx)
//     "materials": [                                        // optional
//       {
//         "name": "car paint",                              // default "materials[i]"
//         "ndf": "ggx",                                     // ggx (default) | beckmann
//         "smith": "correlated",                            // correlated (default) | separable
//         "roughness": 0.3,                                 // perceptual roughness in [0, 1]:
//                                                           //   a number, a list of numbers,
//                                                           //   or {"min": a, "max": b}
//         "fresnel": {"model": "dielectric", "eta": 1.5},   // default {"model": "schlick"};
//                                                           //   schlick: optional "f0" in [0, 1]
//                                                           //   dielectric: "eta" in (0, 10]
//                                                           //   conductor: "eta" in (0, 10],
//                                                           //     "k" in [0, 20]
//                                                           //   f82: "f0" and "tint" in [0, 1]
//                                                           //   each a number, list or {min, max}
//         "ibl": true, "compensation": true,                // optional, per material
//         "unlit": false,                                   // optional: true needs no table
//         "sheenRoughness": 0.5,                            // optional: a sheen layer
//                                                           //   (KHR_materials_sheen), as
//                                                           //   "roughness" but never snapped
//         "coat": {"eta": 1.5, "roughness": 0.1}            // optional: a dielectric coat;
//                                                           //   "eta" in (0, 10], a number or a
//                                                           //   list, never a range (spec_E is
//                                                           //   baked at exactly those IORs and
//                                                           //   their inverses); "roughness" as
//                                                           //   the material's, a layer "coat"
//       }
//     ]
//   }
//
// "lighting" applies to every material of the plan, glTF scenes' included,
// unless a material says otherwise; --no-ibl and --no-compensation on the
// command line switch a term off for everything. "areaLights" may also stand
// at the top level ({"areaLights": true, "materials": [...]}).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lutbake/plans/material.h"

namespace lutbake {

struct Manifest {
  std::string source;
  std::optional<bool> ibl;
  std::optional<bool> compensation;
  std::optional<bool> areaLights;  // rectangular area lights: the LTC tables
  std::vector<MaterialSpec> materials;
};

// Throws InputError (material.h) for a missing or unreadable file, malformed
// JSON, an unknown key, or a value of the wrong type or outside its range.
Manifest ReadManifest(const std::string &path);
Manifest ParseManifest(std::string_view text, const std::string &name);

}  // namespace lutbake
