// A bake plan: from the materials of some scenes and manifests, the tables
// they need, over only the ranges they use, and why every other table is
// left out.
//
// Rules (docs/plans.md):
//   - Unlit materials, and materials with no specular lobe, need nothing.
//   - dfg (split-sum IBL) for the materials shaded with image-based lighting;
//     E and E_avg for those with Kulla-Conty energy compensation. Both are
//     on unless --no-ibl / --no-compensation, the manifest's "lighting", or
//     the material itself says otherwise (the command line wins).
//   - Favg only for compensated materials whose Fresnel is not Schlick's
//     (Schlick's F_avg = 20/21 F0 + 1/21 F90 exactly: the Favg.h header then
//     carries that function and no table), over just the IORs used (eta,
//     eta x k), or for F82-tint metals the F0 x tint they use.
//   - f82 for the F82-tint metals lit by image-based lighting, over their
//     base roughness: their split-sum specular albedo is F0 A + F90 B - a C,
//     with dfg's A, B and f82's C.
//   - The roughness axis of E, E_avg and dfg covers what their materials
//     use, every layer (clearcoat too): a layer with a roughness texture
//     covers [0, factor], one without exactly its factor. When every use is
//     exact and there are at most kMaxListedRoughness distinct values, the
//     axis lists them (a row at exactly each value); otherwise it is linear
//     over [min, max] of all uses, with as many rows as the full [0, 1] axis
//     would spend on that interval (at least 2), so the texel spacing does not
//     grow.
//   - Which tables serve which purpose is each table's PlanRole
//     (table_definition.h): a new table with an existing role is planned
//     with no change here.
//   - Tables are named E, Eavg, dfg, Favg; when a plan needs two variants of
//     one (GGX and Beckmann materials, say), the ones that are not GGX with
//     the height-correlated Smith term get a suffix: E_beckmann,
//     E_separable, E_beckmann_separable; Favg_dielectric, Favg_conductor
//     and Favg_f82 when two appear.
//   - glass_E and glass_Eavg for materials with transmission, over their
//     roughness and exactly the relative IORs they use, both sides (ior and
//     1 / ior) as a listed eta axis: glass at 1.5 alone gets the two slices
//     eta = 1.5 and 1/1.5, nothing between.
//   - spec_E and spec_Eavg for compensated materials with a dielectric coat
//     (a manifest's "coat"; glTF's KHR_materials_clearcoat, whose IOR is
//     1.5), over the coat roughness and a listed eta axis at exactly the
//     coat IORs, both sides, as for glass: energy-conserving layering scales
//     the base by 1 - spec_E (light leaving through the coat: eta < 1).
//   - Features lutbake does not bake (volume absorption, ...) are listed as
//     unsupported; the plan still holds the tables of those materials'
//     other lobes.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lutbake/plans/material.h"
#include "lutbake/tables/bake_estimate.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

inline constexpr int kMaxListedRoughness = 16;

struct PlanOptions {
  // Command line: false switches the term off for every material.
  bool ibl = true;
  bool compensation = true;
  // Manifest "lighting": the default for materials that do not say.
  std::optional<bool> defaultIbl;
  std::optional<bool> defaultCompensation;
  // A manifest's "areaLights": the LTC tables of the lobes the lit
  // materials use (off unless asked).
  std::optional<bool> areaLights;
  int maxListedRoughness = kMaxListedRoughness;
  // Texels per axis of the full tables: tableSizes[name], else size, else
  // (0) the table's default (the bake's --size, or 32 / 128).
  int size = 0;
  std::map<std::string, int> tableSizes;
};

// The values of one parameter that a table must cover.
struct CoveredRange {
  double min = 0.0, max = 0.0;
  std::vector<double> values;  // the exact values, when the axis lists them
};

struct PlannedTable {
  std::string name;  // file stem and header identifier
  const TableDefinition *definition = nullptr;
  NdfKind ndf = NdfKind::kGgx;                    // E, Eavg, dfg
  SmithForm smith = SmithForm::kCorrelated;       // E, Eavg, dfg
  FresnelModel fresnel = FresnelModel::kSchlick;  // Favg
  CoveredRange roughness;                         // E, Eavg, dfg
  CoveredRange eta, k;                            // Favg (k: conductor only)
  CoveredRange f0, tint;                          // Favg f82
  Axis x, y;                                      // the axes it is baked on
  Axis z = LinearAxis("", 0.0, 1.0, 1);           // a 3D table's third axis (glass_E: eta)
  std::vector<double> etas;                       // glass, spec: the relative IORs, both sides
  std::vector<std::string> materials;             // the materials that need it
};

struct OmittedTable {
  std::string name;
  std::string reason;
};

struct UnsupportedFeature {
  std::string material;
  std::string feature;
};

struct BakePlan {
  std::vector<MaterialSpec> materials;  // everything read, in order
  std::vector<PlannedTable> tables;
  std::vector<OmittedTable> omitted;
  std::vector<UnsupportedFeature> unsupported;
  // Favg is omitted because every compensated material uses Schlick: a
  // header bake writes Favg.h with the closed form instead of a table.
  bool schlickFavgFunction = false;
  // How long baking it will take (lutbake::Plan with PlanRequest::estimate;
  // bake_estimate.h): printed by DescribePlan and PlanJson when present.
  std::optional<BakeEstimate> estimate;
  bool empty() const { return tables.empty(); }
};

BakePlan MakePlan(const std::vector<MaterialSpec> &materials, const PlanOptions &options);

// The plan as JSON: {"tables": [{"name", "table", "roughness": {"min",
// "max", "values"?}, "materials", ...}], "omitted": [{"name", "reason"}],
// "unsupported": [{"material", "feature"}], "materials": [...]}.
std::string PlanJson(const BakePlan &plan);
// The plan in words, for people.
std::string DescribePlan(const BakePlan &plan);

// The settings of one planned table's bake: the plan's model on top of `base`.
BakeSettings PlannedSettings(const PlannedTable &table, const BakeSettings &base);

}  // namespace lutbake
