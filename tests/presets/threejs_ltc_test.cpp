// The threejs-ltc preset (three.js's RectAreaLightTexturesLib.js): the
// module read back by a reader of its own here (not the library's), in
// three.js's layout and axes (texel (row i, column j) at (i * 64 + j) * 4,
// roughness j / 63, NdotV = 1 - (i / 63)^2), its LTC_MAT_2 against table
// dfg's integrals at those points, det M^-1 > 0, the lobe error of every
// texel, the clipped sphere against a brute-force quadrature, and
// `lutbake check` of the preset directory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/api/presets.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/table_definition.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

// The numbers between "const NAME = [" and the next "]", by strtod.
std::vector<double> JsArray(const std::string &text, const std::string &name) {
  std::vector<double> out;
  const size_t at = text.find("const " + name + " = [");
  if (at == std::string::npos) return out;
  const size_t open = text.find('[', at), close = text.find(']', open);
  std::string body = text.substr(open + 1, close - open - 1);
  for (char &c : body)
    if (c == ',') c = ' ';
  std::istringstream in(body);
  for (double v; in >> v;) out.push_back(v);
  return out;
}

// The clipped sphere by brute force: the cap of half-angle sigma (sin^2 =
// len) around the axis at cos(omega) = z, a midpoint rule of 1200 x 1200 in
// (t, phi), of max(w.z, 0) / pi, over len.
double BruteClippedSphere(double z, double len) {
  const double sigma = std::asin(std::sqrt(len)), omega = std::acos(z);
  const int n = 1200;
  double sum = 0.0;
  for (int a = 0; a < n; ++a) {
    const double t = (a + 0.5) / n * sigma;
    for (int b = 0; b < n; ++b) {
      const double phi = (b + 0.5) / n * 2.0 * kPi;
      const double wz =
          std::cos(omega) * std::cos(t) - std::sin(omega) * std::sin(t) * std::cos(phi);
      sum += std::max(wz, 0.0) * std::sin(t) * (sigma / n) * (2.0 * kPi / n);
    }
  }
  return sum / kPi / len;
}

class ThreejsLtc : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::Scratch("preset_threejs_ltc"));
    BakeRequest request = test::BakeRequestFor(*dir_);
    request.preset = "threejs-ltc";
    Bake(request);
    std::ifstream in(*dir_ / "RectAreaLightTexturesLib.js");
    text_ = new std::string((std::istreambuf_iterator<char>(in)), {});
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete text_;
  }
  static fs::path *dir_;
  static std::string *text_;
};
fs::path *ThreejsLtc::dir_ = nullptr;
std::string *ThreejsLtc::text_ = nullptr;

// Drop-in: three.js's imports, class and static textures.
TEST_F(ThreejsLtc, IsThreejsModule) {
  const std::string &text = *text_;
  EXPECT_NE(text.find("} from 'three';"), std::string::npos);
  EXPECT_NE(text.find("class RectAreaLightTexturesLib {"), std::string::npos);
  EXPECT_NE(text.find("static init() {"), std::string::npos);
  EXPECT_NE(text.find("new DataTexture( ltc_float_1, 64, 64, RGBAFormat, FloatType, UVMapping, "
                      "ClampToEdgeWrapping, ClampToEdgeWrapping, LinearFilter, NearestFilter, 1 )"),
            std::string::npos);
  EXPECT_NE(text.find("DataUtils.toHalfFloat( x )"), std::string::npos);
  EXPECT_NE(text.find("export { RectAreaLightTexturesLib };"), std::string::npos);
  for (const char *name : {"LTC_HALF_1", "LTC_HALF_2", "LTC_FLOAT_1", "LTC_FLOAT_2"})
    EXPECT_NE(text.find(std::string("RectAreaLightTexturesLib.") + name + " = null;"),
              std::string::npos);
}

// The layout as three.js reads it: t2 = (E, B, 0, w) at roughness j / 63
// and NdotV = 1 - (i / 63)^2, E and B table dfg's at that point as float32;
// det M^-1 > 0; the lobe error of t1 (as float32) at the texel's point.
TEST_F(ThreejsLtc, LayoutAxesAndValues) {
  const std::vector<double> t1 = JsArray(*text_, "LTC_MAT_1"), t2 = JsArray(*text_, "LTC_MAT_2");
  ASSERT_EQ(t1.size(), 64u * 64u * 4u);
  ASSERT_EQ(t2.size(), 64u * 64u * 4u);
  double meanLobe = 0.0, worstLobe = 0.0;
  int measured = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const size_t k = (static_cast<size_t>(i) * 64 + j) * 4;
      const double r = j / 63.0, v = i / 63.0, mu = 1.0 - v * v;
      const LtcMatrix m{t1[k], t1[k + 1], t1[k + 2], t1[k + 3]};
      EXPECT_GT(m.Determinant(), 0.0) << i << ", " << j;
      EXPECT_EQ(t2[k + 2], 0.0);
      if ((i * 7 + j) % 5 != 0) continue;  // a fifth of the texels for the integrals
      const PointValue ab = TableNamed("dfg").Evaluate(BakeSettings{}, mu, r);
      EXPECT_EQ(static_cast<float>(t2[k]), static_cast<float>(ab.value[0] + ab.value[1]))
          << i << ", " << j;
      EXPECT_EQ(static_cast<float>(t2[k + 1]), static_cast<float>(ab.value[1])) << i << ", " << j;
      const LtcLobe lobe = MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
      const double e = LtcLobeError(lobe, mu, t2[k], t2[k], m, 1);
      meanLobe += e;
      worstLobe = std::max(worstLobe, e);
      ++measured;
    }
  meanLobe /= measured;
  // Over all 4096 texels the lobe error measures mean 0.070, max 0.68 (at a
  // grazing view; tools/measure_ltc.cpp --shipped).
  EXPECT_LT(meanLobe, 0.1);
  EXPECT_LT(worstLobe, 0.7);
}

// w, the clipped sphere, at u = z / 2 + 1 / 2 and v = len: 1 where the cap
// is above the horizon (z = 1), against the brute force elsewhere.
TEST_F(ThreejsLtc, ClippedSphereAgainstBruteForce) {
  const std::vector<double> t2 = JsArray(*text_, "LTC_MAT_2");
  ASSERT_EQ(t2.size(), 64u * 64u * 4u);
  for (const auto &[i, j] : std::vector<std::pair<int, int>>{
           {32, 32}, {10, 40}, {50, 20}, {63, 40}, {63, 63}, {5, 10}, {40, 2}}) {
    const double z = 2.0 * j / 63.0 - 1.0, len = i / 63.0;
    const double w = t2[(static_cast<size_t>(i) * 64 + j) * 4 + 3];
    EXPECT_NEAR(w, BruteClippedSphere(z, len), 2e-6) << i << ", " << j;
  }
  EXPECT_EQ(t2[(static_cast<size_t>(0) * 64 + 63) * 4 + 3], 1.0);  // len 0, z = 1
}

// The library's reader and `lutbake check` of the preset directory.
TEST_F(ThreejsLtc, ReadsBackAndChecks) {
  const Table read = ReadThreejsLtcModule((*dir_ / "RectAreaLightTexturesLib.js").string());
  const std::vector<double> t1 = JsArray(*text_, "LTC_MAT_1"), t2 = JsArray(*text_, "LTC_MAT_2");
  ASSERT_EQ(read.channels, 8);
  ASSERT_EQ(read.values.size(), 64u * 64u * 8u);
  for (size_t t = 0; t < 64 * 64; ++t)
    for (int c = 0; c < 4; ++c) {
      ASSERT_EQ(read.values[t * 8 + c], static_cast<float>(t1[t * 4 + c]));
      ASSERT_EQ(read.values[t * 8 + 4 + c], static_cast<float>(t2[t * 4 + c]));
    }
  const PresetCheck check = CheckPresetDirectory(dir_->string());
  EXPECT_TRUE(check.pass) << check.json;
}

}  // namespace
}  // namespace lutbake
