// The default bake (`lutbake bake --out DIR`, no other option) is float32-
// exact: every texel of E, Eavg and dfg within 1e-7 of the truth as stored,
// and every stated bound a true bound of the stored value (float32 and half),
// on small tables and on the stiff corner of the full-size ones; the same
// bits for 1, 2 and 16 threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>

#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/storage.h"

namespace lutbake {
namespace {

// Texels (index into the table) to compare, and the reference there: the
// adaptive quadrature at 1e-12 (E_avg at 1e-11), an independent method.
struct Compared {
  std::vector<size_t> texels;
  std::vector<double> truth;       // per value (texel x channel)
  std::vector<double> truthError;  // the reference's own estimate
};

Compared Reference(const Table &t, const std::vector<size_t> &texels) {
  Compared c;
  c.texels = texels;
  c.truth.assign(texels.size() * t.channels, 0.0);
  c.truthError.assign(texels.size() * t.channels, 0.0);
  tbb::parallel_for(size_t(0), texels.size(), [&](size_t k) {
    const int x = static_cast<int>(texels[k] % t.width()),
              y = static_cast<int>(texels[k] / t.width());
    if (t.definition == &TableNamed("Eavg")) {
      const double r = t.x.TexelCenter(x);
      const ReferenceAverage a =
          IntegrateReferenceAlbedoAverage(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, 1e-11);
      c.truth[k] = a.value;
      c.truthError[k] = 16 * a.error + 1e-12;
      return;
    }
    const double mu = t.x.TexelCenter(x), r = t.y.TexelCenter(y);
    const ReferenceAlbedo a =
        IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, mu, 1e-12);
    if (t.definition == &TableNamed("E")) {
      c.truth[k] = a.E;
    } else {
      c.truth[2 * k] = a.A;
      c.truth[2 * k + 1] = a.B;
    }
    for (int ch = 0; ch < t.channels; ++ch)
      c.truthError[k * t.channels + ch] = 16 * a.error + 1e-12;
  });
  return c;
}

// Every compared value as float32 and half: within its stored bound, and
// (float32) within 1e-7 of the truth.
void ExpectFloat32Exact(const Table &t, const Compared &c, const std::string &what) {
  double worst = 0.0, worstBound = 0.0;
  for (size_t k = 0; k < c.texels.size(); ++k)
    for (int ch = 0; ch < t.channels; ++ch) {
      const size_t i = c.texels[k] * t.channels + ch, j = k * t.channels + ch;
      const double v = t.values[i], e = t.errors[i];
      const double stored = StoredValue(v, ValueType::kFloat32);
      const double real = std::abs(stored - c.truth[j]);
      worst = std::max(worst, real);
      worstBound = std::max(worstBound, StoredBound(v, e, ValueType::kFloat32));
      EXPECT_LE(real, 1e-7) << what << " texel " << c.texels[k] << " channel " << ch;
      EXPECT_LE(real, StoredBound(v, e, ValueType::kFloat32) + c.truthError[j])
          << what << " texel " << c.texels[k] << " channel " << ch;
      const double half = StoredValue(v, ValueType::kHalf);
      EXPECT_LE(std::abs(half - c.truth[j]), StoredBound(v, e, ValueType::kHalf) + c.truthError[j])
          << what << " (half) texel " << c.texels[k] << " channel " << ch;
    }
  std::printf("%s: %zu texels, worst |float32 - truth| %.2e, largest stored bound %.2e\n",
              what.c_str(), c.texels.size(), worst, worstBound);
}

std::vector<size_t> AllTexels(const Table &t) {
  std::vector<size_t> all(static_cast<size_t>(t.width()) * t.height());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

TEST(DefaultBake, SmallTablesAreFloat32Exact) {
  BakeSettings s;  // the default: panel quadrature, bound 1e-8
  s.tableSizes = {{"E", 16}, {"Eavg", 16}, {"dfg", 16}};
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("Eavg"), &TableNamed("dfg")}) {
    const Table t = BakeTable(*kind, s);
    ExpectFloat32Exact(t, Reference(t, AllTexels(t)), kind->Name());
  }
}

// The full-size defaults at their stiff corner: the smoothest rows
// (r <= 1/32) and the grazing columns (mu <= 1/64) of E 32 x 32 and
// dfg 128 x 128, every texel there.
TEST(DefaultBake, StiffRowsAndColumnsAreFloat32Exact) {
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("dfg")}) {
    const Table t = BakeTable(*kind, BakeSettings{});
    std::vector<size_t> stiff;
    for (int y = 0; y < t.height(); ++y)
      for (int x = 0; x < t.width(); ++x)
        if (t.y.TexelCenter(y) <= 1.0 / 32 || t.x.TexelCenter(x) <= 1.0 / 64)
          stiff.push_back(static_cast<size_t>(y) * t.width() + x);
    // E: row 0 and column 0 (63 texels); dfg: rows 0-3 and columns 0-1 (760).
    ASSERT_EQ(stiff.size(), kind == &TableNamed("E") ? 63u : 760u);
    ExpectFloat32Exact(t, Reference(t, stiff), std::string(kind->Name()) + " stiff");
  }
}

// --tolerance EPS: the error map (T.err.exr: bounds of the float32 values,
// rounded up) holds at every texel, and the integration bounds reach EPS.
TEST(DefaultBake, ToleranceBakeErrorMapHoldsAtEveryTexel) {
  for (double tolerance : {1e-3, 1e-5}) {
    BakeSettings s;
    s.tolerance = tolerance;
    s.tableSizes = {{"E", 12}, {"Eavg", 12}, {"dfg", 12}};
    for (const TableDefinition *kind :
         {&TableNamed("E"), &TableNamed("Eavg"), &TableNamed("dfg")}) {
      BakeStats stats;
      const Table t = BakeTable(*kind, s, {}, &stats);
      EXPECT_EQ(stats.unconverged, 0u);
      EXPECT_LE(t.MaxError(), tolerance);
      const Table map = ErrorMapOf(t);
      const Compared c = Reference(t, AllTexels(t));
      for (size_t k = 0; k < c.texels.size(); ++k)
        for (int ch = 0; ch < t.channels; ++ch) {
          const size_t i = k * t.channels + ch;
          EXPECT_LE(std::abs(StoredValue(t.values[i], ValueType::kFloat32) - c.truth[i]),
                    map.values[i] + c.truthError[i])
              << kind->Name() << " tolerance " << tolerance << " texel " << k;
          EXPECT_EQ(map.values[i], static_cast<double>(static_cast<float>(map.values[i])));
        }
    }
  }
}

// Output independent of the thread count: each texel depends on its own
// coordinates only.
TEST(DefaultBake, BitIdenticalForOneTwoAndSixteenThreads) {
  BakeSettings s;
  s.size = 16;
  s.tableSizes = {{"dfg", 32}};
  // The rough-dielectric tables at eta = 1 alone (their averages on the
  // inside take seconds a texel; glass_tables_test covers both sides).
  s.depthSize = 1;
  for (const TableDefinition *kind : AllTables()) {
    std::vector<Table> tables;
    for (int threads : {1, 2, 16}) {
      // Exactly that many threads, even on fewer cores (as --threads N does).
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      tbb::task_arena arena(threads);
      arena.execute([&] { tables.push_back(BakeTable(*kind, s)); });
    }
    for (size_t k = 1; k < tables.size(); ++k) {
      ASSERT_EQ(tables[k].values.size(), tables[0].values.size());
      EXPECT_EQ(0, std::memcmp(tables[k].values.data(), tables[0].values.data(),
                               tables[0].values.size() * sizeof(double)))
          << kind->Name();
      EXPECT_EQ(0, std::memcmp(tables[k].errors.data(), tables[0].errors.data(),
                               tables[0].errors.size() * sizeof(double)))
          << kind->Name();
    }
  }
}

}  // namespace
}  // namespace lutbake
