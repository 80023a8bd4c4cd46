// The sheen tables (sheen_E, sheen_Eavg) through the table definitions and
// the library: evaluation (as `lutbake eval` does it) against the
// independent reference values of tests/data/sheen (another program, another
// parameterisation) for both visibilities and both roughness mappings,
// within the stated bound; the limits; a default bake checked by
// CheckBakedSet; a glTF scene with KHR_materials_sheen planned and baked;
// the header's albedo-scaling helper compiled and run. What eval refuses is
// tests/cli/eval_tables_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/lutbake.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const std::string kData = LUTBAKE_TEST_DATA;

BakeSettings Sheen(SheenVisibility v, SheenAlpha a = SheenAlpha::kLinear) {
  BakeSettings s;
  s.sheenVisibility = v;
  s.sheenAlpha = a;
  return s;
}

// The settings `lutbake eval --sheen-visibility V --sheen-alpha A` evaluates
// with: no sampling option, so the quadrature (ApplySampling's default).
BakeSettings EvalSettings(const std::string &visibility, SheenAlpha alpha = SheenAlpha::kLinear) {
  SheenVisibility v = SheenVisibility::kCharlie;
  EXPECT_TRUE(ParseSheenVisibility(visibility, &v)) << visibility;
  BakeSettings s = Sheen(v, alpha);
  ApplySampling(SamplingRequest{}, &s);
  return s;
}

TEST(SheenTables, AreDefinedAndRegistered) {
  const TableDefinition &e = TableNamed("sheen_E"), &avg = TableNamed("sheen_Eavg");
  // Its claim with the set: the albedo-scaling furnace, judged on a grid of
  // reference values; sheen_Eavg averages sheen_E's rows.
  ASSERT_EQ(e.Claims().size(), 1u);
  EXPECT_TRUE(e.Claims()[0]->NeedsGrid());
  EXPECT_EQ(avg.Relations().averageOf, "sheen_E");
  EXPECT_EQ(avg.Claims().size(), 1u);
  EXPECT_EQ(e.Role(), PlanRole::kSheenAlbedoScaling);
  Axis x, y;
  DefaultAxes(e, BakeSettings{}, &x, &y);
  EXPECT_EQ(x.name, "mu");
  EXPECT_EQ(y.name, "sheenRoughness");
  EXPECT_EQ(y.count, 32);
  EXPECT_EQ(e.AlphaMetadata(Sheen(SheenVisibility::kCharlie)), "alpha = sheenRoughness");
  EXPECT_EQ(e.AlphaMetadata(Sheen(SheenVisibility::kCharlie, SheenAlpha::kSquared)),
            "alpha = sheenRoughness^2");
}

// --sheen-alpha squared at r is linear at r^2: the same alpha, bit for bit.
TEST(SheenTables, SquaredMappingIsLinearAtTheSquare) {
  const TableDefinition &e = TableNamed("sheen_E");
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin})
    for (double r : {0.03, 0.3, 0.9}) {
      const PointValue squared = e.Evaluate(Sheen(v, SheenAlpha::kSquared), 0.4, r);
      const PointValue linear = e.Evaluate(Sheen(v), 0.4, r * r);
      EXPECT_EQ(squared.value[0], linear.value[0]) << r;
    }
}

// The limits the definitions document: r = 0 is exactly 0 for mu > 0 (the
// lobe sits on the horizon of h), and so is E_avg; Charlie's E is infinite
// at mu = 0 for every r, Ashikhmin's only at r = 0; small r stays finite.
TEST(SheenTables, Limits) {
  const TableDefinition &e = TableNamed("sheen_E"), &avg = TableNamed("sheen_Eavg");
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin}) {
    for (double mu : {1e-9, 0.1, 1.0}) {
      const PointValue zero = e.Evaluate(Sheen(v), mu, 0.0);
      EXPECT_EQ(zero.value[0], 0.0);
      EXPECT_EQ(zero.error[0], 0.0);
      EXPECT_TRUE(zero.exact);
    }
    EXPECT_EQ(avg.Evaluate(Sheen(v), 0.0, 0.0).value[0], 0.0);
    // Tiny r: E(mu = 0.5) is exponentially small, within its bound of 0.
    const PointValue tiny = e.Evaluate(Sheen(v), 0.5, 1e-6);
    EXPECT_LE(tiny.value[0], tiny.error[0] + 1e-300);
    for (double r : {1e-12, 0.01, 0.03})
      for (double mu : {1e-6, 0.01, 0.5}) {
        const PointValue p = e.Evaluate(Sheen(v), mu, r);
        EXPECT_TRUE(std::isfinite(p.value[0]) && std::isfinite(p.error[0])) << mu << " " << r;
        EXPECT_GE(p.value[0], 0.0);
      }
  }
  EXPECT_THROW(e.Evaluate(Sheen(SheenVisibility::kCharlie), 0.0, 0.5), std::domain_error);
  EXPECT_THROW(e.Evaluate(Sheen(SheenVisibility::kAshikhmin), 0.0, 0.0), std::domain_error);
  EXPECT_TRUE(std::isfinite(e.Evaluate(Sheen(SheenVisibility::kAshikhmin), 0.0, 0.5).value[0]));
  EXPECT_THROW(e.Evaluate(Sheen(SheenVisibility::kCharlie), 0.5, 1.5), std::domain_error);
}

// Every point of the independent reference (tests/data/sheen, alpha given)
// evaluated as `lutbake eval` does with each mapping: alpha = r (r = alpha) and
// alpha = r^2 (r = sqrt(alpha), where the square returns alpha exactly);
// |value - reference| within the stated bound plus the reference's error.
TEST(SheenTables, EvalMatchesTheIndependentReference) {
  struct Group {
    std::vector<double> mu, ref, err;
  };
  std::map<std::pair<std::string, double>, Group> groups;  // (visibility, alpha)
  for (const test::CsvRow &row : test::ReadCsv(kData + "/sheen/sheen_E.csv")) {
    Group &g = groups[{row.Text("visibility"), row.Number("alpha")}];
    g.mu.push_back(row.Number("mu"));
    g.ref.push_back(row.Number("E"));
    g.err.push_back(row.Number("error"));
  }
  ASSERT_GE(groups.size(), 20u);
  size_t compared = 0;
  double worstRatio = 0.0;
  for (const auto &[key, g] : groups) {
    const auto &[visibility, alpha] = key;
    for (const char *mapping : {"linear", "squared"}) {
      const bool squared = std::string(mapping) == "squared";
      const double r = squared ? std::sqrt(alpha) : alpha;
      if (squared && r * r != alpha) continue;  // not exactly representable
      const BakeSettings settings =
          EvalSettings(visibility, squared ? SheenAlpha::kSquared : SheenAlpha::kLinear);
      for (size_t i = 0; i < g.mu.size(); ++i) {
        const PointValue p = TableNamed("sheen_E").Evaluate(settings, g.mu[i], r);
        const double v = p.value[0], bound = p.error[0];
        EXPECT_LE(std::abs(v - g.ref[i]), bound + g.err[i])
            << visibility << " alpha " << alpha << " mu " << g.mu[i] << " " << mapping;
        if (bound > 0) worstRatio = std::max(worstRatio, std::abs(v - g.ref[i]) / bound);
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 300u);
  std::printf("sheen_E eval: %zu points, worst |error| / bound %.3g\n", compared, worstRatio);
}

TEST(SheenTables, EvalOfTheAverageMatchesTheIndependentReference) {
  size_t compared = 0;
  for (const test::CsvRow &row : test::ReadCsv(kData + "/sheen/sheen_Eavg.csv")) {
    const std::string visibility = row.Text("visibility");
    const double alpha = row.Number("alpha"), ref = row.Number("Eavg"), err = row.Number("error");
    // eval --table sheen_Eavg --roughness alpha: sheen_Eavg's one coordinate.
    const PointValue p = TableNamed("sheen_Eavg").Evaluate(EvalSettings(visibility), alpha, 0.0);
    EXPECT_LE(std::abs(p.value[0] - ref), p.error[0] + err) << visibility << " alpha " << alpha;
    ++compared;
  }
  EXPECT_GE(compared, 10u);
}

// A sampled sheen texel reproduces through eval at its centre, and the
// sampled values sit within their own 99% bounds of the quadrature.
TEST(SheenTables, SampledBakeIsWithinItsBounds) {
  BakeSettings s = Sheen(SheenVisibility::kCharlie);
  s.size = 6;
  s.samples = 4096;
  s.estimator = Estimator::kNdf;
  const TableDefinition &e = TableNamed("sheen_E");
  const Table t = BakeTable(e, s);
  BakeSettings q = s;
  q.estimator = Estimator::kQuadrature;
  int outside = 0;
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const PointValue truth = e.Evaluate(q, t.x.TexelCenter(x), t.y.TexelCenter(y));
      const size_t i = t.index(x, y, 0);
      outside += std::abs(t.values[i] - truth.value[0]) > t.errors[i] + truth.error[0];
      EXPECT_EQ(e.Evaluate(s, t.x.TexelCenter(x), t.y.TexelCenter(y)).value[0], t.values[i]);
    }
  // 36 texels, each outside its 99% bound with probability <= 1%: more than
  // 3 outside has probability below 0.6%.
  EXPECT_LE(outside, 3);
}

// A default bake of both sheen tables, every format, checked by
// CheckBakedSet (range, texels against the half-vector reference, points, sheen_Eavg
// against sheen_E's rows, the albedo-scaling furnace).
TEST(SheenTables, DefaultBakePassesCheck) {
  const fs::path out = test::Scratch("sheen_default");
  BakeRequest request = test::BakeRequestFor(out);  // --tables sheen_E,sheen_Eavg --error-map
  request.tables = {"sheen_E", "sheen_Eavg"};
  request.errorMaps = true;
  Bake(request);
  for (const char *file : {"sheen_E.exr", "sheen_E.bin", "sheen_E.h", "sheen_E.err.exr",
                           "sheen_Eavg.exr", "sheen_Eavg.bin", "sheen_Eavg.h"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const Table t = ReadBinaryTable((out / "sheen_E.bin").string());
  EXPECT_EQ(*t.FindMetadata("visibility"), "charlie");
  EXPECT_EQ(*t.FindMetadata("alpha"), "alpha = sheenRoughness");
  // Float32-exact as the default claims: every stored bound is the
  // integration bound, at most 1e-8 max(1, |value|), plus the value's float32
  // rounding (half an ulp: 6e-8 for values in [1, 2)), the bound itself
  // rounded up to float32.
  for (size_t i = 0; i < t.values.size(); ++i) {
    const double v = t.values[i];
    const double halfUlp = v > 0.0 ? std::ldexp(1.0, std::ilogb(v) - 24) : 0.0;
    EXPECT_LE(t.errors[i], (1e-8 * std::max(1.0, std::abs(v)) + halfUlp) * (1.0 + 1e-6)) << i;
  }
  const CheckReport check = CheckBakedSet(out.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  std::map<std::string, std::string> status = test::CheckStatuses(check);
  for (const char *expected :
       {"sheen_E range", "sheen_E texels", "sheen_E points", "sheen_E furnace", "sheen_Eavg range",
        "sheen_Eavg texels", "sheen_E+sheen_Eavg average"})
    EXPECT_EQ(status[expected], "pass") << expected;
  fs::remove_all(out);
}

// A glTF scene with KHR_materials_sheen: sheen_E over the sheen roughness
// it uses ([0, 0.6]: a roughness texture under factor 0.6, and 0.25), the
// black sheen left out; baked with the Ashikhmin visibility and checked.
TEST(SheenTables, SceneWithSheenIsPlannedAndBaked) {
  const fs::path out = test::Scratch("sheen_scene");
  const std::string scene = kData + "/plans/sheen.gltf";
  PlanRequest planRequest;  // plan --scene SCENE --json
  planRequest.scenes = {scene};
  const std::string plan = PlanJson(Plan(planRequest));
  const nlohmann::json j = nlohmann::json::parse(plan);
  const nlohmann::json *sheen = nullptr;
  for (const auto &t : j["tables"])
    if (t["name"] == "sheen_E") sheen = &t;
  ASSERT_NE(sheen, nullptr) << plan;
  EXPECT_EQ(double((*sheen)["sheenRoughness"]["min"]), 0.0);
  EXPECT_EQ(double((*sheen)["sheenRoughness"]["max"]), 0.6);
  EXPECT_EQ((*sheen)["materials"], (nlohmann::json{"velvet textured", "satin"}));
  BakeRequest request = test::BakeRequestFor(out);
  request.scenes = {scene};
  request.tables = {"sheen_E"};
  request.sheenVisibility = SheenVisibility::kAshikhmin;
  Bake(request);
  EXPECT_EQ(test::FileNames(out), (std::vector<std::string>{"lutbake-set.json", "sheen_E.bin",
                                                            "sheen_E.exr", "sheen_E.h"}));
  const Table t = ReadExrTable((out / "sheen_E.exr").string());
  EXPECT_EQ(t.y.name, "sheenRoughness");
  EXPECT_EQ(t.y.min, 0.0);
  EXPECT_EQ(t.y.max, 0.6);
  EXPECT_EQ(t.y.count, 20);  // ceil(32 x 0.6): the full table's texel spacing
  EXPECT_EQ(*t.FindMetadata("visibility"), "ashikhmin");
  const CheckReport check = CheckBakedSet(out.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  fs::remove_all(out);
}

// The header's helper is glTF's 1 - max3(sheenColor) E(NdotV, r) (and the
// min over NdotV and NdotL), over the header's own lookup: compiled with
// both compilers, run, and compared with the formula over the .bin values.
TEST(SheenTables, HeaderHelperIsTheAlbedoScaling) {
  const fs::path out = test::Scratch("sheen_header");
  BakeRequest request = test::BakeRequestFor(out);  // --tables sheen_E --size 8
  request.tables = {"sheen_E"};
  request.size = 8;
  Bake(request);
  const Table t = ReadBinaryTable((out / "sheen_E.bin").string());
  const fs::path program = out / "scaling.cpp";
  std::ofstream(program) << "#include <cstdio>\n#include \"sheen_E.h\"\n"
                            "int main() {\n"
                            "  using namespace lutbake_luts;\n"
                            "  std::printf(\"%.9g %.9g %.9g\\n\", lookup_sheen_E(0.3f, 0.5f),\n"
                            "      albedo_scaling_sheen_E(0.3f, 0.5f, 0.2f, 0.7f, 0.4f),\n"
                            "      albedo_scaling_sheen_E(0.3f, 0.9f, 0.5f, 0.2f, 0.7f, 0.4f));\n"
                            "}\n";
  const double lookup = Lookup(t, 0.3, 0.5, 0);
  const double lookupL = Lookup(t, 0.9, 0.5, 0);
  for (const std::string &compiler : test::HeaderCompilers()) {
    const std::string exe = (out / "scaling").string();
    ASSERT_EQ(std::system((compiler + " -std=c++17 -Wall -Wextra -Werror -I" + out.string() + " " +
                           program.string() + " -o " + exe)
                              .c_str()),
              0)
        << compiler;
    FILE *pipe = popen(exe.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    double e = 0, one = 0, two = 0;
    ASSERT_EQ(std::fscanf(pipe, "%lf %lf %lf", &e, &one, &two), 3);
    pclose(pipe);
    EXPECT_NEAR(e, lookup, 1e-6 * std::max(1.0, lookup)) << compiler;
    EXPECT_FLOAT_EQ(static_cast<float>(one), 1.0f - 0.7f * static_cast<float>(e)) << compiler;
    const double viaL = 1.0 - 0.7 * lookupL;
    EXPECT_NEAR(two, std::min(1.0 - 0.7 * lookup, viaL), 1e-6) << compiler;
  }
  fs::remove_all(out);
}

}  // namespace
}  // namespace lutbake
