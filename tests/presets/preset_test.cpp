// Engine presets: each texture agrees with the engine's own shipped table
// in the engine's layout (up to that table's own error, which shows the
// layout is right), with independent values (to the storage's precision,
// which shows the values are), and describes itself in preset.json.
#include "lutbake/presets/preset.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/integrators/furnace.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/lutbake.h"
#include "lutbake/models/sheen.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table_definition.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

using test::DataPath;
using test::ReadCsv;

const PresetTexture &TextureOf(const std::string &preset, size_t index = 0) {
  const Preset *p = FindPreset(preset);
  EXPECT_NE(p, nullptr) << preset;
  return p->textures.at(index);
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// `lutbake bake --preset NAME [--files FILES] --out dir`.
void BakePreset(const std::string &name, const std::filesystem::path &dir,
                const std::vector<std::string> &files = {}) {
  BakeRequest request = test::BakeRequestFor(dir);
  request.preset = name;
  if (!files.empty()) request.presetFiles = files;
  Bake(request);
}

// One file's line of a preset check (`lutbake check DIR` prints "pass FILE"
// or "FAIL FILE"), or null if the check did not read that file.
const PresetFileCheck *FileCheck(const PresetCheck &check, const std::string &file) {
  for (const PresetFileCheck &f : check.files)
    if (f.file == file) return &f;
  return nullptr;
}

TEST(Presets, EveryEngineOfTheIssueIsListed) {
  for (const char *name :
       {"filament", "unreal", "unity-hdrp", "godot", "threejs", "gltf-sample-renderer",
        "learnopengl", "eevee", "cycles", "babylon", "ospray", "materialx"})
    EXPECT_NE(FindPreset(name), nullptr) << name;
  // The listing (`lutbake presets --json`) names every preset.
  const nlohmann::json listed = nlohmann::json::parse(PresetListJson());
  std::vector<std::string> names;
  for (const auto &p : listed["presets"]) names.push_back(p["name"]);
  for (const Preset *p : AllPresets())
    EXPECT_NE(std::find(names.begin(), names.end(), p->name), names.end()) << p->name;
}

// The estimate of a preset bake counts every texel of its textures, times
// at least one texel of each, and the listing carries it.
TEST(Presets, EstimateCountsEveryTexelOfEveryTexture) {
  for (const char *name : {"filament", "cycles", "threejs-ltc"}) {
    const Preset &preset = *FindPreset(name);
    size_t texels = 0;
    for (const PresetTexture &t : preset.textures) {
      size_t n = 1;
      for (const PresetAxis &a : t.axes) n *= static_cast<size_t>(a.count);
      texels += n;
    }
    const BakeEstimate e = EstimatePresetBake(preset);
    EXPECT_EQ(e.texels, texels) << name;
    EXPECT_GE(e.timedTexels, preset.textures.size()) << name;
    EXPECT_TRUE(std::isfinite(e.seconds) && e.seconds > 0.0) << name;
  }
  const nlohmann::json listed = nlohmann::json::parse(PresetListJson(true));
  for (const auto &p : listed["presets"]) EXPECT_GT(p["estimate"]["texels"].get<size_t>(), 0u);
  EXPECT_FALSE(nlohmann::json::parse(PresetListJson())["presets"][0].contains("estimate"));
}

// Cycles' table_ggx_E (2^23 samples, 6 decimals) at its own edge texels, and
// the independent quadrature (1e-10) at exactly those points.
TEST(Presets, CyclesEdgeTexelsMatchCyclesAndTheReference) {
  const Table table = BakePresetTexture(TextureOf("cycles"), "cycles");
  ASSERT_EQ(table.width(), 32);
  ASSERT_EQ(table.height(), 32);
  const auto rows = ReadCsv(DataPath("presets/cycles_table_ggx_E.csv"));
  ASSERT_EQ(rows.size(), 1024u);
  double worstPeer = 0, worstRef = 0;
  for (const auto &row : rows) {
    const int x = static_cast<int>(row.Number("col_x")), y = static_cast<int>(row.Number("row_y"));
    const double ours = table.value(x, y);
    const double stored = StoredValue(ours, ValueType::kFloat32);
    const double bound = StoredBound(ours, table.errors[table.index(x, y, 0)], ValueType::kFloat32);
    EXPECT_LE(std::abs(stored - row.Number("ref_E_hc")), bound + 1e-10) << x << " " << y;
    worstRef = std::max(worstRef, std::abs(stored - row.Number("ref_E_hc")));
    worstPeer = std::max(worstPeer, std::abs(stored - row.Number("cycles_E")));
  }
  // Cycles' own error: 9.9e-7 (refdata) plus its 6-decimal printing.
  EXPECT_LT(worstPeer, 1.5e-6);
  EXPECT_LT(worstRef, 1e-7);
}

// Cycles' glass tables at a quarter of their texels in each axis: an axis
// of 4 edge texels puts u at 0, 1/3, 2/3, 1, Cycles' texels 0, 5, 10, 15 of
// 16. The eta > 1 table agrees with Cycles' own (2^23 samples, 6 decimals:
// within 1.3e-5 at all 4096 texels, docs/presets.md "Cycles' glass tables,
// measured"), which shows the layout: x = rough, y = mu, z = the IOR axis;
// both tables agree with the independent adaptive reference at exactly
// those points; slice 0 (ior = 1) is 1. Cycles' shipped inverse table holds
// the 2023 sampler's excess (tests/data/glass/README.md), far above this.
TEST(Presets, CyclesGlassAlbedoAtCyclesTexels) {
  const Preset *cycles = FindPreset("cycles");
  ASSERT_NE(cycles, nullptr);
  ASSERT_EQ(cycles->textures.size(), 6u);
  for (const bool inside : {false, true}) {
    PresetTexture texture = cycles->textures[inside ? 4 : 2];
    ASSERT_EQ(texture.axes.size(), 3u);
    EXPECT_EQ(texture.axes[2].quantity, inside ? "1/eta" : "eta");
    for (PresetAxis &axis : texture.axes) {
      ASSERT_EQ(axis.count, 16);
      axis.count = 4;
    }
    const Table table = BakePresetTexture(texture, "cycles");
    ASSERT_TRUE(table.is3D());
    ASSERT_EQ(table.values.size(), 64u);
    const auto rows = ReadCsv(DataPath(inside ? "glass/peers/cycles_ggx_glass_inv_E.csv"
                                              : "glass/peers/cycles_ggx_glass_E.csv"));
    ASSERT_EQ(rows.size(), 4096u);
    double worstPeer = 0.0, worstReference = 0.0;
    int referenced = 0;
    for (const auto &row : rows) {
      const int x = static_cast<int>(row.Number("ix")), y = static_cast<int>(row.Number("iy")),
                z = static_cast<int>(row.Number("iz"));
      if (x % 5 || y % 5 || z % 5) continue;
      const size_t at = table.index(x / 5, y / 5, z / 5, 0);
      const double ours = StoredValue(table.values[at], ValueType::kFloat32);
      const double bound = StoredBound(table.values[at], table.errors[at], ValueType::kFloat32);
      if (z == 0) {  // ior = 1: Cycles' closure passes light through
        EXPECT_EQ(ours, 1.0) << x << " " << y;
        EXPECT_EQ(bound, 0.0);
        continue;
      }
      const double ior = row.Number("ior"), eta = inside ? 1.0 / ior : ior;
      const double rough = row.Number("rough"), mu = row.Number("mu");
      if (!inside) worstPeer = std::max(worstPeer, std::abs(ours - row.Number("value")));
      if (inside) worstPeer = std::max(worstPeer, row.Number("value") - ours);
      if (rough < 0.3) continue;  // the adaptive rule needs the lobe wider than ~0.01
      const DielectricIntegral reference = IntegrateDielectricAlbedoAdaptive(
          NdfKind::kGgx, SmithForm::kCorrelated, DielectricLobes::kReflectionAndTransmission,
          rough * rough, mu, eta, 1e-10);
      ASSERT_TRUE(reference.converged);
      // The texel's point is Cycles' up to a float ulp of rough, mu and z
      // (the generator's float arithmetic): 1e-7 covers that.
      EXPECT_LE(std::abs(ours - reference.value), bound + reference.bound + 1e-7)
          << (inside ? "inside" : "outside") << " rough " << rough << " mu " << mu << " ior "
          << ior;
      worstReference = std::max(worstReference, std::abs(ours - reference.value));
      ++referenced;
    }
    EXPECT_EQ(referenced, 3 * 4 * 3);  // rough 1/3, 2/3, 1; 4 mu; 3 IORs
    EXPECT_LT(worstReference, 2e-7);
    if (inside) {
      EXPECT_GT(worstPeer, 0.1);  // the shipped excess, above today's albedo
    } else {
      EXPECT_LT(worstPeer, 3e-5);
    }
    RecordProperty(inside ? "inside_worst_peer" : "outside_worst_peer", std::to_string(worstPeer));
  }
}

// The averages: the eta > 1 table against Cycles' own (2^26 samples), the
// inside one (Cycles' is wrong there) by reciprocity of the transmitted
// parts with the outside one at ior = 1.25 (dielectric.h):
//   glass_Eavg(1/eta) = spec_Eavg(1/eta) + (glass_Eavg(eta) - spec_Eavg(eta)) / eta^2.
TEST(Presets, CyclesGlassAveragesAtCyclesTexels) {
  const Preset *cycles = FindPreset("cycles");
  ASSERT_NE(cycles, nullptr);
  Table tables[2];
  for (const bool inside : {false, true}) {
    PresetTexture texture = cycles->textures[inside ? 5 : 3];
    ASSERT_EQ(texture.axes.size(), 2u);
    EXPECT_EQ(texture.axes[1].quantity, inside ? "1/eta" : "eta");
    // rough 1/3, 2/3, 1 (Cycles' 5, 10, 15; texel 0 is clamped up to 1/3
    // too: near-smooth averages cost seconds), ior at z = 1e-4, 1/3, 2/3,
    // 0.99 (Cycles' 0, 5, 10, 15).
    texture.axes[0].count = 4;
    texture.axes[0].lowest = 1.0 / 3.0;
    texture.axes[1].count = 4;
    // The inside averages cost 2 s each: only rough 1 (through the axis's
    // clamp) at ior = 1 and 1.25 = Cycles' slice 5 (the clamp again),
    // texels (0, 0) and (0, 1).
    if (inside) {
      texture.axes[0].count = 1;
      texture.axes[0].lowest = 1.0;
      texture.axes[1].count = 2;
      texture.axes[1].highest = 1.25;
    }
    tables[inside] = BakePresetTexture(texture, "cycles");
  }
  const auto rows = ReadCsv(DataPath("glass/peers/cycles_ggx_glass_Eavg.csv"));
  ASSERT_EQ(rows.size(), 256u);
  double worstPeer = 0.0;
  for (const auto &row : rows) {
    const int x = static_cast<int>(row.Number("ix")), z = static_cast<int>(row.Number("iz"));
    if (x == 0 || x % 5 || z % 5) continue;
    if (z == 0) {
      EXPECT_EQ(tables[0].value(x / 5, 0), 1.0);
      EXPECT_EQ(tables[1].value(0, 0), 1.0);
    }
    worstPeer = std::max(worstPeer, std::abs(tables[0].value(x / 5, z / 5) - row.Number("value")));
  }
  EXPECT_LT(worstPeer, 2e-5);
  RecordProperty("outside_worst_peer", std::to_string(worstPeer));
  // Reciprocity at rough 1, ior 1.25 (texel (3, 1) outside, (0, 1) inside).
  const double ior = 1.25, alpha = 1.0, tolerance = 1e-8;
  const auto spec = [&](double eta) {
    return IntegrateDielectricAverage(NdfKind::kGgx, SmithForm::kCorrelated,
                                      DielectricLobes::kReflection, alpha, eta, tolerance);
  };
  const DielectricIntegral specOut = spec(ior), specIn = spec(1.0 / ior);
  ASSERT_EQ(tables[1].values.size(), 2u);
  const double outside = tables[0].value(3, 1), inside = tables[1].value(0, 1);
  const double bounds = tables[0].errors[tables[0].index(3, 1, 0)] / (ior * ior) +
                        tables[1].errors[tables[1].index(0, 1, 0)] + specIn.bound +
                        specOut.bound / (ior * ior);
  EXPECT_NEAR(inside, specIn.value + (outside - specOut.value) / (ior * ior), bounds);
}

// preset.json of a glass table (3D: depth, the z axis and its IOR mapping),
// written with --files, and CheckPresetDirectory (`check`) reading it back. (The inside table's
// axis is the same with quantity 1/eta, CyclesGlassAlbedoAtCyclesTexels.)
TEST(Presets, CyclesGlassPresetJsonAndCheck) {
  const auto dir = test::Scratch("preset_cycles_glass");
  BakePreset("cycles", dir, {"table_ggx_glass_E.h"});
  std::ifstream in(dir / "preset.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  ASSERT_EQ(manifest["files"].size(), 1u);
  const nlohmann::json &f = manifest["files"][0];
  EXPECT_EQ(f["file"], "table_ggx_glass_E.h");
  EXPECT_EQ(f["width"], 16);
  EXPECT_EQ(f["height"], 16);
  EXPECT_EQ(f["depth"], 16);
  ASSERT_EQ(f["axes"].size(), 3u);
  EXPECT_EQ(f["axes"][0]["quantity"], "roughness");
  EXPECT_EQ(f["axes"][1]["quantity"], "mu");
  const nlohmann::json &z = f["axes"][2];
  EXPECT_EQ(z["axis"], "z");
  EXPECT_EQ(z["quantity"], "eta");
  EXPECT_EQ(z["mapping"], "eta = (1 + u^2) / (1 - u^2)");
  EXPECT_EQ(z["placement"], "edges");
  EXPECT_DOUBLE_EQ(z["clamp"][0].get<double>(), 1.0);
  EXPECT_NEAR(z["clamp"][1].get<double>(), 99.5026932, 1e-6);
  EXPECT_EQ(f["channels"][0]["meaning"], "glass_E");
  EXPECT_EQ(f["model"]["unitEtaWindow"], 1e-4);
  // Float32-exact: the integration bound and float32 rounding together.
  // (The inside table's errorMax is 4.9e-7, where Cycles' grid puts the view
  // on a kink of the inside albedo: docs/presets.md.)
  EXPECT_LT(f["errorMax"].get<double>(), 6e-8);
  const Table read = ReadSourceTable((dir / "table_ggx_glass_E.h").string());
  EXPECT_EQ(read.values.size(), 4096u);
  const PresetCheck checked = CheckPresetDirectory(dir.string());
  EXPECT_TRUE(checked.pass) << checked.json;
  const PresetFileCheck *glass = FileCheck(checked, "table_ggx_glass_E.h");
  ASSERT_NE(glass, nullptr) << checked.json;
  EXPECT_TRUE(glass->pass) << checked.json;
  EXPECT_EQ(FileCheck(checked, "table_ggx_E.h"), nullptr) << checked.json;
}

// three.js's 32 x 32 table (r181, 4096 samples): the transposed layout
// (x = roughness, y = NdotV) and the independent values at its texels.
TEST(Presets, ThreejsLayoutMatchesItsTableAndValuesTheReference) {
  PresetTexture texture = TextureOf("threejs");
  texture.axes[0].count = texture.axes[1].count = 32;
  const Table table = BakePresetTexture(texture, "threejs");
  const auto rows = ReadCsv(DataPath("presets/threejs_dfg_lut_32x32.csv"));
  ASSERT_EQ(rows.size(), 1024u);
  std::vector<double> peer, transposed;
  for (const auto &row : rows) {
    const int x = static_cast<int>(row.Number("col_x")), y = static_cast<int>(row.Number("row_y"));
    for (int c = 0; c < 2; ++c) {
      const double ours = table.value(x, y, c), bound = table.errors[table.index(x, y, c)];
      EXPECT_LE(std::abs(ours - row.Number(c ? "ref_B_hc" : "ref_A_hc")), bound + 1e-11);
      const double theirs = row.Number(c ? "three_bias_B" : "three_scale_A");
      peer.push_back(std::abs(ours - theirs));
      transposed.push_back(std::abs(table.value(y, x, c) - theirs));
    }
  }
  // Half floats and 4096 samples: three.js is within 1.9e-2 at grazing
  // rows, ~1e-4 typically; read transposed it is far off.
  EXPECT_LT(*std::max_element(peer.begin(), peer.end()), 2e-2);
  EXPECT_LT(Median(peer), 1e-3);
  EXPECT_GT(Median(transposed), 2e-2);

  // The current 16 x 16 table, as the preset writes it (half floats).
  const Table current = BakePresetTexture(TextureOf("threejs"), "threejs");
  const auto rows16 = ReadCsv(DataPath("presets/threejs_dfg_lut_16x16.csv"));
  ASSERT_EQ(rows16.size(), 256u);
  std::vector<double> diff16;
  for (const auto &row : rows16) {
    const int x = static_cast<int>(row.Number("i")), y = static_cast<int>(row.Number("j"));
    diff16.push_back(
        std::abs(StoredValue(current.value(x, y, 0), ValueType::kHalf) - row.Number("R_A_scale")));
    diff16.push_back(
        std::abs(StoredValue(current.value(x, y, 1), ValueType::kHalf) - row.Number("G_B_bias")));
  }
  EXPECT_LT(*std::max_element(diff16.begin(), diff16.end()), 1.5e-2);
  EXPECT_LT(Median(diff16), 1e-3);
}

// Filament's shipped 64 x 64 dfg.inc (v1.19.0, 1024 samples for B and E):
// R = B, G = E, B = cloth. Its memory row j was integrated at roughness
// (j + 1.5) / 64, the preset's row j + 1: the shifted comparison agrees to
// the peer's noise, the unshifted one shows the defect the preset does not
// reproduce.
TEST(Presets, FilamentChannelsMatchItsTableOneRowShifted) {
  const Table table = BakePresetTexture(TextureOf("filament-mobile"), "filament-mobile");
  ASSERT_EQ(table.width(), 64);
  ASSERT_EQ(table.channels, 3);
  const auto rows = ReadCsv(DataPath("presets/filament_dfg_64x64.csv"));
  ASSERT_EQ(rows.size(), 4096u);
  std::vector<double> shifted, unshifted, cloth;
  for (const auto &row : rows) {
    const int i = static_cast<int>(row.Number("i")), j = static_cast<int>(row.Number("j"));
    if (j + 1 >= 64) continue;
    for (int c = 0; c < 2; ++c) {
      const double theirs = row.Number(c ? "G_E" : "R_B");
      shifted.push_back(std::abs(table.value(i, j + 1, c) - theirs));
      unshifted.push_back(std::abs(table.value(i, j, c) - theirs));
    }
    // The cloth channel (4096 uniform samples of a peaked lobe) where the
    // peer's estimator is not dominated by its noise.
    if ((j + 1.5) / 64 >= 0.5)
      cloth.push_back(std::abs(table.value(i, j + 1, 2) - row.Number("B_sheenE_ashikhmin")));
  }
  EXPECT_LT(Median(shifted), 2e-3);
  EXPECT_GT(Median(unshifted), 3.0 * Median(shifted));
  EXPECT_LT(Median(cloth), 5e-3);
}

// The fitted visibilities against the furnace integrator (adaptive
// Gauss-Kronrod over the half vector, another code path): Schlick-GGX.
TEST(Presets, SchlickGgxTexelsMatchTheFurnaceIntegrator) {
  for (const char *name : {"learnopengl", "godot"}) {
    PresetTexture texture = TextureOf(name);
    texture.axes[0].count = texture.axes[1].count = 12;
    const Table table = BakePresetTexture(texture, name);
    const bool rb = texture.channels[0].meaning == "B";  // godot: R = B, G = E
    for (int iy = 0; iy < 12; ++iy) {
      const PresetAxis &ra = texture.axes[1];
      const double r = ra.Quantity(ra.reversed ? 11 - iy : iy);
      FurnaceModel m;
      m.kind = FurnaceModelKind::kMicrofacet;
      m.visibility = FurnaceVisibility::kSchlickGgxIbl;
      m.fresnel = FurnaceFresnel::kSchlick;
      m.f0 = 0.0;
      const FurnaceIntegrator b(m, r);
      m.f0 = 1.0;
      const FurnaceIntegrator e(m, r);
      for (int ix = 0; ix < 12; ++ix) {
        const double mu = texture.axes[0].Quantity(ix);
        const FurnaceValue B = b.Albedo(mu).albedo, E = e.Albedo(mu).albedo;
        const double first = rb ? B.value : E.value - B.value, second = rb ? E.value : B.value;
        const double firstError = rb ? B.error : E.error + B.error,
                     secondError = rb ? E.error : B.error;
        EXPECT_LE(std::abs(table.value(ix, iy, 0) - first),
                  table.errors[table.index(ix, iy, 0)] + firstError)
            << name << " mu " << mu << " r " << r;
        EXPECT_LE(std::abs(table.value(ix, iy, 1) - second),
                  table.errors[table.index(ix, iy, 1)] + secondError)
            << name << " mu " << mu << " r " << r;
      }
    }
  }
}

// A brute-force albedo over light directions (theta_i, phi_i), Gauss-Legendre
// on panels x panels panels of 24 nodes, for integrands that are smooth above the
// horizon: f(mu_o, i) mu_i.
template <class F>
double BruteForceAlbedo(F brdf, int panels = 8) {
  const GaussLegendreRule &rule = GaussLegendre(24);
  const double pi = 3.14159265358979323846;
  double sum = 0;
  for (int pt = 0; pt < panels; ++pt)
    for (int pp = 0; pp < panels; ++pp)
      for (int a = 0; a < rule.n; ++a)
        for (int b = 0; b < rule.n; ++b) {
          const double theta = (pt + rule.x[a]) / panels * (pi / 2);
          const double phi = (pp + rule.x[b]) / panels * pi;
          const double w = rule.w[a] * rule.w[b] * (pi / 2 / panels) * (pi / panels);
          const double mu_i = std::cos(theta), s_i = std::sin(theta);
          sum += 2 * w * brdf(mu_i, s_i, phi) * mu_i * s_i;
        }
  return sum;
}

// Unity HDRP's Disney diffuse channel (z + 0.5) against the BRDF integrated
// by brute force: the closed azimuth and polynomial rule of the preset are
// not used.
TEST(Presets, HdrpDisneyDiffuseMatchesBruteForce) {
  const PresetTexture &texture = TextureOf("unity-hdrp");
  const Table table = BakePresetTexture(texture, "unity-hdrp");
  const double pi = 3.14159265358979323846;
  for (int ix : {0, 5, 31, 63})
    for (int iy : {0, 17, 40, 63}) {
      const double mu_o = texture.axes[0].Quantity(ix), p = texture.axes[1].Quantity(iy);
      const double s_o = std::sqrt(1 - mu_o * mu_o);
      const double value = BruteForceAlbedo([&](double mu_i, double s_i, double phi) {
        const double lv = mu_o * mu_i + s_o * s_i * std::cos(phi);
        const double fd90 = 0.5 + p + p * lv;
        const auto F = [&](double u) { return 1 + (fd90 - 1) * std::pow(1 - u, 5); };
        return F(mu_i) * F(mu_o) / 1.03571 / pi;
      });
      EXPECT_NEAR(table.value(ix, iy, 2) + 0.5, value, 1e-9) << mu_o << " " << p;
    }
  // The axes: x holds sqrt(NdotV) at texel edges.
  EXPECT_DOUBLE_EQ(texture.axes[0].Quantity(63), 1.0);
  EXPECT_DOUBLE_EQ(texture.axes[0].Quantity(21), (21.0 / 63) * (21.0 / 63));
}

// Unreal's Vis_SmithJointApprox split sum against the BRDF integrated over
// light directions (the horizon is the hemisphere's edge here: no cut).
TEST(Presets, UnrealJointApproxMatchesBruteForce) {
  PresetTexture texture = TextureOf("unreal");
  const Table table = BakePresetTexture(texture, "unreal");
  const double pi = 3.14159265358979323846;
  for (int ix : {3, 40, 90, 127})
    for (int iy : {12, 20, 31}) {  // roughness >= 0.39: the lobe is wide enough for the rule
      const double mu_o = texture.axes[0].Quantity(ix), r = texture.axes[1].Quantity(iy);
      const double a = r * r, s_o = std::sqrt(1 - mu_o * mu_o);
      double weights[2];
      for (int c = 0; c < 2; ++c)
        weights[c] = BruteForceAlbedo(
            [&](double mu_i, double s_i, double phi) {
              const double hx = s_o + s_i * std::cos(phi), hy = s_i * std::sin(phi),
                           hz = mu_o + mu_i;
              const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
              const double nh = hz / len, vh = (s_o * hx + mu_o * hz) / len;
              const double d = a * a / (pi * std::pow(nh * nh * (a * a - 1) + 1, 2));
              const double vis = 0.5 / (mu_i * (mu_o * (1 - a) + a) + mu_o * (mu_i * (1 - a) + a));
              const double fc = std::pow(1 - vh, 5);
              return d * vis * (c == 0 ? 1 - fc : fc);
            },
            32);
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(table.value(ix, iy, c), weights[c], 2e-6) << mu_o << " " << r << " " << c;
    }
}

// EEVEE: x = roughness at edges, y = sqrt(1 - NV) at edges, channel 2 the
// F82 term; against the tables it is made of, at its own coordinates.
TEST(Presets, EeveeAxesAreEdgesInSqrtOneMinusNv) {
  const PresetTexture &texture = TextureOf("eevee");
  EXPECT_DOUBLE_EQ(texture.axes[1].Quantity(0), 1.0);
  EXPECT_DOUBLE_EQ(texture.axes[1].Quantity(63), 0.0);
  EXPECT_DOUBLE_EQ(texture.axes[1].Quantity(21), 1.0 - (21.0 / 63) * (21.0 / 63));
  EXPECT_DOUBLE_EQ(texture.axes[0].Quantity(63), 1.0);
  const Table table = BakePresetTexture(texture, "eevee");
  // Row 0 is normal incidence: the mirror column (r = 0) is A = 1, B = 0.
  EXPECT_NEAR(table.value(0, 0, 0), 1.0, 1e-12);
  EXPECT_NEAR(table.value(0, 0, 1), 0.0, 1e-12);
  // F0 A + F90 B - a C stays in [0, 1] at F82-tint's extremes.
  for (int iy = 0; iy < 64; ++iy)
    for (int ix = 0; ix < 64; ++ix) {
      EXPECT_GE(table.value(ix, iy, 2), -1e-12);
      EXPECT_LE(table.value(ix, iy, 2), table.value(ix, iy, 1) / 4 + 1e-9);
    }
}

// Blender's own brdf_ggx (eevee_next at bfc6978, two channels; 13 of its 64
// rows, printed to 6 decimals): brdf_ggx[j][i] with j the sqrt(1 - NV) row.
// The bias B, a small sum, agrees to its printed digits up to the middle
// rows, which only the right layout does (one row off or transposed misses
// by far more). The scale A is off by up to 3e-3 near roughness 0, where
// the exact A + B is 1 and Blender's exceeds it: its generator sums 512^2
// samples of about 1 in a float (spacing 1/32 near the total).
TEST(Presets, EeveeLayoutMatchesBlendersTable) {
  const Table table = BakePresetTexture(TextureOf("eevee"), "eevee");
  const auto rows = ReadCsv(DataPath("presets/eevee_brdf_ggx_rows.csv"));
  ASSERT_EQ(rows.size(), 13u * 64u);
  std::vector<double> scale, bias, biasRowOff, biasTransposed;
  for (const auto &row : rows) {
    const int i = static_cast<int>(row.Number("i")), j = static_cast<int>(row.Number("j"));
    const double theirsA = row.Number("blender_A"), theirsB = row.Number("blender_B");
    scale.push_back(std::abs(table.value(i, j, 0) - theirsA));
    bias.push_back(std::abs(table.value(i, j, 1) - theirsB));
    if (j <= 32) {
      EXPECT_NEAR(table.value(i, j, 1), theirsB, 2e-6) << "i " << i << " j " << j;
    }
    if (j < 63) biasRowOff.push_back(std::abs(table.value(i, j + 1, 1) - theirsB));
    biasTransposed.push_back(std::abs(table.value(j, i, 1) - theirsB));
    // At the mirror column the exact scale is 1 - (1 - NV)^5.
    if (i == 0 && j < 63) {
      const double nv = 1.0 - (j / 63.0) * (j / 63.0);
      EXPECT_NEAR(table.value(0, j, 0), 1.0 - std::pow(1.0 - nv, 5), 1e-9);
    }
  }
  EXPECT_LT(Median(bias), 1e-6);
  EXPECT_LT(Median(scale), 1e-4);
  EXPECT_GT(Median(biasRowOff), 50.0 * Median(bias));
  EXPECT_GT(Median(biasTransposed), 1e-2);
}

// A preset bake: the files, and preset.json describing them well enough to
// read the file without knowing the preset.
TEST(Presets, BakeWritesFilesAndPresetJsonThatDescribesThem) {
  const auto dir = test::Scratch("preset_unreal");
  BakePreset("unreal", dir);
  std::ifstream in(dir / "preset.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["preset"], "unreal");
  ASSERT_EQ(manifest["files"].size(), 1u);
  const auto &f = manifest["files"][0];
  EXPECT_EQ(f["file"], "PreIntegratedGF.png");
  EXPECT_EQ(f["storage"], "unorm16");
  EXPECT_EQ(f["axes"][0]["quantity"], "mu");
  EXPECT_EQ(f["axes"][0]["placement"], "centres");
  EXPECT_EQ(f["axes"][1]["quantity"], "roughness");
  EXPECT_EQ(f["channels"][0]["meaning"], "A");
  EXPECT_EQ(f["channels"][1]["meaning"], "B");
  // Read the PNG with OpenImageIO and compare with the integral at the
  // coordinates preset.json states, within its errorMax.
  auto image = OIIO::ImageInput::open((dir / "PreIntegratedGF.png").string());
  ASSERT_TRUE(image);
  const OIIO::ImageSpec spec = image->spec();
  ASSERT_EQ(spec.width, 128);
  ASSERT_EQ(spec.height, 32);
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(image->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  const double errorMax = f["errorMax"];
  EXPECT_LT(errorMax, 1e-5);
  const Table exact = BakePresetTexture(TextureOf("unreal"), "unreal");
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 128; ++x)
      for (int c = 0; c < 2; ++c)
        ASSERT_LE(std::abs(pixels[(static_cast<size_t>(y) * 128 + x) * spec.nchannels + c] -
                           exact.value(x, y, c)),
                  errorMax + 1e-7);
}

// HDRP's Charlie + fabric texture: x = B / 2 pi, y = E / 2 pi against a
// brute-force integral of D W (1 - o.h)^5 over light directions (the
// library's Charlie D and visibility, not its integrators), z = 1 - alpha/2.
TEST(Presets, HdrpCharlieMatchesBruteForce) {
  const PresetTexture &texture = TextureOf("unity-hdrp", 1);
  PresetTexture small = texture;
  small.axes[0].count = small.axes[1].count = 8;  // centres at (i + 0.5) / 8
  const Table table = BakePresetTexture(small, "unity-hdrp");
  const double pi = 3.14159265358979323846;
  for (int ix : {1, 4, 7})
    for (int iy : {3, 5, 7}) {  // alpha >= 0.19: smooth enough for the rule
      const double mu_o = small.axes[0].Quantity(ix), p = small.axes[1].Quantity(iy);
      const double alpha = p * p, s_o = std::sqrt(1 - mu_o * mu_o);
      double weighted[2];
      for (int c = 0; c < 2; ++c)
        weighted[c] = BruteForceAlbedo(
            [&](double mu_i, double s_i, double phi) {
              const double hx = s_o + s_i * std::cos(phi), hy = s_i * std::sin(phi),
                           hz = mu_o + mu_i;
              const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
              const double nh = hz / len, vh = (s_o * hx + mu_o * hz) / len;
              const double d = CharlieD(alpha, (1 - nh) * (1 + nh));
              const double w = SheenCosineVisibility(SheenVisibility::kCharlie, alpha, mu_o, mu_i);
              return d * w / mu_i * (c == 0 ? std::pow(1 - vh, 5) : 1.0);
            },
            32);
      EXPECT_NEAR(table.value(ix, iy, 0) * 2 * pi, weighted[0], 2e-6) << mu_o << " " << p;
      EXPECT_NEAR(table.value(ix, iy, 1) * 2 * pi, weighted[1], 2e-6) << mu_o << " " << p;
      EXPECT_DOUBLE_EQ(table.value(ix, iy, 2), 1 - alpha / 2);
    }
}

// Every preset's files read back by CheckPresetDirectory (`lutbake check`)
// against the preset integrated again; a tampered value fails it.
TEST(Presets, CheckReadsEveryPresetDirectoryBack) {
  // unity-hdrp is left out: its Charlie texture takes ~35 s to integrate
  // (twice here); HdrpCharlieMatchesBruteForce holds its values.
  for (const char *name : {"filament-mobile", "unreal", "godot", "threejs", "learnopengl", "eevee",
                           "cycles", "materialx"}) {
    const auto dir = test::Scratch(std::string("preset_check_") + name);
    // Cycles' glass averages take minutes: its 2D tables here, its glass
    // tables in CyclesGlassPresetJsonAndCheck.
    const std::vector<std::string> files =
        std::string(name) == "cycles"
            ? std::vector<std::string>{"table_ggx_E.h", "table_ggx_Eavg.h"}
            : std::vector<std::string>{};
    BakePreset(name, dir, files);
    const PresetCheck checked = CheckPresetDirectory(dir.string());
    EXPECT_TRUE(checked.pass) << name << "\n" << checked.json;
    for (const PresetFileCheck &f : checked.files)
      EXPECT_TRUE(f.pass) << f.file << ": " << f.problem;
  }
  // Tamper with Cycles' E: one literal changed in its last digits.
  const auto dir = test::Scratch("preset_check_cycles_tampered");
  BakePreset("cycles", dir, {"table_ggx_E.h"});
  const auto path = dir / "table_ggx_E.h";
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const size_t at = text.find("0.980404");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 8, "0.980504");
  std::ofstream(path) << text;
  const PresetCheck tampered = CheckPresetDirectory(dir.string());
  EXPECT_FALSE(tampered.pass) << tampered.json;
  const PresetFileCheck *e = FileCheck(tampered, "table_ggx_E.h");
  ASSERT_NE(e, nullptr) << tampered.json;
  EXPECT_FALSE(e->pass) << tampered.json;
}

// three.js's module: its own API (getDFGLUT over a DataTexture of halves)
// and the halves of the exact values.
TEST(Presets, ThreejsModuleIsThreejsFile) {
  const auto dir = test::Scratch("preset_threejs_module");
  BakePreset("threejs", dir);
  std::ifstream in(dir / "DFGLUTData.js");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("export function getDFGLUT()"), std::string::npos);
  EXPECT_NE(text.find("new DataTexture( DATA, 16, 16, RGFormat, HalfFloatType )"),
            std::string::npos);
  EXPECT_NE(text.find("from '../../constants.js'"), std::string::npos);
  const Table read = ReadSourceTable((dir / "DFGLUTData.js").string());
  const Table exact = BakePresetTexture(TextureOf("threejs"), "threejs");
  ASSERT_EQ(read.values.size(), exact.values.size());
  for (size_t i = 0; i < exact.values.size(); ++i)
    ASSERT_EQ(read.values[i], StoredValue(exact.values[i], ValueType::kHalf)) << i;
}

// OSPRay's arrays: its texels (edges, cosThetaO clamped to 1e-6, alpha =
// max(r^2, 0.001), OSPRay's eta the inverse of lutbake's) against the
// tables evaluated here at those points, the index-matched slice (eta = 1:
// no reflection, full transmission through the microfacets), and `check`
// of the directory. Its generator, re-run, is in engine_generators_test.py.
TEST(Presets, OsprayArraysHoldTheTablesAtOspraysTexels) {
  const auto dir = test::Scratch("preset_ospray");
  BakePreset(
      "ospray", dir,
      {"MicrofacetAlbedoTable_dir.ih", "MicrofacetAlbedoTable_avg.ih",
       "MicrofacetDielectricAlbedoTable_dir.ih", "MicrofacetDielectricReflectionAlbedoTable_dir.ih",
       "MicrofacetSheenAlbedoTable_dir.ih"});
  const Table e = ReadSourceTable((dir / "MicrofacetAlbedoTable_dir.ih").string());
  const Table glass = ReadSourceTable((dir / "MicrofacetDielectricAlbedoTable_dir.ih").string());
  const Table spec =
      ReadSourceTable((dir / "MicrofacetDielectricReflectionAlbedoTable_dir.ih").string());
  ASSERT_EQ(e.values.size(), 32u * 32u);
  ASSERT_EQ(glass.values.size(), 16u * 16u * 16u);
  const auto roughnessOf = [](double r) { return std::sqrt(std::max(r * r, 0.001)); };
  BakeSettings settings;
  for (int j : {0, 3, 17, 31})
    for (int i : {0, 1, 15, 31}) {
      const double mu = std::max(i / 31.0, 1e-6);
      const double exact = TableNamed("E").Evaluate(settings, mu, roughnessOf(j / 31.0)).value[0];
      EXPECT_NEAR(e.values[static_cast<size_t>(j) * 32 + i], exact, 1e-7) << i << " " << j;
    }
  const double third = static_cast<double>(1.0f / 3.0f);
  for (int k : {2, 9, 15})
    for (int jEta : {0, 7, 15})
      for (int i : {1, 8, 15}) {
        const double ospraysEta = third + jEta / 15.0 * (1.0 - third);
        const size_t at = (static_cast<size_t>(k) * 16 + jEta) * 16 + i;
        const double r = roughnessOf(k / 15.0);
        const double g =
            TableNamed("glass_E").Evaluate3D(settings, i / 15.0, r, 1.0 / ospraysEta).value[0];
        const double s =
            TableNamed("spec_E").Evaluate3D(settings, i / 15.0, r, 1.0 / ospraysEta).value[0];
        EXPECT_NEAR(glass.values[at], g, 1e-7) << i << " " << jEta << " " << k;
        EXPECT_NEAR(spec.values[at], s, 1e-7) << i << " " << jEta << " " << k;
        // Index matched: F = 0, nothing reflects; the microfacets still
        // shadow the transmitted light: G2(o, -o) / G1(o) = (1 + Lambda) /
        // (1 + 2 Lambda), 8 / 15 at the roughest grazing texel, 1 at mu = 1.
        if (jEta == 15) {
          EXPECT_EQ(spec.values[at], 0.0);
          EXPECT_LE(glass.values[at], 1.0);
          EXPECT_GT(glass.values[at], 0.5);
          if (k == 15 && i == 1) {
            EXPECT_NEAR(glass.values[at], 8.0 / 15.0, 1e-6);
          }
        }
      }
  // The sheen albedo: sheen r = max(roughness^2, 0.001), OSPRay's softened
  // light Lambda, min(E, 1); against the adaptive rule (not the panel rule
  // the bake used). Charlie's plain visibility is far from it: the
  // visibility is OSPRay's.
  const Table sheen = ReadSourceTable((dir / "MicrofacetSheenAlbedoTable_dir.ih").string());
  ASSERT_EQ(sheen.values.size(), 16u * 16u);
  double charlieFarthest = 0.0;
  for (int j : {0, 4, 9, 15})
    for (int i : {0, 1, 7, 15}) {
      const double alpha = std::max(Sqr(j / 15.0), 0.001);
      const double mu = std::max(i / 15.0, 1e-6);
      const SheenIntegral ospray =
          IntegrateSheenAlbedoAdaptive(SheenVisibility::kOspray, alpha, mu, 1e-10);
      const double stored = sheen.values[static_cast<size_t>(j) * 16 + i];
      EXPECT_NEAR(stored, std::min(ospray.value, 1.0), 1e-6) << i << " " << j;
      if (ospray.value >= 1.0) {
        EXPECT_EQ(stored, 1.0) << i << " " << j;
      }
      const double charlie =
          IntegrateSheenAlbedoAdaptive(SheenVisibility::kCharlie, alpha, mu, 1e-10).value;
      charlieFarthest = std::max(charlieFarthest, std::abs(std::min(charlie, 1.0) - stored));
    }
  EXPECT_GT(charlieFarthest, 1e-2);
  const PresetCheck checked = CheckPresetDirectory(dir.string());
  EXPECT_TRUE(checked.pass) << checked.json;
}

}  // namespace
}  // namespace lutbake
