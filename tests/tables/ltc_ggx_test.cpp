// Table ltc_ggx (issue 28): its values against independent quadratures
// (magnitude = E, fresnel against the adaptive reference), det M^-1 > 0,
// finiteness, bit-identical bakes for 1 and 2 threads, eval at a texel centre
// against the bake, the stated lobe error against an independent
// measurement at a finer rule, check on its files, and the files it writes
// read back in its channel order. The checks every LTC table passes are in
// ltc_lobe_table_checks.h; this file calls the library, not the executable.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ltc_lobe_table_checks.h"
#include "lutbake/api/eval.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const TableDefinition &Ltc() { return TableNamed("ltc_ggx"); }

BakeSettings Sized(int size) { return test::LtcSized(size); }

const test::LtcLobeTable kTable{
    "ltc_ggx",
    "E",
    [](double r) {
      return MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
    },
    0.55,
    0.02,
    0.11,
    2e-3,
    3,
    2,
    0.0};

// A 12 x 12 bake shared by the tests (about 0.3 s of CPU).
const Table &Small() {
  static const Table table = BakeTable(Ltc(), Sized(12));
  return table;
}

LtcMatrix MatrixAt(const Table &t, int ix, int iy) {
  return {t.value(ix, iy, 0), t.value(ix, iy, 1), t.value(ix, iy, 2), t.value(ix, iy, 3)};
}

TEST(LtcGgx, ChannelsAxesAndDefaults) {
  EXPECT_EQ(Ltc().Channels(), 6);
  EXPECT_EQ(Ltc().ChannelNames(),
            (std::vector<std::string>{"m00", "m20", "m02", "m22", "magnitude", "fresnel"}));
  Axis x, y;
  DefaultAxes(Ltc(), BakeSettings{}, &x, &y);
  EXPECT_EQ(x.name, "mu");
  EXPECT_EQ(y.name, "perceptualRoughness");
  EXPECT_EQ(x.count, 64);
  EXPECT_EQ(y.count, 64);
  EXPECT_EQ(x.TexelCenter(0), 0.5 / 64);  // texel centres
  EXPECT_FALSE(Ltc().Sampled());
}

// magnitude is table E's value bit for bit; fresnel is dfg's B bit for bit
// and within 1e-5 of the adaptive Gauss-Kronrod reference (another rule and
// parameterisation), as is magnitude.
TEST(LtcGgx, MagnitudeIsEAndFresnelIsB) {
  const Table &t = Small();
  const Table e = BakeTable(TableNamed("E"), Sized(12));
  const Table dfg = BakeTable(TableNamed("dfg"), Sized(12));
  BakeSettings reference = Sized(12);
  reference.estimator = Estimator::kAdaptiveQuadrature;
  double worst = 0.0;
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      EXPECT_EQ(t.value(ix, iy, 4), e.value(ix, iy, 0));
      EXPECT_EQ(t.value(ix, iy, 5), dfg.value(ix, iy, 1));
      if ((ix + iy) % 3 != 0) continue;  // a third of the texels for the reference
      const double mu = t.x.TexelCenter(ix), r = t.y.TexelCenter(iy);
      const PointValue ref = TableNamed("dfg").Evaluate(reference, mu, r);
      worst = std::max(worst, std::fabs(t.value(ix, iy, 4) - (ref.value[0] + ref.value[1])));
      worst = std::max(worst, std::fabs(t.value(ix, iy, 5) - ref.value[1]));
    }
  EXPECT_LT(worst, 1e-5);
}

TEST(LtcGgx, DeterminantPositiveAndFinite) {
  const Table &t = Small();
  for (double v : t.values) EXPECT_TRUE(std::isfinite(v));
  for (double v : t.errors) EXPECT_TRUE(std::isfinite(v));
  for (double v : t.fitMaps) EXPECT_TRUE(std::isfinite(v));
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      // As stored in float32, too.
      const LtcMatrix m = MatrixAt(t, ix, iy);
      const double det =
          static_cast<double>(static_cast<float>(m.m00)) * static_cast<float>(m.m22) -
          static_cast<double>(static_cast<float>(m.m02)) * static_cast<float>(m.m20);
      EXPECT_GT(m.Determinant(), 0.0) << ix << ", " << iy;
      EXPECT_GT(det, 0.0) << ix << ", " << iy;
    }
}

TEST(LtcGgx, BitIdenticalForOneAndTwoThreads) {
  test::ExpectBitIdenticalForOneAndTwoThreads(kTable, 10);
}

// eval fits a point along the bake's path: at a texel centre of the default
// grid it is the bake's texel bit for bit.
TEST(LtcGgx, EvalAtTexelCentreIsTheBakesTexel) {
  test::ExpectEvalAtTexelCentreIsTheBakesTexel(kTable, Small(), {{0, 0}, {11, 11}, {3, 7}, {9, 2}});
  // Off the texels: a valid LTC.
  const PointValue v = Ltc().Evaluate(Sized(12), 0.37, 0.55);
  EXPECT_GT(v.value[0] * v.value[3] - v.value[2] * v.value[1], 0.0);
}

// The stated lobe error (the level-1 rule, for the matrix as stored)
// against the level-2 rule at every third texel of every other row, and
// within what the fit reaches on this 12 x 12 grid (measured: lobe error
// mean 0.099, max 0.505 at a grazing view; leakage max 0.0174).
TEST(LtcGgx, StatedLobeErrorAgreesWithAFinerRule) {
  test::ExpectStatedLobeErrorAgreesWithTheNextLevel(kTable, Small());
  const std::string *summary = Small().FindMetadata("fitErrors");
  ASSERT_NE(summary, nullptr);
  EXPECT_NE(summary->find("lobeError mean"), std::string::npos);
}

// bake --tables ltc_ggx --format exr,bin,header (lutbake::Bake): every file
// holds the six channels in order, T.fit.exr the three maps; image formats
// are refused.
TEST(LtcGgx, BakesExrBinHeaderAndReadsThemBack) {
  const fs::path dir = fs::temp_directory_path() / "lutbake_ltc_ggx_test";
  fs::remove_all(dir);
  BakeRequest request;
  request.outputDirectory = dir.string();
  request.tables = std::vector<std::string>{"ltc_ggx"};
  request.size = 8;
  request.formats = std::vector<std::string>{"exr", "bin", "header"};
  Bake(request);
  const Table expected = BakeTable(Ltc(), Sized(8));
  const Table exr = ReadExrTable((dir / "ltc_ggx.exr").string());
  const Table bin = ReadBinaryTable((dir / "ltc_ggx.bin").string());
  const HeaderValues h = ReadHeaderValues((dir / "ltc_ggx.h").string());
  ASSERT_EQ(exr.channelNames, Ltc().ChannelNames());
  ASSERT_EQ(bin.channelNames, Ltc().ChannelNames());
  ASSERT_EQ(h.channels, 6);
  ASSERT_EQ(exr.values.size(), expected.values.size());
  ASSERT_EQ(bin.values.size(), expected.values.size());
  ASSERT_EQ(h.values.size(), expected.values.size());
  for (size_t i = 0; i < expected.values.size(); ++i) {
    const float v = static_cast<float>(expected.values[i]);
    EXPECT_EQ(static_cast<float>(exr.values[i]), v);
    EXPECT_EQ(static_cast<float>(bin.values[i]), v);
    EXPECT_EQ(h.values[i], v);
  }
  const Table fit = ReadExrTable((dir / "ltc_ggx.fit.exr").string());
  ASSERT_EQ(fit.channelNames, expected.fitMapNames);
  for (size_t i = 0; i < expected.fitMaps.size(); ++i)
    EXPECT_EQ(static_cast<float>(fit.values[i]), static_cast<float>(expected.fitMaps[i]));
  request.formats = std::vector<std::string>{"png16"};
  try {
    Bake(request);
    ADD_FAILURE() << "--format png16 was not refused";
  } catch (const UsageError &e) {
    EXPECT_NE(std::string(e.what()).find("holds at most 2 channels"), std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}

// eval --json (lutbake::Evaluate) prints the six channels fitted at the
// point, and the lobe error, polygon error and leakage beside them, as the
// definition computes them.
TEST(LtcGgx, EvalJsonPrintsSixChannelsAndTheLobeError) {
  EvalRequest request;
  request.table = "ltc_ggx";
  request.coordinates = {{"mu", {0.4}}, {"roughness", {0.35}}};
  const EvalResult result = Evaluate(request);
  ASSERT_EQ(result.points.size(), 1u);
  const nlohmann::json line = nlohmann::json::parse(result.JsonLine(0));
  ASSERT_EQ(line["value"].size(), 6u);
  const PointValue v = Ltc().Evaluate(BakeSettings{}, 0.4, 0.35);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(line["value"][c].get<double>(), v.value[c]);
  const auto fit = Ltc().PointFitErrors(BakeSettings{}, 0.4, 0.35, v);
  ASSERT_EQ(fit.size(), 3u);
  EXPECT_EQ(line["lobeError"].get<double>(), fit[0].second);
  EXPECT_EQ(line["polygonError"].get<double>(), fit[1].second);
  EXPECT_EQ(line["leakage"].get<double>(), fit[2].second);
  EXPECT_GT(fit[0].second, 0.0);
  EXPECT_LT(fit[0].second, 0.3);
  // The text form names them too.
  EXPECT_NE(result.TextLine(0).find("lobeError"), std::string::npos) << result.TextLine(0);
}

// check on a bake of ltc_ggx and E: passes; a texel with a negative
// determinant, or swapped for the mirrored branch (the lobe reflected to the
// view's side), or a changed magnitude, fails the check that guards it.
TEST(LtcGgx, CheckPassesAndCatchesBrokenTexels) {
  test::ExpectCheckPassesAndCatchesBrokenTexels(kTable);
}

}  // namespace
}  // namespace lutbake
