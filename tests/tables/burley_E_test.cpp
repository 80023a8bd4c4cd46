// Table burley_E, the directional albedo of Burley's (Disney 2012) diffuse:
// the closed form against a brute-force 2D Gauss-Legendre quadrature of the
// BRDF (the half vector computed, not the 2 cos^2(theta_d) = 1 + v.l
// identity), against its analytic values, against a long-double evaluation
// of the unexpanded derivation (its stated rounding bound, and the bound of
// the stored float32), check's reference, the Unity HDRP preset channel that
// reads it, and eval, bake (every format), check and the header's helpers
// through the library calls the command line makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "lutbake/api/bake.h"
#include "lutbake/api/check.h"
#include "lutbake/api/eval.h"
#include "lutbake/core/error.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table_definition.h"
#include "support/check_json.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

double BurleyE(double mu, double r) { return TableNamed("burley_E").Evaluate({}, mu, r).value[0]; }

// The albedo by brute force: Gauss-Legendre over mu_l in [0, 1] (panels of
// 16 nodes) times phi in [0, pi] (f is even in phi; 4 panels of 16 nodes),
// f_d with cos(theta_d) = l.h from h = normalize(v + l).
double BruteForceBurleyE(double mu, double r) {
  const GaussLegendreRule &rule = GaussLegendre(16);
  const double s = std::sqrt((1.0 - mu) * (1.0 + mu));
  const int muPanels = 4, phiPanels = 4;
  double sum = 0.0;
  for (int pm = 0; pm < muPanels; ++pm)
    for (int a = 0; a < rule.n; ++a) {
      const double mu_l = (pm + rule.x[a]) / muPanels;
      const double s_l = std::sqrt((1.0 - mu_l) * (1.0 + mu_l));
      double inner = 0.0;
      for (int pp = 0; pp < phiPanels; ++pp)
        for (int b = 0; b < rule.n; ++b) {
          const double phi = (pp + rule.x[b]) / phiPanels * kPi;
          const double lx = s_l * std::cos(phi), ly = s_l * std::sin(phi);
          const double hx = s + lx, hy = ly, hz = mu + mu_l;
          const double lh =
              (lx * hx + ly * hy + mu_l * hz) / std::sqrt(hx * hx + hy * hy + hz * hz);
          const double fd90 = 0.5 + 2.0 * r * lh * lh;
          const double f = (1.0 + (fd90 - 1.0) * std::pow(1.0 - mu_l, 5)) *
                           (1.0 + (fd90 - 1.0) * std::pow(1.0 - mu, 5)) / kPi;
          inner += rule.w[b] / phiPanels * kPi * f;
        }
      sum += rule.w[a] / muPanels * 2.0 * inner * mu_l;  // phi over [0, 2 pi]: twice [0, pi]
    }
  return sum;
}

// The derivation before it was expanded, in long double (64-bit mantissa):
// E = 1 + 2 c I1 + 2 r mu I2 + 2 b (c / 2 + r mu / 3)
//     + 2 b (c^2 I1 + 2 c r mu I2 + r^2 mu^2 I3 + r^2 (1 - mu^2)(I1 - I3) / 2),
// c = r - 1/2, b = (1 - mu)^5, I_n = int_0^1 x^n (1 - x)^5 dx = n! 5! / (n + 6)!.
long double UnexpandedBurleyE(long double mu, long double r) {
  const long double I1 = 1.0L / 42, I2 = 1.0L / 168, I3 = 1.0L / 504;
  const long double c = r - 0.5L, b = std::pow(1.0L - mu, 5), s2 = 1.0L - mu * mu;
  return 1 + 2 * c * I1 + 2 * r * mu * I2 + 2 * b * (c / 2 + r * mu / 3) +
         2 * b *
             (c * c * I1 + 2 * c * r * mu * I2 + r * r * mu * mu * I3 + r * r * s2 * (I1 - I3) / 2);
}

TEST(BurleyTable, ClosedFormMatchesBruteForceQuadrature) {
  double worst = 0.0;
  for (double mu : {0.0, 1e-9, 1e-3, 0.05, 0.2, 0.5, 0.7071, 0.9, 0.999, 1.0})
    for (double r : {0.0, 1e-3, 0.1, 0.3, 0.5, 0.8, 0.99, 1.0}) {
      const PointValue v = TableNamed("burley_E").Evaluate({}, mu, r);
      const double brute = BruteForceBurleyE(mu, r);
      worst = std::max(worst, std::abs(v.value[0] - brute));
      EXPECT_NEAR(v.value[0], brute, 1e-13) << "mu " << mu << " r " << r;
    }
  std::printf("closed form vs brute-force 2D Gauss-Legendre: max |difference| %.3g\n", worst);
}

TEST(BurleyTable, AnalyticValues) {
  const double bound = TableNamed("burley_E").Evaluate({}, 0.5, 0.5).error[0];
  EXPECT_EQ(bound, 1e-14);
  // Normal view: the view factor is 1 and E = 2 int mu_l F(mu_l) = 41/42 + 5 r / 84.
  for (double r : {0.0, 0.25, 0.6, 1.0})
    EXPECT_NEAR(BurleyE(1.0, r), 41.0 / 42.0 + 5.0 * r / 84.0, bound) << r;
  // ... which is HDRP's normalisation 1.03571 at r = 1 (29/28, rounded).
  EXPECT_NEAR(BurleyE(1.0, 1.0), 29.0 / 28.0, bound);
  EXPECT_NEAR(29.0 / 28.0, 1.03571, 5e-6);
  // r = 0: F_D90 = 1/2 everywhere, the BRDF separates, E = F(mu) 2 int mu_l F(mu_l).
  for (double mu : {0.0, 0.1, 0.5, 0.9, 1.0})
    EXPECT_NEAR(BurleyE(mu, 0.0), 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - mu, 5)), bound) << mu;
  // The extremes (the range check claims): grazing, smooth and rough.
  EXPECT_NEAR(BurleyE(0.0, 0.0), 41.0 / 84.0, bound);
  EXPECT_NEAR(BurleyE(0.0, 1.0), 785.0 / 504.0, bound);
}

// The stated bound 1e-14 covers the double evaluation: measured against the
// unexpanded form in long double over a 401 x 401 grid (the corners
// included); and the bound a float32 file states covers its stored value.
TEST(BurleyTable, StatedBoundsHold) {
  const TableDefinition &table = TableNamed("burley_E");
  double worst = 0.0, worstStored = 0.0, worstStoredBound = 0.0, lo = 1e300, hi = -1e300;
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j <= 400; ++j) {
      const double mu = i / 400.0, r = j / 400.0;
      const PointValue v = table.Evaluate({}, mu, r);
      const long double exact = UnexpandedBurleyE(mu, r);
      const double error =
          static_cast<double>(std::fabs(static_cast<long double>(v.value[0]) - exact));
      worst = std::max(worst, error);
      ASSERT_LE(error, v.error[0]) << "mu " << mu << " r " << r;
      const double stored = StoredValue(v.value[0], ValueType::kFloat32);
      const double storedBound = StoredBound(v.value[0], v.error[0], ValueType::kFloat32);
      const double storedError =
          static_cast<double>(std::fabs(static_cast<long double>(stored) - exact));
      ASSERT_LE(storedError, storedBound) << "mu " << mu << " r " << r;
      // Half an ulp of float32: 2^-25 below 1, 2^-24 in [1, 2).
      ASSERT_LE(storedBound, (v.value[0] < 1.0 ? 0x1p-25 : 0x1p-24) + 2e-14) << mu << " " << r;
      worstStored = std::max(worstStored, storedError);
      worstStoredBound = std::max(worstStoredBound, storedBound);
      lo = std::min(lo, v.value[0]);
      hi = std::max(hi, v.value[0]);
      // The range check's claim, and dE/dr > 0 (the claim's proof).
      EXPECT_GE(v.value[0], 41.0 / 84.0 - 1e-15);
      EXPECT_LE(v.value[0], 785.0 / 504.0 + 1e-15);
      if (j > 0) {
        EXPECT_GT(v.value[0], table.Evaluate({}, mu, (j - 1) / 400.0).value[0]);
      }
    }
  EXPECT_DOUBLE_EQ(lo, BurleyE(0.0, 0.0));
  EXPECT_DOUBLE_EQ(hi, BurleyE(0.0, 1.0));
  std::printf(
      "closed form in double vs long double: max %.3g (bound 1e-14); float32 stored: max error "
      "%.3g, max stated bound %.3g\n",
      worst, worstStored, worstStoredBound);
}

// check's range claim holds for every stored value: the extremes, stored
// in half or float32, stay inside it, though half rounds across 785/504
// itself at the first texel of a 4096-texel axis.
TEST(BurleyTable, RangeClaimHoldsForStoredValues) {
  const ValueClaim claim = TableNamed("burley_E").Range({});
  for (ValueType type : {ValueType::kFloat32, ValueType::kHalf, ValueType::kFloat64}) {
    EXPECT_GE(StoredValue(BurleyE(0.0, 0.0), type), claim.lower) << ToString(type);
    EXPECT_LE(StoredValue(BurleyE(0.0, 1.0), type), claim.upper) << ToString(type);
  }
  const double nearCorner = BurleyE(0.5 / 4096, 1.0 - 0.5 / 4096);
  EXPECT_LT(nearCorner, 785.0 / 504.0);
  EXPECT_GT(StoredValue(nearCorner, ValueType::kHalf), 785.0 / 504.0);
}

// check's reference, nested adaptive Gauss-Kronrod of the BRDF, is another
// computation that agrees within its bound.
TEST(BurleyTable, ReferenceAgreesWithTheClosedForm) {
  BakeSettings adaptive;
  adaptive.estimator = Estimator::kAdaptiveQuadrature;
  int differ = 0;
  for (double mu : {0.0, 0.01, 0.4, 0.8, 1.0})
    for (double r : {0.0, 0.35, 1.0}) {
      const PointValue ref = TableNamed("burley_E").Evaluate(adaptive, mu, r);
      const PointValue closed = TableNamed("burley_E").Evaluate({}, mu, r);
      EXPECT_NEAR(ref.value[0], closed.value[0], ref.error[0] + closed.error[0]) << mu << " " << r;
      EXPECT_LT(ref.error[0], 1e-9);
      EXPECT_FALSE(ref.exact);
      EXPECT_TRUE(closed.exact);
      differ += ref.value[0] != closed.value[0];
    }
  EXPECT_GT(differ, 0) << "the reference must not be the closed form";
}

// Unity HDRP's Disney diffuse channel (z + 0.5) is burley_E / 1.03571 at
// the texel's (NdotV, perceptualRoughness), read from the table; and the
// preset's former rule (8-node Gauss-Legendre over mu_i of the azimuth-
// averaged polynomial, written again here) gives the same values, to
// rounding.
TEST(BurleyTable, HdrpPresetChannelReadsTheTable) {
  const PresetTexture &texture = FindPreset("unity-hdrp")->textures.at(0);
  ASSERT_EQ(texture.channels.at(2).meaning, "disney_diffuse");
  const Table table = BakePresetTexture(texture, "unity-hdrp");
  const GaussLegendreRule &rule = GaussLegendre(8);
  double worstOld = 0.0;
  for (int iy = 0; iy < 64; ++iy)
    for (int ix = 0; ix < 64; ++ix) {
      const double mu = texture.axes[0].Quantity(ix), p = texture.axes[1].Quantity(iy);
      const double expected = BurleyE(mu, p) / 1.03571;
      EXPECT_NEAR(table.value(ix, iy, 2) + 0.5, expected, 1e-15) << mu << " " << p;
      const double b = std::pow(1.0 - mu, 5.0), s2 = (1.0 - mu) * (1.0 + mu);
      double sum = 0.0;
      for (int k = 0; k < rule.n; ++k) {
        const double mu_i = rule.x[k], a = std::pow(1.0 - mu_i, 5.0);
        const double P = p - 0.5 + p * mu * mu_i;
        const double Q2 = p * p * s2 * (1.0 - mu_i) * (1.0 + mu_i);
        sum += rule.w[k] * mu_i * (1.0 + P * (a + b) + (P * P + 0.5 * Q2) * a * b);
      }
      worstOld = std::max(worstOld, std::abs(2.0 / 1.03571 * sum - 0.5 - table.value(ix, iy, 2)));
    }
  EXPECT_LT(worstOld, 1e-14);
  std::printf("HDRP disney_diffuse: the former 8-node rule vs the table, max |difference| %.3g\n",
              worstOld);
}

TEST(BurleyTable, Eval) {
  EvalRequest request;
  request.table = "burley_E";
  request.coordinates = {{"mu", {0.25, 1.0}}, {"roughness", {0.5}}};
  const EvalResult eval = Evaluate(request);
  // One point each; E(1, 1/2) = 41/42 + 5/168 = 169/168.
  ASSERT_EQ(eval.points.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const nlohmann::json point = nlohmann::json::parse(eval.JsonLine(k));
    const double mu = k == 0 ? 0.25 : 1.0;
    EXPECT_EQ(point["mu"].get<double>(), mu);
    EXPECT_EQ(point["roughness"].get<double>(), 0.5);
    EXPECT_EQ(point["estimator"], "exact");
    EXPECT_EQ(point["error"].get<double>(), 1e-14);
    EXPECT_EQ(point["value"].get<double>(), BurleyE(mu, 0.5));
  }
  EXPECT_NEAR(BurleyE(1.0, 0.5), 169.0 / 168.0, 1e-14);
  // Out of range, an option the table does not take, a coordinate missing:
  // usage errors (exit 2 on the command line).
  for (const auto &coordinates : std::vector<std::map<std::string, std::vector<double>>>{
           {{"mu", {0.5}}, {"roughness", {1.5}}},
           {{"mu", {0.5}}, {"sigma", {0.5}}},
           {{"mu", {0.5}}}}) {
    request.coordinates = coordinates;
    EXPECT_THROW(Evaluate(request), UsageError);
  }
}

BakeRequest BurleyBake(const fs::path &dir, const std::vector<std::string> &formats) {
  BakeRequest request;
  request.outputDirectory = dir.string();
  request.tables = std::vector<std::string>{"burley_E"};
  request.size = 8;
  request.formats = formats;
  return request;
}

// Every format that holds values above 1 writes it, and check reads the set
// back: the closed form at every texel, the range, the reference. PNG holds
// [0, 1] only and refuses it (E reaches 785/504), as it refuses sheen_E.
TEST(BurleyTable, BakeEveryFormatAndCheck) {
  const fs::path dir = test::Scratch("burley_bake");
  BakeRequest request = BurleyBake(dir, {"exr", "bin", "header", "ktx2", "dds", "inc", "js", "ts",
                                         "glsl-array", "hlsl-array", "wgsl-array", "msl-array"});
  request.shaders = {"glsl", "hlsl", "wgsl", "msl"};
  request.errorMaps = true;
  Bake(request);
  for (const char *file : {"burley_E.exr", "burley_E.bin", "burley_E.h", "burley_E.ktx2",
                           "burley_E.dds", "burley_E.inc", "burley_E.js", "burley_E.ts"})
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  CheckRequest checkRequest;
  checkRequest.dir = dir.string();
  const CheckOutcome check = Check(checkRequest);
  EXPECT_TRUE(check.passed) << check.text << check.failureText;
  std::map<std::string, std::string> status = test::CheckStatuses(check.json);
  for (const char *claim : {"burley_E range", "burley_E texels", "burley_E points",
                            "burley_E closed form", "burley_E finite"})
    EXPECT_EQ(status[claim], "pass") << claim << "\n" << check.text;
  fs::remove_all(dir);

  const fs::path half = test::Scratch("burley_half");
  request = BurleyBake(
      half, {"ktx2-half", "dds-half", "inc-half", "js-half", "ts-half", "header", "bin"});
  request.headerType = "half";
  request.binType = "double";
  Bake(request);
  checkRequest.dir = half.string();
  EXPECT_TRUE(Check(checkRequest).passed);
  fs::remove_all(half);

  const fs::path png = test::Scratch("burley_png");
  try {
    Bake(BurleyBake(png, {"png16"}));
    ADD_FAILURE() << "png16 accepted values above 1";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("stores values in [0, 1] only"), std::string::npos)
        << e.what();
  }
  fs::remove_all(png);
}

// The header's helpers compile (both compilers, warnings as errors) and
// return E / 1.03571 and 1 / E at a texel centre, where the lookup is the
// texel.
TEST(BurleyTable, HeaderHelpers) {
  const fs::path dir = test::Scratch("burley_header");
  Bake(BurleyBake(dir, {"header"}));
  const double mu = 2.5 / 8, r = 6.5 / 8, e = static_cast<float>(BurleyE(mu, r));
  std::ofstream(dir / "main.cpp")
      << "#include <cmath>\n#include \"burley_E.h\"\n"
         "int main() {\n"
         "  using namespace lutbake_luts;\n"
         "  const float fgd = hdrp_diffuse_fgd_burley_E(0.3125f, 0.8125f);\n"
         "  const float n = normalisation_burley_E(0.3125f, 0.8125f);\n"
         "  if (std::fabs(fgd - " +
             std::to_string(e / 1.03571) + "f) > 1e-6f) return 1;\n" + "  if (std::fabs(n - " +
             std::to_string(1.0 / e) + "f) > 1e-6f) return 2;\n" + "  return 0;\n}\n";
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(dir, "c++17");
  fs::remove_all(dir);
}

// check on a unity-hdrp directory recomputes the texture (now from the
// table) and holds the file to it.
TEST(BurleyTable, CheckReadsTheHdrpPresetBack) {
  const fs::path dir = test::Scratch("burley_hdrp");
  BakeRequest request;
  request.outputDirectory = dir.string();
  request.preset = "unity-hdrp";
  request.presetFiles = std::vector<std::string>{"PreIntegratedFGD_GGXDisneyDiffuse.exr"};
  Bake(request);
  CheckRequest checkRequest;
  checkRequest.dir = dir.string();
  const CheckOutcome check = Check(checkRequest);
  EXPECT_TRUE(check.passed) << check.text;
  EXPECT_NE(check.text.find("pass PreIntegratedFGD_GGXDisneyDiffuse.exr"), std::string::npos)
      << check.text;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
