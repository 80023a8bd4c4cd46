// Table ltc_sheen (issue 28): the Charlie sheen lobe's LTC. magnitude is
// sheen_E bit for bit under every model option, fresnel within its bound of
// the adaptive Schlick-weighted reference; det M^-1 > 0, finite, bit-
// identical for 1 and 2 threads, eval at a texel centre is the bake's texel,
// the stated lobe error against the next level of its rule, check passes
// and catches a mirrored texel and a changed magnitude.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"
#include "lutbake/validation/check.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const TableDefinition &Ltc() { return TableNamed("ltc_sheen"); }

BakeSettings Sized(int size, SheenVisibility v = SheenVisibility::kCharlie,
                   SheenAlpha a = SheenAlpha::kLinear) {
  BakeSettings s;
  s.size = size;
  s.sheenVisibility = v;
  s.sheenAlpha = a;
  s.commandLine = "lutbake bake --test";
  return s;
}

const Table &Small() {
  static const Table table = BakeTable(Ltc(), Sized(10));
  return table;
}

TEST(LtcSheen, ChannelsAxesAndOptions) {
  EXPECT_EQ(Ltc().ChannelNames(),
            (std::vector<std::string>{"m00", "m20", "m02", "m22", "magnitude", "fresnel"}));
  EXPECT_EQ(Ltc().ModelOptions(), (std::vector<std::string>{"sheen-visibility", "sheen-alpha"}));
  Axis x, y;
  DefaultAxes(Ltc(), BakeSettings{}, &x, &y);
  EXPECT_EQ(x.name, "mu");
  EXPECT_EQ(y.name, "sheenRoughness");
  EXPECT_EQ(x.count, 64);
  EXPECT_EQ(y.count, 64);
  EXPECT_EQ(Ltc().Role(), PlanRole::kSheenAreaLights);
  // The Charlie visibility's albedo is infinite at mu = 0: refused.
  EXPECT_THROW(Ltc().Evaluate(BakeSettings{}, 0.0, 0.5), std::domain_error);
}

// Under both visibilities and both mappings: magnitude is sheen_E's value
// bit for bit (and its bound), fresnel within its stated bound of the
// adaptive reference (tolerance 1e-11) and within 1e-5 of it; every matrix
// has det > 0 as stored in float32; everything finite.
TEST(LtcSheen, MagnitudeIsSheenEAndFresnelWithinItsBound) {
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin})
    for (SheenAlpha a : {SheenAlpha::kLinear, SheenAlpha::kSquared}) {
      const BakeSettings s = Sized(6, v, a);
      const Table t = BakeTable(Ltc(), s);
      const Table e = BakeTable(TableNamed("sheen_E"), s);
      for (double value : t.values) EXPECT_TRUE(std::isfinite(value));
      for (double value : t.fitMaps) EXPECT_TRUE(std::isfinite(value));
      for (int iy = 0; iy < t.height(); ++iy)
        for (int ix = 0; ix < t.width(); ++ix) {
          EXPECT_EQ(t.value(ix, iy, 4), e.value(ix, iy, 0));
          EXPECT_EQ(t.errors[t.index(ix, iy, 4)], e.errors[e.index(ix, iy, 0)]);
          const double mu = t.x.TexelCenter(ix), r = t.y.TexelCenter(iy);
          const double alpha = a == SheenAlpha::kSquared ? r * r : r;
          const SheenIntegral f = IntegrateSheenSchlickWeightedAdaptive(v, alpha, mu, 1e-11);
          EXPECT_LE(std::fabs(t.value(ix, iy, 5) - f.value), t.errors[t.index(ix, iy, 5)] + f.bound)
              << ix << " " << iy;
          EXPECT_LT(std::fabs(t.value(ix, iy, 5) - f.value), 1e-5);
          const auto g = [](double x) { return static_cast<double>(static_cast<float>(x)); };
          EXPECT_GT(g(t.value(ix, iy, 0)) * g(t.value(ix, iy, 3)) -
                        g(t.value(ix, iy, 2)) * g(t.value(ix, iy, 1)),
                    0.0);
        }
    }
}

TEST(LtcSheen, BitIdenticalForOneAndTwoThreads) {
  Table one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = BakeTable(Ltc(), Sized(8));
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = BakeTable(Ltc(), Sized(8));
  }
  ASSERT_EQ(one.values.size(), two.values.size());
  EXPECT_EQ(0, std::memcmp(one.values.data(), two.values.data(), one.values.size() * 8));
  EXPECT_EQ(0, std::memcmp(one.errors.data(), two.errors.data(), one.errors.size() * 8));
  ASSERT_EQ(one.fitMaps.size(), two.fitMaps.size());
  EXPECT_EQ(0, std::memcmp(one.fitMaps.data(), two.fitMaps.data(), one.fitMaps.size() * 8));
}

TEST(LtcSheen, EvalAtTexelCentreIsTheBakesTexel) {
  const Table &t = Small();
  const BakeSettings s = Sized(10);
  for (const auto &[ix, iy] : std::vector<std::pair<int, int>>{{0, 0}, {9, 9}, {3, 7}}) {
    const PointValue v = Ltc().Evaluate(s, t.x.TexelCenter(ix), t.y.TexelCenter(iy));
    for (int c = 0; c < 6; ++c) EXPECT_EQ(v.value[c], t.value(ix, iy, c)) << ix << ", " << iy;
  }
}

// The stated lobe error (level 1 of the half-vector rule, the matrix as
// stored) against level 2; the fit's quality on this grid (measured at 64
// x 64, Charlie, alpha = r: lobe error mean 0.162, max 0.378; leakage max
// 0.084).
TEST(LtcSheen, StatedLobeErrorAgreesWithTheNextLevel) {
  const Table &t = Small();
  ASSERT_EQ(t.fitMapNames, (std::vector<std::string>{"lobeError", "polygonError", "leakage"}));
  double worstDifference = 0.0, mean = 0.0;
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      const size_t texel = static_cast<size_t>(iy) * t.width() + ix;
      const double r = t.y.TexelCenter(iy), mu = t.x.TexelCenter(ix);
      const auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
      const LtcMatrix stored{f(t.value(ix, iy, 0)), f(t.value(ix, iy, 1)), f(t.value(ix, iy, 2)),
                             f(t.value(ix, iy, 3))};
      const double m = f(t.value(ix, iy, 4));
      const double fine =
          LtcLobeError(SheenLtcLobe(SheenVisibility::kCharlie, r), mu, m, m, stored, 2);
      worstDifference = std::max(worstDifference, std::fabs(fine - t.fitMaps[texel * 3]));
      mean += t.fitMaps[texel * 3] / static_cast<double>(t.texelCount());
      EXPECT_LT(t.fitMaps[texel * 3], 0.45);
      EXPECT_LT(t.fitMaps[texel * 3 + 2], 0.1);
      EXPECT_DOUBLE_EQ(t.fitMaps[texel * 3 + 2], LtcLeakage(stored));
    }
  EXPECT_LT(worstDifference, 2e-3);  // 64 x 64: 4.8e-3 (alpha = r), 5.2e-3 (r^2), at r = 1/128
  EXPECT_LT(mean, 0.2);
}

const CheckResult *Find(const CheckReport &report, const std::string &check) {
  for (const CheckResult &r : report.results)
    if (r.subject == "ltc_sheen" && r.check == check) return &r;
  return nullptr;
}

// check on a bake of ltc_sheen and sheen_E: passes (magnitude = sheen_E
// among its checks); a texel swapped for its mirrored branch fails "no
// jumps", a changed magnitude fails "texels".
TEST(LtcSheen, CheckPassesAndCatchesBrokenTexels) {
  const fs::path dir = fs::temp_directory_path() / "lutbake_ltc_sheen_check";
  fs::remove_all(dir);
  const test::CommandResult run = test::Lutbake(
      "bake --tables ltc_sheen,sheen_E --size 10 --format exr -q --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const CheckReport good = CheckBakedSet(dir.string());
  for (const CheckResult &r : good.results)
    EXPECT_NE(r.status, CheckStatus::kFail) << r.subject << " " << r.check << ": " << r.detail;
  for (const char *check : {"fit usable", "fit errors", "no jumps", "texels"})
    EXPECT_NE(Find(good, check), nullptr) << check;
  bool channel = false;
  for (const CheckResult &r : good.results)
    channel = channel || (r.subject == "ltc_sheen+sheen_E" && r.status == CheckStatus::kPass);
  EXPECT_TRUE(channel);

  const Table original = BakeTable(Ltc(), Sized(10));
  const auto rewrite = [&](const std::function<void(Table *)> &change) {
    Table t = original;
    change(&t);
    MakeExrWriter()->Write(t, (dir / "ltc_sheen.exr").string(), {});
    return CheckBakedSet(dir.string());
  };
  const CheckReport mirrored = rewrite([](Table *t) {
    t->values[t->index(4, 6, 1)] = -t->values[t->index(4, 6, 1)];
    t->values[t->index(4, 6, 2)] = -t->values[t->index(4, 6, 2)];
  });
  ASSERT_NE(Find(mirrored, "no jumps"), nullptr);
  EXPECT_EQ(Find(mirrored, "no jumps")->status, CheckStatus::kFail);
  EXPECT_EQ(Find(mirrored, "fit errors")->status, CheckStatus::kFail);
  const CheckReport magnitude = rewrite([](Table *t) { t->values[t->index(5, 5, 4)] += 1e-4; });
  EXPECT_EQ(Find(magnitude, "texels")->status, CheckStatus::kFail);
  fs::remove_all(dir);
}

// eval --json with the model options prints the six channels.
TEST(LtcSheen, EvalJsonWithOptions) {
  const test::CommandResult run = test::Lutbake(
      "eval --table ltc_sheen --mu 0.4 --roughness 0.35 --sheen-visibility ashikhmin "
      "--sheen-alpha squared --json",
      true);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json line = nlohmann::json::parse(run.output);
  ASSERT_EQ(line["value"].size(), 6u);
  const BakeSettings s = Sized(64, SheenVisibility::kAshikhmin, SheenAlpha::kSquared);
  const PointValue v = Ltc().Evaluate(s, 0.4, 0.35);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(line["value"][c].get<double>(), v.value[c]);
  EXPECT_EQ(line["lobeError"].get<double>(), Ltc().PointFitErrors(s, 0.4, 0.35, v)[0].second);
  EXPECT_GT(v.value[0] * v.value[3] - v.value[2] * v.value[1], 0.0);
}

}  // namespace
}  // namespace lutbake
