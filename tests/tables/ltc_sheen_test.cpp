// Table ltc_sheen (issue 28): the Charlie sheen lobe's LTC. magnitude is
// sheen_E bit for bit under every model option, fresnel within its bound of
// the adaptive Schlick-weighted reference; det M^-1 > 0, finite, bit-
// identical for 1 and 2 threads, eval at a texel centre is the bake's texel,
// the stated lobe error against the next level of its rule, check passes
// and catches a mirrored texel, a negative determinant and a changed
// magnitude (those shared with every LTC table: ltc_lobe_table_checks.h).
// Calls the library, not the executable.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "ltc_lobe_table_checks.h"
#include "lutbake/api/eval.h"
#include "lutbake/integrators/sheen_quadrature.h"

namespace lutbake {
namespace {

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

// Charlie, alpha = r (the defaults the shared checks bake with).
const test::LtcLobeTable kTable{
    "ltc_sheen", "sheen_E", [](double r) { return SheenLtcLobe(SheenVisibility::kCharlie, r); },
    0.45,        0.1,       0.2,
    2e-3,        1,         1,
    0.0};

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
  test::ExpectBitIdenticalForOneAndTwoThreads(kTable);
}

TEST(LtcSheen, EvalAtTexelCentreIsTheBakesTexel) {
  test::ExpectEvalAtTexelCentreIsTheBakesTexel(kTable, Small());
}

// The stated lobe error (level 1 of the half-vector rule, the matrix as
// stored) against level 2 (64 x 64: 4.8e-3 (alpha = r), 5.2e-3 (r^2), at r =
// 1/128); the fit's quality on this grid (measured at 64 x 64, Charlie,
// alpha = r: lobe error mean 0.162, max 0.378; leakage max 0.084).
TEST(LtcSheen, StatedLobeErrorAgreesWithTheNextLevel) {
  test::ExpectStatedLobeErrorAgreesWithTheNextLevel(kTable, Small());
}

// check on a bake of ltc_sheen and sheen_E: passes (magnitude = sheen_E
// among its checks); a texel swapped for its mirrored branch fails "no
// jumps", a negative determinant "fit usable", a changed magnitude "texels".
TEST(LtcSheen, CheckPassesAndCatchesBrokenTexels) {
  test::ExpectCheckPassesAndCatchesBrokenTexels(kTable);
}

// eval --json with the model options (lutbake::Evaluate) prints the six
// channels.
TEST(LtcSheen, EvalJsonWithOptions) {
  EvalRequest request;
  request.table = "ltc_sheen";
  request.coordinates = {{"mu", {0.4}}, {"roughness", {0.35}}};
  request.sheenVisibility = SheenVisibility::kAshikhmin;
  request.sheenAlpha = SheenAlpha::kSquared;
  const EvalResult result = Evaluate(request);
  ASSERT_EQ(result.points.size(), 1u);
  const nlohmann::json line = nlohmann::json::parse(result.JsonLine(0));
  ASSERT_EQ(line["value"].size(), 6u);
  const BakeSettings s = Sized(64, SheenVisibility::kAshikhmin, SheenAlpha::kSquared);
  const PointValue v = Ltc().Evaluate(s, 0.4, 0.35);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(line["value"][c].get<double>(), v.value[c]);
  EXPECT_EQ(line["lobeError"].get<double>(), Ltc().PointFitErrors(s, 0.4, 0.35, v)[0].second);
  EXPECT_GT(v.value[0] * v.value[3] - v.value[2] * v.value[1], 0.0);
}

}  // namespace
}  // namespace lutbake
