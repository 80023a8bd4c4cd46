// The rough-dielectric tables (glass_E, glass_Eavg, spec_E, spec_Eavg)
// through the table definitions and the command line: the exact limits
// (smooth interface, eta = 1), the reciprocity of the transmitted averages
// between the two sides, eval of three coordinates, a small 3D bake in every
// format checked by `lutbake check`, and the header's trilinear lookup and
// helpers compiled and run.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lutbake/api/bake.h"
#include "lutbake/api/check.h"
#include "lutbake/api/eval.h"
#include "lutbake/api/plan.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/models/fresnel.h"
#include "lutbake/models/ndf.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/validation/check.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

// `lutbake bake --out DIR --tables TABLES --size N [--eta-size M]
// [--tolerance T] --format FORMATS` as the library call the command makes.
BakeRequest TableBake(const fs::path &dir, const std::vector<std::string> &tables, int size,
                      int etaSize, double tolerance, const std::vector<std::string> &formats) {
  BakeRequest request;
  request.outputDirectory = dir.string();
  request.tables = tables;
  request.size = size;
  request.etaSize = etaSize;
  request.sampling.tolerance = tolerance;
  request.formats = formats;
  return request;
}

// `lutbake check DIR [--points N]` as a library call.
CheckOutcome CheckDirectory(const fs::path &dir, int points = 256) {
  CheckRequest request;
  request.dir = dir.string();
  request.points = points;
  return Check(request);
}

// `lutbake plan --json` of one scene or manifest, as a library call.
nlohmann::json PlanOf(const std::string &scene, const std::string &manifest) {
  PlanRequest request;
  if (!scene.empty()) request.scenes = {scene};
  if (!manifest.empty()) request.manifests = {manifest};
  return nlohmann::json::parse(PlanJson(Plan(request)));
}

BakeSettings Model(NdfKind ndf, SmithForm smith) {
  BakeSettings s;
  s.ndf = ndf;
  s.smith = smith;
  return s;
}

TEST(GlassTables, AreDefinedWithAListedEtaAxis) {
  const TableDefinition &glass = TableNamed("glass_E");
  Axis x, y, z;
  DefaultAxes(glass, BakeSettings{}, &x, &y, &z);
  EXPECT_EQ(x.name, "mu");
  EXPECT_EQ(y.name, "perceptualRoughness");
  ASSERT_EQ(z.name, "eta");
  ASSERT_TRUE(z.listed());
  // Uniform in s = (eta - 1) / (eta + 1) over [-1/2, 1/2], with eta = 1 and
  // water, glass and diamond on both sides as nodes of their own.
  EXPECT_DOUBLE_EQ(z.nodes.front(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(z.nodes.back(), 3.0);
  for (double eta : {1.0, 1.33, 1.5, 2.42, 1 / 1.33, 1 / 1.5, 1 / 2.42})
    EXPECT_NE(std::find(z.nodes.begin(), z.nodes.end(), eta), z.nodes.end()) << eta;
  EXPECT_EQ(TableNamed("glass_Eavg").Relations().averageOf, "glass_E");
  EXPECT_EQ(TableNamed("spec_Eavg").Relations().averageOf, "spec_E");
}

// r = 0: a smooth interface scatters everything (glass_E = F + T = 1) and
// reflects F(mu) (spec_E), the exact dielectric Fresnel, on both sides.
// eta = 1: nothing reflects (spec_E = 0) and every facet passes o straight
// through, so glass_E = G2(o, -o) / G1(o): (1 + Lambda) / (1 + 2 Lambda)
// with the correlated G2, G1(mu) with the separable one.
TEST(GlassTables, ExactLimits) {
  const TableDefinition &glass = TableNamed("glass_E"), &spec = TableNamed("spec_E");
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable}) {
      const BakeSettings s = Model(ndf, smith);
      for (double eta : {1 / 2.42, 1 / 1.33, 1.33, 2.42})
        for (double mu : {0.05, 0.5, 1.0}) {
          EXPECT_NEAR(glass.Evaluate3D(s, mu, 0.0, eta).value[0], 1.0, 1e-15);
          EXPECT_NEAR(spec.Evaluate3D(s, mu, 0.0, eta).value[0], ExactFresnel(eta, 0.0, mu), 1e-15);
        }
      for (double r : {0.3, 0.7, 1.0})
        for (double mu : {0.1, 0.5, 0.9}) {
          const Ndf n{ndf, r * r};
          const double lambda = n.MuLambda(mu) / mu;
          const double expected = smith == SmithForm::kCorrelated
                                      ? (1.0 + lambda) / (1.0 + 2.0 * lambda)
                                      : 1.0 / (1.0 + lambda);
          const PointValue g = glass.Evaluate3D(s, mu, r, 1.0);
          EXPECT_NEAR(g.value[0], expected, g.error[0] + 1e-12) << r << " " << mu;
          EXPECT_NEAR(spec.Evaluate3D(s, mu, r, 1.0).value[0], 0.0, 1e-12);
        }
    }
}

// Reciprocity between the sides: the transmitted energy averages obey
//   T_avg(eta) = eta^2 T_avg(1/eta),  T_avg = glass_Eavg - spec_Eavg,
// as 1 - F_avg(eta) = eta^2 (1 - F_avg(1/eta)) does for a smooth interface.
TEST(GlassTables, TransmittedAveragesAreReciprocal) {
  const TableDefinition &glass = TableNamed("glass_Eavg"), &spec = TableNamed("spec_Eavg");
  // At 1e-6: the averages on the inside (eta < 1) cost seconds at 1e-8.
  BakeSettings s;
  s.tolerance = 1e-6;
  for (double eta : {1.5, 2.42})
    for (double r : {0.0, 0.6}) {
      const PointValue g = glass.Evaluate(s, r, eta), sp = spec.Evaluate(s, r, eta);
      const PointValue gi = glass.Evaluate(s, r, 1 / eta), spi = spec.Evaluate(s, r, 1 / eta);
      const double outside = g.value[0] - sp.value[0], inside = gi.value[0] - spi.value[0];
      const double allowed =
          g.error[0] + sp.error[0] + eta * eta * (gi.error[0] + spi.error[0]) + 1e-12;
      EXPECT_NEAR(outside, eta * eta * inside, allowed) << eta << " r " << r;
    }
  // The smooth case against the Fresnel average itself.
  const FresnelAverageResult favg = ExactFresnelAverage(1.5, 0.0);
  EXPECT_NEAR(spec.Evaluate(s, 0.0, 1.5).value[0], favg.value, favg.error + 1e-12);
  EXPECT_NEAR(glass.Evaluate(s, 0.0, 1 / 1.5).value[0], 1.0, 1e-12);
}

// Against the independent values of tests/data/glass (numpy, another rule
// over the half vector with its own splits, each to its `err`): every value
// of both tables, both NDFs and Smith forms, both sides of the interface,
// within the stated bound plus the reference's error.
TEST(GlassTables, MatchIndependentReferenceWithinTheirBounds) {
  const std::vector<test::CsvRow> rows = test::ReadCsv(LUTBAKE_TEST_DATA "/glass/glass_E.csv");
  ASSERT_EQ(rows.size(), 736u);
  std::vector<double> ratio(rows.size(), 0.0);
  tbb::parallel_for(size_t{0}, rows.size(), [&](size_t k) {
    const test::CsvRow &row = rows[k];
    BakeSettings s;
    s.ndf = row.Text("ndf") == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
    s.smith = row.Text("smith") == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
    const PointValue v =
        TableNamed(row.Text("table"))
            .Evaluate3D(s, row.Number("mu"), row.Number("roughness"), row.Number("eta"));
    const double real = std::abs(v.value[0] - row.Number("value"));
    ratio[k] = real / (v.error[0] + row.Number("err"));
  });
  double worst = 0.0;
  size_t worstAt = 0;
  for (size_t k = 0; k < ratio.size(); ++k)
    if (ratio[k] > worst) worst = ratio[k], worstAt = k;
  std::printf("worst real error / (bound + reference error): %.3g at row %zu\n", worst,
              worstAt + 3);
  EXPECT_LE(worst, 1.0) << "row " << worstAt + 3 << " of glass_E.csv";
}

TEST(GlassTables, EvalTakesThreeCoordinates) {
  EvalRequest request;
  request.table = "glass_E";
  request.coordinates = {
      {"mu", {0.5, 1}}, {"roughness", {0, 0.5}}, {"eta", {1.5, 0.6666666666666666}}};
  const EvalResult eval = Evaluate(request);
  ASSERT_EQ(eval.points.size(), 8u);
  std::vector<nlohmann::json> lines;
  for (size_t k = 0; k < eval.points.size(); ++k)
    lines.push_back(nlohmann::json::parse(eval.JsonLine(k)));
  // z outermost, then y, x inner.
  EXPECT_EQ(double(lines[0]["eta"]), 1.5);
  EXPECT_EQ(double(lines[0]["roughness"]), 0.0);
  EXPECT_EQ(double(lines[1]["mu"]), 1.0);
  EXPECT_EQ(double(lines[4]["eta"]), 0.6666666666666666);
  EXPECT_EQ(double(lines[0]["value"]), 1.0);  // smooth: exactly 1
  for (const auto &p : lines) {
    EXPECT_GE(double(p["value"]), 0.0);
    EXPECT_LE(double(p["value"]), 1.0 + double(p["error"]));
  }
  // No eta; eta out of range; eta given to a table without it; an estimator
  // the table does not offer: usage errors (exit 2 on the command line).
  const std::map<std::string, std::vector<double>> point{{"mu", {0.5}}, {"roughness", {0.5}}};
  std::vector<EvalRequest> bad(4, request);
  bad[0].coordinates = point;
  bad[1].coordinates = point;
  bad[1].coordinates["eta"] = {130};
  bad[2].table = "glass_Eavg";
  bad[2].coordinates = point;
  bad[2].coordinates["eta"] = {1.5};
  bad[3].coordinates = point;
  bad[3].coordinates["eta"] = {1.5};
  bad[3].sampling.estimator = Estimator::kCosine;
  for (size_t k = 0; k < bad.size(); ++k) EXPECT_THROW(Evaluate(bad[k]), UsageError) << k;
}

// A small bake of the two 3D tables in every format, then `lutbake check`:
// the 3D files read back and agree, every texel within its bound of the
// adaptive reference, trilinear lookups at random points.
TEST(GlassTables, SmallBakePassesCheck) {
  const fs::path dir = test::Scratch("glass_bake");
  BakeRequest request = TableBake(dir, {"glass_E", "spec_E"}, 4, 2, 1e-6, {"exr", "bin", "header"});
  request.errorMaps = true;
  Bake(request);
  const Table exr = ReadExrTable((dir / "glass_E.exr").string());
  ASSERT_TRUE(exr.is3D());
  EXPECT_EQ(exr.z.count, 2);  // --eta-size 2: eta = 1/3 and 3 (s = -+1/2), no material nodes
  const Table bin = ReadBinaryTable((dir / "glass_E.bin").string());
  ASSERT_EQ(bin.values.size(), exr.values.size());
  const CheckOutcome check = CheckDirectory(dir);
  EXPECT_TRUE(check.passed) << check.text << check.failureText;
  EXPECT_NE(check.text.find("glass_E texels"), std::string::npos) << check.text;
  // Both tables' random points, through the trilinear lookup.
  size_t trilinear = 0;
  for (size_t at = check.text.find("trilinear lookup"); at != std::string::npos;
       at = check.text.find("trilinear lookup", at + 1))
    ++trilinear;
  EXPECT_EQ(trilinear, 2u) << check.text;
  fs::remove_all(dir);
}

// Rewrites value `index` of a float32 .bin file (data offset at byte 12).
void PatchBin(const fs::path &path, size_t index, float value) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  uint32_t dataOffset = 0;
  f.seekg(12);
  f.read(reinterpret_cast<char *>(&dataOffset), 4);
  f.seekp(dataOffset + 4 * static_cast<std::streamoff>(index));
  f.write(reinterpret_cast<const char *>(&value), 4);
}

const CheckResult *Find(const CheckReport &r, const std::string &subject,
                        const std::string &check) {
  for (const CheckResult &c : r.results)
    if (c.subject == subject && c.check == check) return &c;
  return nullptr;
}

// `check` holds the eta = 1 slice to its closed form, the integrator to the
// smooth limit, and the averages of both sides to reciprocity; a texel moved
// by 20x the stated bound on the slice, or on one side of a reciprocal pair,
// fails the claim by name.
TEST(GlassTables, CheckHoldsSliceLimitAndReciprocity) {
  const fs::path dir = test::Scratch("glass_claims");
  // eta-size 3: eta = 1/3, 1, 3.
  Bake(TableBake(dir, {"glass_E", "spec_E"}, 4, 3, 1e-6, {"bin"}));
  // The averages (slower: --size 2) in a directory of their own: a bake into
  // a directory replaces the set there.
  const fs::path averages = test::Scratch("glass_claims_averages");
  Bake(TableBake(averages, {"glass_Eavg", "spec_Eavg"}, 2, 3, 1e-6, {"bin"}));
  CheckOptions quick;
  quick.randomPoints = 2;
  const auto statusOf = [](const CheckReport &r, const std::string &subject,
                           const std::string &check) {
    const CheckResult *c = Find(r, subject, check);
    EXPECT_NE(c, nullptr) << subject << " " << check;
    return c ? c->status : CheckStatus::kSkipped;
  };
  {
    const CheckReport r = CheckBakedSet(dir.string(), quick);
    const CheckReport a = CheckBakedSet(averages.string(), quick);
    for (const CheckReport *report : {&r, &a})
      for (const CheckResult &c : report->results)
        EXPECT_NE(c.status, CheckStatus::kFail) << c.subject << " " << c.check << ": " << c.detail;
    for (const char *t : {"glass_E", "spec_E"})
      EXPECT_EQ(statusOf(r, t, "slice"), CheckStatus::kPass) << t;
    for (const char *t : {"glass_Eavg", "spec_Eavg"})
      EXPECT_EQ(statusOf(a, t, "slice"), CheckStatus::kPass) << t;
    EXPECT_EQ(statusOf(r, "glass_E", "limit"), CheckStatus::kPass);
    EXPECT_EQ(statusOf(r, "spec_E", "limit"), CheckStatus::kPass);
    EXPECT_EQ(statusOf(a, "glass_Eavg-spec_Eavg", "reciprocity"), CheckStatus::kPass);
  }
  // glass_E at (mu 3/8, r 5/8, eta = 1), and glass_Eavg at (r 3/4, eta 3).
  const Table glass = ReadBinaryTable((dir / "glass_E.bin").string());
  ASSERT_EQ(glass.z.TexelCenter(1), 1.0);
  const size_t onSlice = glass.index(1, 2, 1, 0);
  PatchBin(dir / "glass_E.bin", onSlice,
           static_cast<float>(glass.values[onSlice] - 20.0 * glass.MaxError()));
  const Table average = ReadBinaryTable((averages / "glass_Eavg.bin").string());
  ASSERT_EQ(average.y.TexelCenter(2), 3.0);
  const size_t side = average.index(1, 2, 0, 0);
  PatchBin(averages / "glass_Eavg.bin", side,
           static_cast<float>(average.values[side] - 20.0 * average.MaxError()));
  const CheckReport r = CheckBakedSet(dir.string(), quick);
  const CheckReport a = CheckBakedSet(averages.string(), quick);
  EXPECT_FALSE(r.passed());
  EXPECT_FALSE(a.passed());
  EXPECT_EQ(statusOf(r, "glass_E", "slice"), CheckStatus::kFail);
  EXPECT_EQ(statusOf(a, "glass_Eavg-spec_Eavg", "reciprocity"), CheckStatus::kFail);
  // The untouched tables' claims still hold.
  EXPECT_EQ(statusOf(r, "spec_E", "slice"), CheckStatus::kPass);
  EXPECT_EQ(statusOf(r, "glass_E", "limit"), CheckStatus::kPass);
  fs::remove_all(averages);
  fs::remove_all(dir);
}

// check's reference for the dielectric tables is their own panel rule at
// 1/16 of the stated errorMax (dielectric_table.h): a texel off the eta = 1
// slice moved by 3x its bound (the largest one's: errorMax, so the move
// exceeds every allowance) fails the texel check, in a 3D table and in an
// average, while the untouched tables pass. The 3D tables' sample held to
// the adaptive rule (here all 32 texels) catches it too.
TEST(GlassTables, CheckFailsATexelMovedByThreeBounds) {
  const fs::path dir = test::Scratch("glass_moved");
  Bake(TableBake(dir, {"glass_E", "spec_E"}, 4, 2, 1e-6, {"bin"}));
  const fs::path averages = test::Scratch("glass_moved_averages");
  Bake(TableBake(averages, {"glass_Eavg", "spec_Eavg"}, 2, 2, 1e-6, {"bin"}));
  CheckOptions quick;
  quick.randomPoints = 2;
  const auto texels = [](const CheckReport &r, const std::string &subject,
                         const std::string &check = "texels") {
    const CheckResult *c = Find(r, subject, check);
    EXPECT_NE(c, nullptr) << subject << " " << check;
    return c ? c->status : CheckStatus::kSkipped;
  };
  const CheckReport good = CheckBakedSet(dir.string(), quick);
  for (const char *t : {"glass_E", "spec_E"}) {
    EXPECT_EQ(texels(good, t), CheckStatus::kPass) << t;
    EXPECT_EQ(texels(good, t, "independent"), CheckStatus::kPass) << t;
  }
  for (const char *t : {"glass_Eavg", "spec_Eavg"})
    EXPECT_EQ(texels(CheckBakedSet(averages.string(), quick), t), CheckStatus::kPass) << t;
  // The texel with the largest bound, moved up by 3x it.
  const auto moveWorst = [](const fs::path &path) {
    const Table table = ReadBinaryTable(path.string());
    ASSERT_EQ(table.errors.size(), table.values.size());
    const size_t at = static_cast<size_t>(
        std::max_element(table.errors.begin(), table.errors.end()) - table.errors.begin());
    ASSERT_GT(table.errors[at], 0.0);
    PatchBin(path, at, static_cast<float>(table.values[at] + 3.0 * table.errors[at]));
  };
  moveWorst(dir / "glass_E.bin");
  moveWorst(averages / "glass_Eavg.bin");
  const CheckReport r = CheckBakedSet(dir.string(), quick);
  const CheckReport a = CheckBakedSet(averages.string(), quick);
  EXPECT_FALSE(r.passed());
  EXPECT_FALSE(a.passed());
  EXPECT_EQ(texels(r, "glass_E"), CheckStatus::kFail);
  EXPECT_EQ(texels(a, "glass_Eavg"), CheckStatus::kFail);
  EXPECT_EQ(texels(r, "spec_E"), CheckStatus::kPass);
  EXPECT_EQ(texels(a, "spec_Eavg"), CheckStatus::kPass);
  EXPECT_EQ(texels(r, "glass_E", "independent"), CheckStatus::kFail);
  EXPECT_EQ(texels(r, "spec_E", "independent"), CheckStatus::kPass);
  fs::remove_all(averages);
  fs::remove_all(dir);
}

// A glTF scene with KHR_materials_transmission: planned over exactly the
// IORs it uses, both sides (1.5 by default, 1.33 from KHR_materials_ior),
// and the base roughness; baked (glass_E, chosen among the planned tables)
// and checked; a transmissionFactor of 0 plans nothing and says so.
TEST(GlassTables, SceneWithTransmissionIsPlannedAndBaked) {
  const std::string scene = LUTBAKE_TEST_DATA "/plans/glass.gltf";
  const nlohmann::json j = PlanOf(scene, "");
  const nlohmann::json *glass = nullptr;
  for (const auto &t : j["tables"])
    if (t["name"] == "glass_E") glass = &t;
  ASSERT_NE(glass, nullptr) << j.dump(2);
  EXPECT_EQ((*glass)["eta"], (std::vector<double>{1 / 1.5, 1 / 1.33, 1.33, 1.5}));
  EXPECT_EQ((*glass)["roughness"]["values"], (std::vector<double>{0.25, 0.5}));
  EXPECT_EQ((*glass)["materials"], (std::vector<std::string>{"window", "frosted water"}));
  EXPECT_NE(j.dump().find("transmissionFactor 0: no transmission lobe"), std::string::npos);
  const fs::path dir = test::Scratch("glass_scene");
  BakeRequest request = TableBake(dir, {"glass_E"}, 8, 0, 0, {"exr", "bin"});
  request.scenes = {scene};
  Bake(request);
  const Table t = ReadBinaryTable((dir / "glass_E.bin").string());
  ASSERT_TRUE(t.is3D());
  EXPECT_EQ(t.z.nodes, (std::vector<double>{1 / 1.5, 1 / 1.33, 1.33, 1.5}));
  EXPECT_EQ(t.y.nodes, (std::vector<double>{0.25, 0.5}));
  const CheckOutcome check = CheckDirectory(dir);
  EXPECT_TRUE(check.passed) << check.text << check.failureText;
  fs::remove_all(dir);
}

// A manifest with dielectric coats (1.5; 1.33 and 1.5): spec_E and
// spec_Eavg planned over exactly those IORs, both sides, and the coat
// roughness; baked (chosen among the planned tables, --size 4: spec_Eavg
// at eta < 1 costs about a second a texel) and checked. check's random
// points are left out for the same cost (--points 0): every texel is still
// judged against the quadrature, and spec_Eavg against spec_E's rows.
TEST(GlassTables, ManifestWithCoatsIsPlannedAndBaked) {
  const std::string manifest = LUTBAKE_TEST_DATA "/plans/coat.json";
  const std::vector<double> etas{1 / 1.5, 1 / 1.33, 1.33, 1.5};
  const nlohmann::json j = PlanOf("", manifest);
  std::vector<std::string> names;
  for (const auto &t : j["tables"]) names.push_back(t["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"E", "Eavg", "Favg_dielectric", "Favg_conductor",
                                             "dfg", "spec_E", "spec_Eavg"}));
  EXPECT_EQ(j["tables"][5]["eta"], etas);
  EXPECT_EQ(j["tables"][6]["eta"], etas);
  const fs::path dir = test::Scratch("coat_manifest");
  BakeRequest request = TableBake(dir, {"spec_E", "spec_Eavg"}, 4, 0, 0, {"exr", "bin"});
  request.manifests = {manifest};
  Bake(request);
  EXPECT_EQ(test::FileNames(dir),
            (std::vector<std::string>{"lutbake-set.json", "spec_E.bin", "spec_E.exr",
                                      "spec_Eavg.bin", "spec_Eavg.exr"}));
  const Table e = ReadBinaryTable((dir / "spec_E.bin").string());
  ASSERT_TRUE(e.is3D());
  EXPECT_EQ(e.x.count, 4);
  EXPECT_EQ(e.y.nodes, std::vector<double>{0.1});
  EXPECT_EQ(e.z.nodes, etas);
  EXPECT_EQ(*e.FindMetadata("planMaterials"), "car paint, lacquered wood");
  const Table average = ReadBinaryTable((dir / "spec_Eavg.bin").string());
  EXPECT_EQ(average.x.nodes, std::vector<double>{0.1});
  EXPECT_EQ(average.y.nodes, etas);
  const CheckOutcome check = CheckDirectory(dir, 0);
  EXPECT_TRUE(check.passed) << check.text << check.failureText;
  for (const char *subject : {"spec_E  texels", "spec_Eavg texels", "spec_E+spec_Eavg average"})
    EXPECT_NE(check.text.find(subject), std::string::npos) << subject << "\n" << check.text;
  fs::remove_all(dir);
}

// Bit-identical for 1 and 2 threads on both sides of the interface.
TEST(GlassTables, BitIdenticalForOneAndTwoThreads) {
  const BakeSettings s;
  const Axis eta = ListedAxis("eta", {1 / 1.5, 1.5});
  for (const char *name : {"glass_E", "spec_E", "glass_Eavg"}) {
    const TableDefinition &def = TableNamed(name);
    const bool threeD = def.PlannedRoughnessAxis() == 1;
    const Axis x = threeD ? MuAxis(4) : RoughnessAxis(2);
    const Axis y = threeD ? RoughnessAxis(4) : ListedAxis("eta", {1.5});
    const Axis z = threeD ? eta : LinearAxis("", 0.0, 1.0, 1);
    Table one, two;
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
      one = BakeTableOn(def, s, x, y, z);
    }
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
      two = BakeTableOn(def, s, x, y, z);
    }
    ASSERT_EQ(one.values.size(), two.values.size());
    EXPECT_EQ(0,
              std::memcmp(one.values.data(), two.values.data(), one.values.size() * sizeof(double)))
        << name;
    EXPECT_EQ(0,
              std::memcmp(one.errors.data(), two.errors.data(), one.errors.size() * sizeof(double)))
        << name;
  }
}

TEST(GlassTables, HeaderHelpersCompileAndLookUp) {
  const fs::path dir = test::Scratch("glass_header");
  Bake(TableBake(dir, {"glass_E", "spec_E"}, 4, 3, 0, {"header"}));
  // The averages (slower: --size 2) in a directory of their own, since a bake
  // replaces the set in its directory; the program includes both.
  const fs::path averageDir = test::Scratch("glass_header_averages");
  Bake(TableBake(averageDir, {"glass_Eavg", "spec_Eavg"}, 2, 3, 1e-6, {"header"}));
  for (const char *header : {"glass_Eavg.h", "spec_Eavg.h"})
    fs::copy_file(averageDir / header, dir / header);
  fs::remove_all(averageDir);
  std::ofstream(dir / "main.cpp")
      << "#include <cmath>\n#include <cstdio>\n#include \"glass_E.h\"\n#include \"spec_E.h\"\n"
         "#include \"glass_Eavg.h\"\n#include \"spec_Eavg.h\"\n"
         "int main() {\n  int fail = 0;\n  using namespace lutbake_luts;\n"
         "  // At texel centres the lookup is the texel; the helpers are 1/E and 1 - E.\n"
         "  for (std::size_t z = 0; z < glass_E_table::kDepth; ++z) {\n"
         "    const float eta = float(glass_E_table::kZNodes[z]);\n"
         "    const float e = lookup_glass_E(0.375f, 0.625f, eta);\n"
         "    if (e != glass_E_table::kValues[(z * 4 + 2) * 4 + 1]) ++fail;\n"
         "    if (std::fabs(energy_compensation_glass_E(0.375f, 0.625f, eta) * e - 1.0f) > "
         "1e-6f) ++fail;\n"
         "    const float s = lookup_spec_E(0.375f, 0.625f, eta);\n"
         "    if (base_weight_spec_E(0.375f, 0.625f, eta) != 1.0f - s) ++fail;\n"
         "    if (!(s >= 0.0f && s <= e)) ++fail;\n"
         "  }\n"
         "  // The averages' helpers: 1 - spec_Eavg, and the Kulla-Conty lobe\n"
         "  // (1 - E_o) (1 - E_i) / (pi (1 - glass_Eavg)), 0 at eta = 1, r = 1/4 if nothing is "
         "lost.\n"
         "  for (float eta : {1.0f / 3.0f, 1.0f, 3.0f}) {\n"
         "    const float s = lookup_spec_Eavg(0.75f, eta);\n"
         "    if (diffuse_transmittance_spec_Eavg(0.75f, eta) != 1.0f - s) ++fail;\n"
         "    const float lost = 1.0f - lookup_glass_Eavg(0.75f, eta);\n"
         "    if (!(lost > 0.0f)) ++fail;\n"
         "    const float f = ms_lobe_glass_Eavg(0.9f, 0.8f, 0.75f, eta);\n"
         "    if (std::fabs(f * 3.14159265f * lost - 0.1f * 0.2f) > 1e-6f) ++fail;\n"
         "  }\n  std::printf(\"%d failures\\n\", fail);\n  return fail == 0 ? 0 : 1;\n}\n";
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(dir, "c++17");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
