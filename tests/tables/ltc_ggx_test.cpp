// Table ltc_ggx (issue 28): its values against independent quadratures
// (magnitude = E, fresnel against the adaptive reference), det M^-1 > 0,
// finiteness, bit-identical bakes for 1 and 2 threads, eval at a texel centre
// against the bake, the stated lobe error against an independent
// measurement at a finer rule, and the files it writes read back in its
// channel order.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"
#include "lutbake/validation/check.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const TableDefinition &Ltc() { return TableNamed("ltc_ggx"); }

BakeSettings Sized(int size) {
  BakeSettings s;
  s.size = size;
  s.commandLine = "lutbake bake --test";
  return s;
}

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
  Table one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = BakeTable(Ltc(), Sized(10));
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = BakeTable(Ltc(), Sized(10));
  }
  ASSERT_EQ(one.values.size(), two.values.size());
  EXPECT_EQ(0, std::memcmp(one.values.data(), two.values.data(), one.values.size() * 8));
  EXPECT_EQ(0, std::memcmp(one.errors.data(), two.errors.data(), one.errors.size() * 8));
  ASSERT_EQ(one.fitMaps.size(), two.fitMaps.size());
  EXPECT_EQ(0, std::memcmp(one.fitMaps.data(), two.fitMaps.data(), one.fitMaps.size() * 8));
}

// eval fits a point along the bake's path: at a texel centre of the default
// grid it is the bake's texel bit for bit.
TEST(LtcGgx, EvalAtTexelCentreIsTheBakesTexel) {
  const Table &t = Small();
  const BakeSettings s = Sized(12);
  for (const auto &[ix, iy] : std::vector<std::pair<int, int>>{{0, 0}, {11, 11}, {3, 7}, {9, 2}}) {
    const PointValue v = Ltc().Evaluate(s, t.x.TexelCenter(ix), t.y.TexelCenter(iy));
    for (int c = 0; c < 6; ++c) EXPECT_EQ(v.value[c], t.value(ix, iy, c)) << ix << ", " << iy;
  }
  // Off the texels: a valid LTC.
  const PointValue v = Ltc().Evaluate(s, 0.37, 0.55);
  EXPECT_GT(v.value[0] * v.value[3] - v.value[2] * v.value[1], 0.0);
}

// The stated lobe error (the level-1 rule, for the matrix as stored)
// against the level-2 rule, and within what the fit reaches on this 12 x 12
// grid (measured: lobe error mean 0.099, max 0.505 at a grazing view;
// leakage max 0.0174).
TEST(LtcGgx, StatedLobeErrorAgreesWithAFinerRule) {
  const Table &t = Small();
  ASSERT_EQ(t.fitMapNames, (std::vector<std::string>{"lobeError", "polygonError", "leakage"}));
  double worstDifference = 0.0, worstLobe = 0.0, worstLeak = 0.0;
  for (int iy = 0; iy < t.height(); iy += 2)
    for (int ix = 0; ix < t.width(); ix += 3) {
      const size_t texel = static_cast<size_t>(iy) * t.width() + ix;
      const double r = t.y.TexelCenter(iy), mu = t.x.TexelCenter(ix);
      const LtcLobe lobe = MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
      const auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
      const LtcMatrix stored{f(t.value(ix, iy, 0)), f(t.value(ix, iy, 1)), f(t.value(ix, iy, 2)),
                             f(t.value(ix, iy, 3))};
      const double m = f(t.value(ix, iy, 4));
      const double fine = LtcLobeError(lobe, mu, m, m, stored, 2);
      worstDifference = std::max(worstDifference, std::fabs(fine - t.fitMaps[texel * 3]));
      worstLobe = std::max(worstLobe, t.fitMaps[texel * 3]);
      worstLeak = std::max(worstLeak, t.fitMaps[texel * 3 + 2]);
      EXPECT_DOUBLE_EQ(t.fitMaps[texel * 3 + 2], LtcLeakage(stored));
    }
  EXPECT_LT(worstDifference, 2e-3);
  EXPECT_LT(worstLobe, 0.55);
  EXPECT_LT(worstLeak, 0.02);
  double mean = 0.0;
  for (size_t texel = 0; texel < t.texelCount(); ++texel) {
    mean += t.fitMaps[texel * 3] / static_cast<double>(t.texelCount());
    EXPECT_LT(t.fitMaps[texel * 3], 0.55);
    EXPECT_LT(t.fitMaps[texel * 3 + 2], 0.02);
  }
  EXPECT_LT(mean, 0.11);
  const std::string *summary = t.FindMetadata("fitErrors");
  ASSERT_NE(summary, nullptr);
  EXPECT_NE(summary->find("lobeError mean"), std::string::npos);
}

// bake --tables ltc_ggx --format exr,bin,header: every file holds the six
// channels in order, T.fit.exr the three maps; image formats are refused.
TEST(LtcGgx, BakesExrBinHeaderAndReadsThemBack) {
  const fs::path dir = fs::temp_directory_path() / "lutbake_ltc_ggx_test";
  fs::remove_all(dir);
  const test::CommandResult run = test::Lutbake(
      "bake --tables ltc_ggx --size 8 --format exr,bin,header -q --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
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
  const test::CommandResult png =
      test::Lutbake("bake --tables ltc_ggx --size 8 --format png16 --out " + dir.string());
  EXPECT_NE(png.status, 0);
  EXPECT_NE(png.output.find("holds at most 2 channels"), std::string::npos) << png.output;
  fs::remove_all(dir);
}

// eval --json prints the six channels fitted at the point, and the lobe
// error, polygon error and leakage beside them, as the definition computes
// them.
TEST(LtcGgx, EvalJsonPrintsSixChannelsAndTheLobeError) {
  const test::CommandResult run =
      test::Lutbake("eval --table ltc_ggx --mu 0.4 --roughness 0.35 --json", true);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json line = nlohmann::json::parse(run.output);
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
  const test::CommandResult text = test::Lutbake("eval --table ltc_ggx --mu 0.4 --roughness 0.35");
  EXPECT_NE(text.output.find("lobeError"), std::string::npos) << text.output;
}

const CheckResult *Find(const CheckReport &report, const std::string &check) {
  for (const CheckResult &r : report.results)
    if (r.subject == "ltc_ggx" && r.check == check) return &r;
  return nullptr;
}

// check on a bake of ltc_ggx and E: passes; a texel with a negative
// determinant, or swapped for the mirrored branch (the lobe reflected to the
// view's side), or a changed magnitude, fails the check that guards it.
TEST(LtcGgx, CheckPassesAndCatchesBrokenTexels) {
  const fs::path dir = fs::temp_directory_path() / "lutbake_ltc_ggx_check";
  fs::remove_all(dir);
  const test::CommandResult run =
      test::Lutbake("bake --tables ltc_ggx,E --size 10 --format exr -q --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const CheckReport good = CheckBakedSet(dir.string());
  for (const CheckResult &r : good.results)
    EXPECT_NE(r.status, CheckStatus::kFail) << r.subject << " " << r.check << ": " << r.detail;
  for (const char *check : {"fit usable", "fit errors", "no jumps", "texels"})
    EXPECT_NE(Find(good, check), nullptr) << check;
  bool channel = false;
  for (const CheckResult &r : good.results) channel = channel || r.subject == "ltc_ggx+E";
  EXPECT_TRUE(channel);

  // The bake again (the same values, bit for bit), changed and written over
  // the EXR with its bounds.
  const Table original = BakeTable(Ltc(), Sized(10));
  const auto rewrite = [&](const std::function<void(Table *)> &change) {
    Table t = original;
    change(&t);
    MakeExrWriter()->Write(t, (dir / "ltc_ggx.exr").string(), {});
    return CheckBakedSet(dir.string());
  };
  // Unchanged, it still passes (the rewrite itself breaks nothing).
  const CheckReport same = rewrite([](Table *) {});
  EXPECT_EQ(Find(same, "fit errors")->status, CheckStatus::kPass)
      << Find(same, "fit errors")->detail;
  EXPECT_EQ(Find(same, "texels")->status, CheckStatus::kPass);
  // The mirrored branch at texel (4, 6): m20 and m02 change sign.
  const CheckReport mirrored = rewrite([](Table *t) {
    t->values[t->index(4, 6, 1)] = -t->values[t->index(4, 6, 1)];
    t->values[t->index(4, 6, 2)] = -t->values[t->index(4, 6, 2)];
  });
  ASSERT_NE(Find(mirrored, "no jumps"), nullptr);
  EXPECT_EQ(Find(mirrored, "no jumps")->status, CheckStatus::kFail);
  EXPECT_EQ(Find(mirrored, "fit errors")->status, CheckStatus::kFail);
  const CheckReport negative =
      rewrite([](Table *t) { t->values[t->index(2, 3, 0)] = -t->values[t->index(2, 3, 0)]; });
  EXPECT_EQ(Find(negative, "fit usable")->status, CheckStatus::kFail);
  const CheckReport magnitude = rewrite([](Table *t) { t->values[t->index(5, 5, 4)] += 1e-4; });
  EXPECT_EQ(Find(magnitude, "texels")->status, CheckStatus::kFail);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
