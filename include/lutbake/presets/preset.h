// Engine presets: the textures an engine's shaders sample, as data.
//
// An engine reads its lookup table with its own conventions: which quantity
// lies on each texture axis and through which mapping (Unity HDRP puts
// sqrt(NdotV) on x, EEVEE sqrt(1 - NoV) on y), where the texels sit
// (centres, u = (i + 0.5) / N, for a GPU's linear filter at uv; edges, u =
// i / (N - 1), for a half-texel remap or a CPU lookup), the order of the
// rows, what each channel holds (A and B, or Filament's B and E, a cloth
// or Charlie channel, an F82 term), the model the engine integrates (the
// visibility form, alpha from roughness) and the storage. A preset states
// all of it, one PresetTexture per texture, and BakePresetTexture computes
// every texel with lutbake's integrators at exactly the coordinates the
// engine's shader asks for. Each preset is one definition in
// src/presets/<engine>.cpp, listed in src/presets/registry.cpp; nothing
// else knows an engine.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lutbake/core/cancellation.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/models/sheen.h"
#include "lutbake/models/smith.h"
#include "lutbake/tables/bake_estimate.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// How a texture coordinate u in [0, 1] gives its axis's quantity q:
//   kLinear         q = u
//   kSquare         q = u^2       (the axis holds sqrt(q): HDRP's sqrt(NdotV))
//   kOneMinusSquare q = 1 - u^2   (the axis holds sqrt(1 - q): EEVEE's sqrt(1 - NoV))
//   kIorOfF0Root4   q = (1 + u^2) / (1 - u^2): the IOR whose normal-incidence
//                   reflectance F0 is u^4, u = sqrt(|(ior - 1) / (ior + 1)|)
//                   (Cycles' IOR axis); u = 1 is infinite, so such an axis
//                   clamps q below.
//   kLinearRange    q = lowest + u (highest - lowest): an axis that runs
//                   linearly over [lowest, highest] (OSPRay's eta axes).
enum class PresetMapping { kLinear, kSquare, kOneMinusSquare, kIorOfF0Root4, kLinearRange };
// Where texel i of N lies in u:
//   kCentres  u = (i + 0.5) / N   (sampled at uv by a linear filter)
//   kEdges    u = i / (N - 1)     (N >= 2: a half-texel remap, a CPU lookup)
enum class TexelPlacement { kCentres, kEdges };

// "u", "u^2", "1 - u^2", "(1 + u^2) / (1 - u^2)"; "centres", "edges".
const char *ToString(PresetMapping mapping);
const char *ToString(TexelPlacement placement);

struct PresetAxis {
  // What the axis drives: "mu" (n.v), "roughness" (the engine's
  // roughness, which PresetModel maps to alpha), "eta" (the relative IOR of
  // the glass channels) or "1/eta" (the axis holds the IOR of the medium
  // the view is in, and the interface is left: eta = 1 / q, an engine's
  // table for the inside of glass).
  std::string quantity;
  PresetMapping mapping = PresetMapping::kLinear;
  TexelPlacement placement = TexelPlacement::kCentres;
  int count = 1;
  // The first texel in memory (and in the file) is u = 1: a top-down image
  // of a table whose v = 0 is at the bottom.
  bool reversed = false;
  // The quantity is clamped to [lowest, highest] before it is evaluated
  // (an engine's own clamp, e.g. mu >= 1e-4).
  double lowest = 0.0, highest = 1.0;

  // u of texel i (before `reversed`), and the quantity there (clamped).
  double Coordinate(int i) const;
  double Quantity(int i) const;
};

// The model an engine integrates its channels with, in the models' and
// tables' own terms: a channel reads its table (TableNamed) under
// TableSettings(), at alpha from the roughness axis through `alpha`.
struct PresetModel {
  // The microfacet G2: Smith's in the form `smith` (tables dfg, f82, Eavg,
  // glass_*, spec_*), unless `fitted` names an engine's fitted G2 in its
  // place (albedo_quadrature.h: Schlick-GGX with k = alpha / 2, the UE4
  // school; Unreal's Vis_SmithJointApprox), which the split-sum channels
  // integrate through IntegrateFittedSplitSumQuadrature.
  SmithForm smith = SmithForm::kCorrelated;
  FittedVisibility fitted = FittedVisibility::kNone;
  // alpha from the engine's roughness q: q^2 (perceptual roughness) or q.
  AlphaMapping alpha = AlphaMapping::kSquared;
  double alphaMin = 0.0;  // alpha = max(alpha, alphaMin): an engine's clamp
  // |eta - 1| below this: the engine treats the interface as absent (no
  // rough lobe, light passes straight through), so the glass channels hold
  // 1 there, exactly (Cycles, bsdf_microfacet.h: fabsf(m_eta - 1.0f) <
  // 1e-4f). 0: none; the glass albedo at eta = 1 is then lutbake's
  // microfacet value G2(o, -o) / G1(o).
  double unitEtaWindow = 0.0;
  // The Charlie sheen channel (table sheen_E): its visibility and alpha.
  SheenVisibility sheenVisibility = SheenVisibility::kCharlie;
  AlphaMapping sheenAlpha = AlphaMapping::kLinear;
  double sheenAlphaMin = 0.0;  // sheen_E at alpha = max(alpha, sheenAlphaMin)

  // The settings the channels' tables are evaluated under: smith,
  // sheenVisibility and sheenAlpha (the rest their defaults).
  BakeSettings TableSettings() const;
};

// What preset.json says of a model: "smith-correlated", "smith-separable",
// "schlick-ggx k = alpha / 2", "smith-joint-approx a = alpha"; "alpha =
// roughness^2", "alpha = roughness".
std::string DescribeVisibility(const PresetModel &model);
const char *DescribeAlpha(AlphaMapping alpha);

// A channel: stored = scale * meaning + offset, meaning a quantity of the
// one list of them (src/presets/channel_source.cpp), each a registered
// table's channel read at the point the texel gives that table, or one of
// a few quantities no table holds:
//   "A", "B"    table dfg's channels at (mu, r = sqrt(alpha)): the split-sum
//               terms int f (1 - (1 - v.h)^5) cos and int f (1 - v.h)^5
//               cos, F = 1 in f, so that Schlick's F0 A + F90 B is the
//               specular albedo; under a fitted G2 (PresetModel::fitted)
//               the same panel quadrature with that G2
//   "E"         A + B, the directional albedo (F = 1)
//   "Eavg"      table Eavg at r: 2 int_0^1 E(mu) mu dmu (1D, over roughness)
//   "sheen_E"   table sheen_E at (mu, the sheen roughness, clamped as
//               sheenAlphaMin says): the Charlie sheen's directional albedo
//   "f82"       table f82 at (mu, r): the F82-tint term C (F0 A + F90 B - a C)
//   "glass_E", "glass_Eavg", "spec_E", "spec_Eavg"  those tables at (mu, r,
//               eta) and (r, eta): rough glass's directional albedo
//               (reflection + transmission) and its average over mu, and
//               the same of the reflection alone; the glass ones 1 within
//               the model's unitEtaWindow
//   "disney_diffuse"  Burley's diffuse albedo as Unity HDRP renormalises it:
//               table burley_E at (mu, the roughness axis itself) / 1.03571
//   "ltc_m00", "ltc_m20", "ltc_m02", "ltc_m22"  the entries of M^-1 of the
//               linearly transformed cosine (models/ltc.h) of the lobe that
//               `table` fits (ltc_ggx by default, ltc_burley, ltc_sheen,
//               ltc_oren_nayar: its channels m00..m22), fitted over the
//               texture's whole (mu, roughness) grid at once
//               (integrators/ltc_fit.h, FitLtcGrid) at the table's
//               coordinate from the model's alpha; "ltc_m11" its middle
//               element, 1. GGX with exact Smith forms only
//   "sheen_B"   the sheen's Schlick-weighted part int D V (1 - o.h)^5 mu_i
//               (HDRP), by the adaptive quadrature (no table holds it)
//   "fabric_lambert"  1 - alpha / 2 (HDRP's FabricLambertNoPI)
//   "zeltner_a", "zeltner_b", "zeltner_R"  Zeltner et al.'s multiple-
//               scattering sheen (OpenPBR's fuzz): its LTC entries a, b and
//               reflectance R from the authors' published table
//               (models/zeltner_sheen_ltc.h), at (mu, alpha = the roughness
//               axis itself), bilinear between its entries as the authors'
//               renderer reads it; not integrated by lutbake, so with no
//               bound of their own (a texel's bound is its storage's only)
//   "clipped_sphere"  ltc_code's horizon-clipped sphere (LTC_2.w): the form
//               factor of a spherical cap, clipped at the horizon, over its
//               unclipped one |F|, at z = 2u - 1 (the cap's axis . n) and
//               |F| = v, u and v the texel's own texture coordinates
//   "one", "zero"  constants (a channel the engine does not read)
// A format that holds only [0, 1] (PNG) takes min(stored, clampMax), and
// one that holds no negative value (RGBD) max(stored, clampMin); the
// texel's bound then adds what the clamp moved it by, so that it still
// covers the value as stored. clampIsValue: the engine's table is defined
// as the clamped value (OSPRay's min(mean, 1)), so the clamp is not an
// error: the bound is the integral's own (a clamp moves two values no
// farther apart).
struct PresetChannel {
  std::string meaning;
  // The table an LTC entry is a fit of (one that fits a lobe); empty: the
  // meaning's own (ltc_ggx). No other meaning takes a table here.
  std::string table = {};
  // stored = scale * meaning / over + offset, `over` another entry of the
  // same fit (Unity HDRP scales M^-1 so that m22 = 1: over = "ltc_m22");
  // empty: none. Only the fit's entries, whose bound is 0, are divided.
  std::string over = {};
  double scale = 1.0, offset = 0.0;
  double clampMin = -1e300, clampMax = 1e300;
  bool clampIsValue = false;
};

// What a channel reads, from the list of quantities: the registered table
// (nullptr: a quantity no table holds), the table's channel (its meaning
// there: "A", "m22"; "" for a fit's m11 or no table), whether the value is
// the table's LTC fit over the texture's grid, and the lobe and its
// parameter in words ("sheen (alpha)"; what preset.json states of a fit).
// Throws std::invalid_argument for an unknown meaning or a table the
// meaning cannot read.
struct PresetChannelSource {
  const TableDefinition *table = nullptr;
  std::string channel;
  bool fitted = false;
  std::string lobe;
};
PresetChannelSource SourceOf(const PresetChannel &channel);

// One texture (or embedded array) of a preset.
struct PresetTexture {
  std::string file;    // the file name written: "dfg.inc", "brdf_lut.png"
  std::string format;  // the --format writer that writes it: "exr", "png16", "ktx2-half", ...
  std::vector<PresetAxis> axes;  // x, then y, then z (1 to 3 axes; z outermost in memory)
  std::vector<PresetChannel> channels;
  PresetModel model;
  std::string sampling;  // the engine's lookup, as its shader writes it
  std::string source;    // the engine file(s) the conventions come from
  std::string notes;     // a defect not reproduced, a clamp, how the engine uses it
};

struct Preset {
  std::string name;     // --preset NAME
  std::string engine;   // "Filament", "Unreal Engine 4/5", ...
  std::string summary;  // one line for `lutbake presets`
  std::vector<PresetTexture> textures;
};

// Every preset, in the order `lutbake presets` lists them, and the one
// called `name` (nullptr if none).
const std::vector<const Preset *> &AllPresets();
const Preset *FindPreset(const std::string &name);
// "filament, unreal, ...".
std::string PresetNameList();

// Every texel of `texture`, with its integration bound, in the texture's
// own memory order: a Table whose axes are u itself (x, y, z over [0, 1] at
// the texture's placement: edges as the linear axis [-h, 1 + h], h = 0.5 /
// (N - 1), whose centres are i / (N - 1); a reversed axis as 1 - u), its
// channels as the engine
// reads them, named R, G, B, A. Bounds: the integrators' bound times
// |scale|. Polls `cancellation` between rows, and reports the fraction of
// rows done to `progress` (from the worker threads, one call at a time).
Table BakePresetTexture(const PresetTexture &texture, const std::string &presetName,
                        const CancellationToken *cancellation = nullptr,
                        const std::function<void(double fraction)> &progress = {});

// One texel of BakePresetTexture: the channels (and their bounds) of the
// texel at memory index (index[0], index[1], index[2]) (unused axes 0). An
// index outside [0, N) is the axis's end (u clamped to [0, 1]), as a table
// read one texel off holds there. `values` and `errors` take one entry per
// channel.
void PresetTexelValues(const PresetTexture &texture, const int index[3], double *values,
                       double *errors);

// How long `bake --preset` will take (bake_estimate.h): a few texels of
// each texture timed; a texel of a texture with LTC channels, fitted over
// its whole grid at once, as the grid fit has it: warm-started from its
// neighbour's fit (computed first, untimed). No more texels of a
// texture are timed once they have taken secondsPerTexture (the listing of
// all presets stays near a second).
BakeEstimate EstimatePresetBake(const Preset &preset, double secondsPerTexture = 0.05);

}  // namespace lutbake
