// The checks every LTC table passes (ltc_ggx_test.cpp, ltc_sheen_test.cpp,
// ltc_burley_test.cpp, ltc_oren_nayar_test.cpp call them with their table):
// bit-identical for 1 and 2 threads, eval at a texel centre is the bake's
// texel, the stated lobe error against the next level of its rule, check
// passes and catches a texel pushed off its branch, a negative determinant
// and a changed magnitude. For the diffuse lobes also: magnitude is the
// albedo table's value and bound bit for bit, fresnel within its bound of
// the nested adaptive Gauss-Kronrod reference, det M^-1 > 0, finite (the
// microfacet and sheen tables check theirs against their own references).
#pragma once

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"
#include "lutbake/validation/check.h"

namespace lutbake::test {

struct LtcLobeTable {
  const char *name;    // "ltc_burley"
  const char *albedo;  // its magnitude's table: "burley_E"
  std::function<LtcLobe(double y)> lobeAt;
  // What the fit reaches on the grid the test bakes (each measured at 64 x
  // 64 in the test file): the lobe error and leakage at every texel, the
  // mean lobe error.
  double lobeErrorMax, leakageMax, lobeErrorMean;
  // The stated lobe error and the next level's at most this apart, compared
  // at every strideX-th texel of every strideY-th row (the rest for cost).
  double levelDifferenceMax = 4e-4;
  int strideX = 1, strideY = 1;
  // The broken texel of the check: m20 and m02 negated (the mirrored
  // branch), then moved by -mirrorShift and +mirrorShift (near the normal
  // view both are small, and a bare mirror moves a diffuse lobe little).
  double mirrorShift = 0.3;
};

inline BakeSettings LtcSized(int size) {
  BakeSettings s;
  s.size = size;
  s.commandLine = "lutbake bake --test";
  return s;
}

inline LtcMatrix StoredLtcMatrix(const Table &t, int ix, int iy) {
  const auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  return {f(t.value(ix, iy, 0)), f(t.value(ix, iy, 1)), f(t.value(ix, iy, 2)),
          f(t.value(ix, iy, 3))};
}

// magnitude is the albedo table's value and bound bit for bit; fresnel
// within its stated bound of the adaptive reference (tolerance 1e-11) and
// within 1e-9 of it; det > 0 as stored; everything finite.
inline void ExpectMagnitudeAndFresnel(const LtcLobeTable &c, const Table &t) {
  const TableDefinition &ltc = TableNamed(c.name);
  EXPECT_EQ(ltc.Channels(), 6);
  EXPECT_EQ(ltc.DefaultSize(), 64);
  const Table e = BakeTable(TableNamed(c.albedo), LtcSized(t.width()));
  for (double v : t.values) EXPECT_TRUE(std::isfinite(v));
  for (double v : t.fitMaps) EXPECT_TRUE(std::isfinite(v));
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      EXPECT_EQ(t.value(ix, iy, 4), e.value(ix, iy, 0));
      EXPECT_EQ(t.errors[t.index(ix, iy, 4)], e.errors[e.index(ix, iy, 0)]);
      const double mu = t.x.TexelCenter(ix), y = t.y.TexelCenter(iy);
      const LtcMomentsReference r = IntegrateLobeMomentsAdaptive(c.lobeAt(y), mu, 1e-11);
      EXPECT_NEAR(r.magnitude, t.value(ix, iy, 4), 1e-9 + r.magnitudeBound);
      EXPECT_LE(std::fabs(t.value(ix, iy, 5) - r.fresnel),
                t.errors[t.index(ix, iy, 5)] + r.fresnelBound);
      EXPECT_LT(std::fabs(t.value(ix, iy, 5) - r.fresnel), 1e-9);
      EXPECT_GT(StoredLtcMatrix(t, ix, iy).Determinant(), 0.0);
    }
}

inline void ExpectBitIdenticalForOneAndTwoThreads(const LtcLobeTable &c, int size = 8) {
  Table one, two;
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 1);
    one = BakeTable(TableNamed(c.name), LtcSized(size));
  }
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 2);
    two = BakeTable(TableNamed(c.name), LtcSized(size));
  }
  ASSERT_EQ(one.values.size(), two.values.size());
  EXPECT_EQ(0, std::memcmp(one.values.data(), two.values.data(), one.values.size() * 8));
  EXPECT_EQ(0, std::memcmp(one.errors.data(), two.errors.data(), one.errors.size() * 8));
  ASSERT_EQ(one.fitMaps.size(), two.fitMaps.size());
  EXPECT_EQ(0, std::memcmp(one.fitMaps.data(), two.fitMaps.data(), one.fitMaps.size() * 8));
}

inline void ExpectEvalAtTexelCentreIsTheBakesTexel(
    const LtcLobeTable &c, const Table &t,
    const std::vector<std::pair<int, int>> &texels = {{0, 0}, {9, 9}, {3, 7}}) {
  for (const auto &[ix, iy] : texels) {
    const PointValue v =
        TableNamed(c.name).Evaluate(LtcSized(t.width()), t.x.TexelCenter(ix), t.y.TexelCenter(iy));
    for (int ch = 0; ch < 6; ++ch) EXPECT_EQ(v.value[ch], t.value(ix, iy, ch)) << ix << ", " << iy;
  }
}

// The stated lobe error (level 1 of the table's rule, the matrix as stored)
// against level 2 (diffuse lobes, measured at 64 x 64: 3.6e-4 at worst, at
// grazing views), the leakage map against the stored matrix's, and the
// fit's quality.
inline void ExpectStatedLobeErrorAgreesWithTheNextLevel(const LtcLobeTable &c, const Table &t) {
  ASSERT_EQ(t.fitMapNames, (std::vector<std::string>{"lobeError", "polygonError", "leakage"}));
  double worstDifference = 0.0, mean = 0.0;
  for (int iy = 0; iy < t.height(); ++iy)
    for (int ix = 0; ix < t.width(); ++ix) {
      const size_t texel = static_cast<size_t>(iy) * t.width() + ix;
      mean += t.fitMaps[texel * 3] / static_cast<double>(t.texelCount());
      EXPECT_LT(t.fitMaps[texel * 3], c.lobeErrorMax);
      EXPECT_LT(t.fitMaps[texel * 3 + 2], c.leakageMax);
      if (iy % c.strideY != 0 || ix % c.strideX != 0) continue;
      const double m = static_cast<float>(t.value(ix, iy, 4));
      const double fine = LtcLobeError(c.lobeAt(t.y.TexelCenter(iy)), t.x.TexelCenter(ix), m, m,
                                       StoredLtcMatrix(t, ix, iy), 2);
      worstDifference = std::max(worstDifference, std::fabs(fine - t.fitMaps[texel * 3]));
      EXPECT_DOUBLE_EQ(t.fitMaps[texel * 3 + 2], LtcLeakage(StoredLtcMatrix(t, ix, iy)));
    }
  EXPECT_LT(worstDifference, c.levelDifferenceMax);
  EXPECT_LT(mean, c.lobeErrorMean);
}

inline const CheckResult *FindLtcCheck(const CheckReport &report, const std::string &subject,
                                       const std::string &check) {
  for (const CheckResult &r : report.results)
    if (r.subject == subject && r.check == check) return &r;
  return nullptr;
}

// A bake of the table and its albedo table (lutbake::Bake, as `bake --tables
// T,E --size 10 --format exr` makes it) passes check, and still does when
// rewritten unchanged; a texel pushed off its branch, a negative
// determinant and a changed magnitude each fail it by name.
inline void ExpectCheckPassesAndCatchesBrokenTexels(const LtcLobeTable &c) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / (std::string("lutbake_check_") + c.name);
  fs::remove_all(dir);
  BakeRequest request;
  request.outputDirectory = dir.string();
  request.tables = std::vector<std::string>{c.name, c.albedo};
  request.size = 10;
  request.formats = std::vector<std::string>{"exr"};
  Bake(request);
  const CheckReport good = CheckBakedSet(dir.string());
  for (const CheckResult &r : good.results)
    EXPECT_NE(r.status, CheckStatus::kFail) << r.subject << " " << r.check << ": " << r.detail;
  for (const char *check : {"fit usable", "fit errors", "no jumps", "texels"})
    EXPECT_NE(FindLtcCheck(good, c.name, check), nullptr) << check;
  bool channel = false;
  for (const CheckResult &r : good.results)
    channel = channel ||
              (r.subject == std::string(c.name) + "+" + c.albedo && r.status == CheckStatus::kPass);
  EXPECT_TRUE(channel);
  const Table original = BakeTable(TableNamed(c.name), LtcSized(10));
  const auto rewrite = [&](const std::function<void(Table *)> &change) {
    Table t = original;
    change(&t);
    MakeExrWriter()->Write(t, (dir / (std::string(c.name) + ".exr")).string(), {});
    return CheckBakedSet(dir.string());
  };
  // Unchanged, it still passes (the rewrite itself breaks nothing).
  const CheckReport same = rewrite([](Table *) {});
  ASSERT_NE(FindLtcCheck(same, c.name, "fit errors"), nullptr);
  EXPECT_EQ(FindLtcCheck(same, c.name, "fit errors")->status, CheckStatus::kPass)
      << FindLtcCheck(same, c.name, "fit errors")->detail;
  EXPECT_EQ(FindLtcCheck(same, c.name, "texels")->status, CheckStatus::kPass);
  // A texel pushed off its branch.
  const CheckReport mirrored = rewrite([&c](Table *t) {
    t->values[t->index(4, 6, 1)] = -t->values[t->index(4, 6, 1)] - c.mirrorShift;
    t->values[t->index(4, 6, 2)] = -t->values[t->index(4, 6, 2)] + c.mirrorShift;
  });
  ASSERT_NE(FindLtcCheck(mirrored, c.name, "no jumps"), nullptr);
  EXPECT_EQ(FindLtcCheck(mirrored, c.name, "no jumps")->status, CheckStatus::kFail);
  EXPECT_EQ(FindLtcCheck(mirrored, c.name, "fit errors")->status, CheckStatus::kFail);
  const CheckReport negative =
      rewrite([](Table *t) { t->values[t->index(2, 3, 0)] = -t->values[t->index(2, 3, 0)]; });
  EXPECT_EQ(FindLtcCheck(negative, c.name, "fit usable")->status, CheckStatus::kFail);
  const CheckReport magnitude = rewrite([](Table *t) { t->values[t->index(5, 5, 4)] += 1e-4; });
  EXPECT_EQ(FindLtcCheck(magnitude, c.name, "texels")->status, CheckStatus::kFail);
  fs::remove_all(dir);
}

}  // namespace lutbake::test
