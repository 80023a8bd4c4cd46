// Table ltc_oren_nayar (issue 28): the LTC of the qualitative Oren-Nayar
// lobe. magnitude is oren_nayar_E bit for bit, fresnel within its bound of
// the nested adaptive Gauss-Kronrod reference; det M^-1 > 0, finite, bit-
// identical for 1 and 2 threads, eval at a texel centre is the bake's
// texel, the stated lobe error against the next level of its rule, check
// passes and catches a texel pushed off its branch and a changed magnitude.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>

#include "lutbake/formats/writer.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"
#include "lutbake/validation/check.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const char *kName = "ltc_oren_nayar";
const char *kAlbedo = "oren_nayar_E";
LtcLobe LobeAt(double y) { return OrenNayarLtcLobe(OrenNayarVariant::kQualitative, y); }

const TableDefinition &Ltc() { return TableNamed(kName); }

BakeSettings Sized(int size) {
  BakeSettings s;
  s.size = size;
  s.commandLine = "lutbake bake --test";
  return s;
}

const Table &Small() {
  static const Table table = BakeTable(Ltc(), Sized(10));
  return table;
}

LtcMatrix StoredMatrix(const Table &t, int ix, int iy) {
  const auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  return {f(t.value(ix, iy, 0)), f(t.value(ix, iy, 1)), f(t.value(ix, iy, 2)),
          f(t.value(ix, iy, 3))};
}

// magnitude is the albedo table's value and bound bit for bit; fresnel
// within its stated bound of the adaptive reference (tolerance 1e-11) and
// within 1e-9 of it; det > 0 as stored; everything finite.
TEST(LtcOrenNayar, MagnitudeIsTheAlbedoTableAndFresnelWithinItsBound) {
  EXPECT_EQ(Ltc().Channels(), 6);
  EXPECT_EQ(Ltc().DefaultSize(), 64);
  const Table &t = Small();
  const Table e = BakeTable(TableNamed(kAlbedo), Sized(10));
  for (double v : t.values) EXPECT_TRUE(std::isfinite(v));
  for (double v : t.fitMaps) EXPECT_TRUE(std::isfinite(v));
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      EXPECT_EQ(t.value(ix, iy, 4), e.value(ix, iy, 0));
      EXPECT_EQ(t.errors[t.index(ix, iy, 4)], e.errors[e.index(ix, iy, 0)]);
      const double mu = t.x.TexelCenter(ix), y = t.y.TexelCenter(iy);
      const LtcMomentsReference r = IntegrateLobeMomentsAdaptive(LobeAt(y), mu, 1e-11);
      EXPECT_NEAR(r.magnitude, t.value(ix, iy, 4), 1e-9 + r.magnitudeBound);
      EXPECT_LE(std::fabs(t.value(ix, iy, 5) - r.fresnel),
                t.errors[t.index(ix, iy, 5)] + r.fresnelBound);
      EXPECT_LT(std::fabs(t.value(ix, iy, 5) - r.fresnel), 1e-9);
      EXPECT_GT(StoredMatrix(t, ix, iy).Determinant(), 0.0);
    }
}

TEST(LtcOrenNayar, BitIdenticalForOneAndTwoThreads) {
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

TEST(LtcOrenNayar, EvalAtTexelCentreIsTheBakesTexel) {
  const Table &t = Small();
  for (const auto &[ix, iy] : std::vector<std::pair<int, int>>{{0, 0}, {9, 9}, {3, 7}}) {
    const PointValue v = Ltc().Evaluate(Sized(10), t.x.TexelCenter(ix), t.y.TexelCenter(iy));
    for (int c = 0; c < 6; ++c) EXPECT_EQ(v.value[c], t.value(ix, iy, c)) << ix << ", " << iy;
  }
}

// The stated lobe error (level 1 of the light-direction rule, the matrix as
// stored) against level 2, and the fit's quality (measured at 64 x 64: lobe
// error mean 0.0325, max 0.084; leakage max 0.017).
TEST(LtcOrenNayar, StatedLobeErrorAgreesWithTheNextLevel) {
  const Table &t = Small();
  double worstDifference = 0.0, mean = 0.0;
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      const size_t texel = static_cast<size_t>(iy) * t.width() + ix;
      const double m = static_cast<float>(t.value(ix, iy, 4));
      const double fine = LtcLobeError(LobeAt(t.y.TexelCenter(iy)), t.x.TexelCenter(ix), m, m,
                                       StoredMatrix(t, ix, iy), 2);
      worstDifference = std::max(worstDifference, std::fabs(fine - t.fitMaps[texel * 3]));
      mean += t.fitMaps[texel * 3] / static_cast<double>(t.texelCount());
      EXPECT_LT(t.fitMaps[texel * 3], 0.1);
      EXPECT_LT(t.fitMaps[texel * 3 + 2], 0.025);
    }
  EXPECT_LT(worstDifference, 4e-4);  // measured at 64 x 64: 3.6e-4, at grazing views
  EXPECT_LT(mean, 0.045);
}

const CheckResult *Find(const CheckReport &report, const std::string &check) {
  for (const CheckResult &r : report.results)
    if (r.subject == kName && r.check == check) return &r;
  return nullptr;
}

TEST(LtcOrenNayar, CheckPassesAndCatchesBrokenTexels) {
  const fs::path dir = fs::temp_directory_path() / (std::string("lutbake_check_") + kName);
  fs::remove_all(dir);
  const test::CommandResult run =
      test::Lutbake("bake --tables " + std::string(kName) + "," + kAlbedo +
                    " --size 10 --format exr -q --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const CheckReport good = CheckBakedSet(dir.string());
  for (const CheckResult &r : good.results)
    EXPECT_NE(r.status, CheckStatus::kFail) << r.subject << " " << r.check << ": " << r.detail;
  for (const char *check : {"fit usable", "fit errors", "no jumps", "texels"})
    EXPECT_NE(Find(good, check), nullptr) << check;
  bool channel = false;
  for (const CheckResult &r : good.results)
    channel = channel ||
              (r.subject == std::string(kName) + "+" + kAlbedo && r.status == CheckStatus::kPass);
  EXPECT_TRUE(channel);
  const Table original = BakeTable(Ltc(), Sized(10));
  const auto rewrite = [&](const std::function<void(Table *)> &change) {
    Table t = original;
    change(&t);
    MakeExrWriter()->Write(t, (dir / (std::string(kName) + ".exr")).string(), {});
    return CheckBakedSet(dir.string());
  };
  // A texel pushed off its branch (m20 and m02 mirrored and shifted by 0.3:
  // near the normal view both are small, and a bare mirror moves little).
  const CheckReport mirrored = rewrite([](Table *t) {
    t->values[t->index(4, 6, 1)] = -t->values[t->index(4, 6, 1)] - 0.3;
    t->values[t->index(4, 6, 2)] = -t->values[t->index(4, 6, 2)] + 0.3;
  });
  EXPECT_EQ(Find(mirrored, "no jumps")->status, CheckStatus::kFail);
  EXPECT_EQ(Find(mirrored, "fit errors")->status, CheckStatus::kFail);
  const CheckReport magnitude = rewrite([](Table *t) { t->values[t->index(5, 5, 4)] += 1e-4; });
  EXPECT_EQ(Find(magnitude, "texels")->status, CheckStatus::kFail);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
