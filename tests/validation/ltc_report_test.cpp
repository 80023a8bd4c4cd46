// The LTC lobe error map of `lutbake report --tables ltc_ggx`: a fitted
// table against the plain cosine (M^-1 = I, what an LTC is before fitting)
// read from a three.js-style module, both measured alike; the reader of
// three.js's own number spelling; the files' shapes; the request's checks.
#include "lutbake/validation/ltc_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "lutbake/api/report.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/models/ltc.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const Table &Fitted() {
  static const Table table = [] {
    BakeSettings s;
    s.size = 12;
    return BakeTable(TableNamed("ltc_ggx"), s);
  }();
  return table;
}

// A module in three.js's layout whose every texel is the cosine (M^-1 = I)
// with magnitude `magnitude`; negatives spelled "- 0" as three.js's own
// module spells some of its numbers.
fs::path CosineModule(const std::string &name, double magnitude) {
  const fs::path dir = test::Scratch(name);
  fs::create_directories(dir);
  const fs::path path = dir / "RectAreaLightTexturesLib.js";
  std::ofstream out(path);
  out << "const LTC_MAT_1 = [\n";
  for (int t = 0; t < 64 * 64; ++t) out << "1, - 0, 0, 1,\n";
  out << "];\nconst LTC_MAT_2 = [\n";
  for (int t = 0; t < 64 * 64; ++t) out << magnitude << ", 0, 0, 1,\n";
  out << "];\n";
  return path;
}

TEST(LtcReport, TheFittedTableBeatsThePlainCosineAtEveryRoughPoint) {
  const fs::path module = CosineModule("ltc_report_cosine", 1.0);
  const LtcErrorMap map =
      MeasureLtcErrorMap(Fitted(), NdfKind::kGgx, SmithForm::kCorrelated, module.string(), 8);
  ASSERT_EQ(map.ours.size(), 64u);
  ASSERT_EQ(map.theirs.size(), 64u);
  for (size_t k = 0; k < map.ours.size(); ++k) {
    ASSERT_TRUE(std::isfinite(map.ours[k]) && map.ours[k] >= 0.0) << k;
    const double r = (static_cast<double>(k / 8) + 0.5) / 8;
    // At r = 1 GGX is near a cosine; below, the fitted LTC must win.
    if (r < 0.8) {
      EXPECT_LT(map.ours[k], map.theirs[k]) << "point " << k;
    }
  }
  EXPECT_LT(map.meanOurs, 0.5 * map.meanTheirs);
  // The cosine's own error at one point, computed directly: the map's
  // value there (it reads the module's numbers, "- 0" included).
  const double mu = 2.5 / 8, r = 3.5 / 8;
  const LtcLobe lobe = MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
  double magnitude = 0, fresnel = 0;
  lobe.moments(mu, &magnitude, &fresnel);
  EXPECT_NEAR(map.theirs[3 * 8 + 2], LtcLobeError(lobe, mu, magnitude, 1.0, LtcMatrix{}, 1), 1e-12);
  fs::remove_all(module.parent_path());
}

// ltc_code's table read as three.js reads it: texel (i, j) at (r, sqrt(1 -
// mu)) = (i, j) / 63, bilinear between, clamped at the edges. Texels that
// hold the bilinear function (1 + 2 i + 3 j + i j / 2) (c + 1) (exact in
// float) make the lookup that function of (x, y) = 63 (r, sqrt(1 - mu))
// clamped to [0, 63] exactly (bilinear interpolation reproduces a bilinear
// function), up to the rounding of the coordinates.
TEST(LtcReport, ThreejsTextureIsLookedUpAsThreejsSamplesIt) {
  std::vector<float> mat1(64 * 64 * 4), mat2(64 * 64 * 4, -7.0f);
  const auto f = [](double x, double y, int c) {
    return (1 + 2 * x + 3 * y + 0.5 * x * y) * (c + 1);
  };
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const size_t at = (static_cast<size_t>(j) * 64 + i) * 4;
      for (int c = 0; c < 4; ++c) mat1[at + c] = static_cast<float>(f(i, j, c));
      mat2[at] = static_cast<float>(f(i, j, 4));
    }
  const Table t = ThreejsLtcTexture(mat1, mat2);
  ASSERT_EQ(t.channels, 5);
  for (const auto &[r, s] : std::vector<std::pair<double, double>>{{0.0, 0.0},
                                                                   {1.0, 1.0},
                                                                   {5.0 / 63, 40.0 / 63},
                                                                   {0.123, 0.877},
                                                                   {0.5, 0.25},
                                                                   {-0.1, 0.3},
                                                                   {0.7, 1.2},
                                                                   {0.999, 0.001}}) {
    const double x = std::clamp(63.0 * r, 0.0, 63.0), y = std::clamp(63.0 * s, 0.0, 63.0);
    for (int c = 0; c < 5; ++c)
      EXPECT_NEAR(Lookup(t, r, s, c), f(x, y, c), 1e-11 * f(x, y, c))
          << r << ", " << s << ", " << c;
  }
  mat2.pop_back();
  EXPECT_THROW(ThreejsLtcTexture(mat1, mat2), std::invalid_argument);
}

TEST(LtcReport, FilesHoldEveryPoint) {
  const LtcErrorMap alone =
      MeasureLtcErrorMap(Fitted(), NdfKind::kGgx, SmithForm::kCorrelated, "", 4);
  EXPECT_TRUE(alone.theirs.empty());
  const std::string csv = LtcErrorCsv(alone);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 16);
  const std::string svg = LtcErrorSvg(alone);
  size_t cells = 0;
  for (size_t at = svg.find("<rect x="); at != std::string::npos; at = svg.find("<rect x=", at + 1))
    ++cells;
  EXPECT_EQ(cells, 16u + 32u);  // the map and the colour bar
  EXPECT_NE(LtcErrorMarkdown(alone).find("| lutbake ltc_ggx |"), std::string::npos);
}

TEST(LtcReport, AReferenceNeedsTheTableAndGgx) {
  ReportRequest r;
  r.outputDirectory = (test::Scratch("ltc_report_refused") / "out").string();
  r.tables = std::vector<std::string>{"E"};
  r.ltcReference = "ltc.js";
  EXPECT_THROW(Report(r), UsageError);
  r.tables = std::vector<std::string>{"ltc_ggx"};
  r.ndf = NdfKind::kBeckmann;
  EXPECT_THROW(Report(r), UsageError);
  EXPECT_FALSE(fs::exists(r.outputDirectory));
}

TEST(LtcReport, AMalformedReferenceIsRefusedNamingIt) {
  const fs::path dir = test::Scratch("ltc_report_bad");
  fs::create_directories(dir);
  const fs::path path = dir / "short.js";
  std::ofstream(path) << "const LTC_MAT_1 = [ 1, 0, 0, 1 ];\nconst LTC_MAT_2 = [ 1, 0, 0, 1 ];\n";
  try {
    MeasureLtcErrorMap(Fitted(), NdfKind::kGgx, SmithForm::kCorrelated, path.string(), 2);
    FAIL() << "accepted";
  } catch (const IoError &e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("16384 expected"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
