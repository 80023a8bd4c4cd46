// Reading the materials of glTF 2.0 scenes, .gltf (JSON) or .glb (binary
// container, read by hand: 12-byte header, then the JSON chunk). Only the
// materials matter; buffers and images are never opened, so missing ones
// are not an error.
//
// What each material needs (material.h), by the glTF 2.0 specification:
//   pbrMetallicRoughness  roughness = roughnessFactor (default 1) times the
//                         green channel of metallicRoughnessTexture: exactly
//                         the factor without the texture, [0, factor] with it.
//                         The BRDF is GGX with the height-correlated Smith
//                         term, Fresnel by Schlick.
//   KHR_materials_unlit   no lighting: needs no table.
//   KHR_materials_ior     ior >= 1 (or 0, meaning F0 = 1): Schlick's F0 only.
//   KHR_materials_specular  specularFactor scales the dielectric F0 and F90;
//                         with metallicFactor 0 and specularFactor 0 there is
//                         no specular lobe at all.
//   KHR_materials_clearcoat  a second GGX layer of roughness
//                         clearcoatRoughnessFactor (default 0; times its
//                         texture's green channel), present when
//                         clearcoatFactor > 0 (default 0: off).
//   KHR_materials_pbrSpecularGlossiness (archived) roughness = 1 - glossiness,
//                         glossiness = glossinessFactor (default 1) times the
//                         texture's alpha: [1 - factor, 1] with the texture.
//   KHR_materials_sheen   a sheen layer (sheen_E) of roughness
//                         sheenRoughnessFactor (default 0; times its
//                         texture's alpha: [0, factor]), present when a
//                         component of sheenColorFactor (default 0) is > 0.
//   KHR_materials_transmission, _volume, _anisotropy, _iridescence
//                         need tables lutbake does not bake: reported as
//                         unsupported (also when their factors switch them
//                         off; a note says so).
// A mesh primitive without a material uses glTF's default material
// (roughness 1, metallic 1), which then counts as a material of its own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "lutbake/plans/material.h"

namespace lutbake {

// Throws InputError (material.h) for a missing or unreadable file, a file
// that is not glTF 2.0, malformed JSON, a bad GLB header or chunk, or a
// material value outside what glTF allows.
std::vector<MaterialSpec> ReadSceneMaterials(const std::string &path);

// The same from bytes already in memory; `name` is used in messages and as
// each material's source.
std::vector<MaterialSpec> ParseSceneMaterials(std::string_view bytes, const std::string &name);

}  // namespace lutbake
