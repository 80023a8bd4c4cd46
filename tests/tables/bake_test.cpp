// Baked tables against the analytic limits, the identities of SPEC section 1,
// the quadrature reference, and each other; and determinism across threads.
#include "lutbake/tables/bake.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "lutbake/integrators/albedo_estimator.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/integrators/replicated_integrator.h"

namespace lutbake {
namespace {

// A sampled bake (visible normals, the estimator --samples chooses).
BakeSettings Small(int size, uint64_t samples) {
  BakeSettings s;
  s.size = size;
  s.samples = samples;
  s.estimator = Estimator::kVisibleNormal;
  return s;
}

TEST(Bake, DefaultSamplesMeetOneE4AgainstQuadrature) {
  // The default sample count on a 16 x 16 E and dfg (grazing column at
  // mu = 1/32, smoothest row at r = 1/32): every texel within 1e-4 of the
  // quadrature, the product's stated accuracy.
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("dfg")}) {
    const Table t = BakeTable(*kind, Small(16, kDefaultSamples));
    std::vector<double> worst(t.width() * t.height(), 0.0);
    tbb::parallel_for(size_t(0), worst.size(), [&](size_t i) {
      const int x = static_cast<int>(i % t.width()), y = static_cast<int>(i / t.width());
      const double r = t.y.TexelCenter(y);
      const ReferenceAlbedo ref = IntegrateReferenceAlbedo(
          Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, t.x.TexelCenter(x));
      if (kind == &TableNamed("E"))
        worst[i] = std::abs(t.value(x, y) - ref.E);
      else
        worst[i] = std::max(std::abs(t.value(x, y, 0) - ref.A), std::abs(t.value(x, y, 1) - ref.B));
    });
    for (size_t i = 0; i < worst.size(); ++i)
      EXPECT_LE(worst[i], 1e-4) << kind->Name() << " texel " << i % t.width() << ","
                                << i / t.width();
  }
}

TEST(Bake, ErrorBoundsHoldForNinetyNinePercentOfInteriorTexels) {
  // The bound is a 99% Student-t interval; away from the smoothest rows
  // (where the GGX tail makes misses a rare event, see docs/accuracy-and-speed.md) at most a few
  // percent of texels may exceed it. 64 texels: allow 4.
  const Table t = BakeTable(TableNamed("E"), Small(8, 4096));
  int exceed = 0;
  for (int y = 1; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const double r = t.y.TexelCenter(y);
      const double ref = IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated,
                                                  t.x.TexelCenter(x))
                             .E;
      if (std::abs(t.value(x, y) - ref) > t.errors[t.index(x, y, 0)]) ++exceed;
    }
  EXPECT_LE(exceed, 4);
}

TEST(Bake, SmoothLimitEIsOneAndBIsSchlickWeight) {
  // alpha -> 0 at fixed mu: E -> 1, B -> (1 - mu)^5. At alpha = 2.5e-5
  // (r = 0.005) the limits hold to 1e-6 for mu >= 0.25 (refdata/limits.csv,
  // checked here through the quadrature); the sampled visible-normal estimate
  // must then agree with the limit within its own bound plus that.
  const double alpha = 2.5e-5;
  const AlbedoEstimator estimator{Ndf{NdfKind::kGgx, alpha}, SmithForm::kCorrelated,
                                  SampleStrategy::kVisibleNormal};
  for (double mu : {0.375, 0.625, 0.875}) {
    const ReferenceAlbedo ref = IntegrateReferenceAlbedo(estimator.ndf, SmithForm::kCorrelated, mu);
    EXPECT_NEAR(ref.E, 1.0, 1e-6);
    EXPECT_NEAR(ref.B, std::pow(1.0 - mu, 5), 1e-6);
    const Vec3 o = ViewDirection(mu);
    const double L_o = estimator.ndf.MuLambda(mu);
    const auto sampled = IntegrateReplicated<2, 2>(
        [&](const double(&u)[2]) {
          const AlbedoSample a = estimator.Sample(o, L_o, u[0], u[1]);
          return std::array<double, 2>{a.weight, a.weight * a.schlickWeight};
        },
        4096, kDefaultReplicates, 7);
    EXPECT_NEAR(sampled.mean[0], 1.0,
                StudentT99(kDefaultReplicates - 1) * sampled.standardError[0] + 1e-6)
        << mu;
    EXPECT_NEAR(sampled.mean[1], std::pow(1.0 - mu, 5),
                StudentT99(kDefaultReplicates - 1) * sampled.standardError[1] + 1e-6)
        << mu;
  }
  const Table e = BakeTable(TableNamed("E"), Small(4, 4096));
  // On the default axes, E decreases along each column as roughness grows.
  for (int x = 0; x < e.width(); ++x)
    for (int y = 1; y < e.height(); ++y)
      EXPECT_LE(e.value(x, y),
                e.value(x, y - 1) + e.errors[e.index(x, y, 0)] + e.errors[e.index(x, y - 1, 0)]);
  // The smoothest row (r = 1/8, alpha = 1/64) is already near the mirror's
  // E = 1 away from grazing (the truth: 1 - E = 1.1e-3 at mu = 3/8, less
  // further in), and the bake agrees with the truth within its bounds.
  for (int x = 1; x < e.width(); ++x) {
    const double mu = e.x.TexelCenter(x), r = e.y.TexelCenter(0);
    const double truth =
        IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, mu).E;
    EXPECT_NEAR(truth, 1.0, 1.2e-3) << mu;
    EXPECT_NEAR(e.value(x, 0), truth, e.errors[e.index(x, 0, 0)]) << mu;
  }
}

TEST(Bake, SplitSumAddsUpToAlbedo) {
  // A + B = E: dfg and E are baked with independent point sets, so the
  // difference is bounded by the sum of their error bounds.
  const BakeSettings s = Small(12, 8192);
  const Table e = BakeTable(TableNamed("E"), s);
  const Table dfg = BakeTable(TableNamed("dfg"), s);
  for (int y = 0; y < e.height(); ++y)
    for (int x = 0; x < e.width(); ++x) {
      const double bound = e.errors[e.index(x, y, 0)] + dfg.errors[dfg.index(x, y, 0)] +
                           dfg.errors[dfg.index(x, y, 1)] + 1e-12;
      EXPECT_NEAR(dfg.value(x, y, 0) + dfg.value(x, y, 1), e.value(x, y), bound) << x << "," << y;
    }
}

TEST(Bake, SchlickFavgIsTheClosedForm) {
  const Table t = BakeTable(TableNamed("Favg"), Small(32, 2));
  for (int x = 0; x < t.width(); ++x) {
    const double f0 = (x + 0.5) / 32.0;
    EXPECT_NEAR(t.value(x, 0), 20.0 / 21.0 * f0 + 1.0 / 21.0, 1e-15);
  }
}

TEST(Bake, ConductorFavgIsTwoDimensionalAndBounded) {
  BakeSettings s = Small(8, 2);
  s.fresnel = FresnelModel::kConductor;
  const Table t = BakeTable(TableNamed("Favg"), s);
  EXPECT_TRUE(t.is2D());
  EXPECT_EQ(t.y.name, "k");
  for (double v : t.values) EXPECT_TRUE(v >= 0.0 && v <= 1.0);
}

TEST(Bake, EavgAgreesWithTheIntegralOfE) {
  // E_avg from its own 3D estimator against the quadrature of 2 int E mu dmu,
  // within the estimator's bound.
  const Table t = BakeTable(TableNamed("Eavg"), Small(4, 4096));
  for (int x = 0; x < t.width(); ++x) {
    const double r = t.x.TexelCenter(x);
    const ReferenceAverage ref =
        IntegrateReferenceAlbedoAverage(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, 1e-9);
    EXPECT_NEAR(t.value(x, 0), ref.value, t.errors[x] + 1e-9) << "r = " << r;
  }
}

TEST(Bake, BitIdenticalForOneAndTwoThreads) {
  const BakeSettings s = Small(16, 256);
  for (const TableDefinition *kind : AllTables()) {
    Table one, two;
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
      one = BakeTable(*kind, s);
    }
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
      two = BakeTable(*kind, s);
    }
    ASSERT_EQ(one.values.size(), two.values.size());
    EXPECT_EQ(0,
              std::memcmp(one.values.data(), two.values.data(), one.values.size() * sizeof(double)))
        << kind->Name();
    EXPECT_EQ(0,
              std::memcmp(one.errors.data(), two.errors.data(), one.errors.size() * sizeof(double)))
        << kind->Name();
  }
}

TEST(Bake, CancelledTokenStopsTheBakeBetweenTexels) {
  // Cancelled before it starts: no texel is computed (the progress callback,
  // called after every block of texels, never runs) and Cancelled carries the
  // reason.
  CancellationToken token;
  token.Cancel(15);
  BakeSettings s = Small(64, 64);
  s.cancellation = &token;
  int calls = 0;
  try {
    BakeTable(TableNamed("E"), s, [&](double) { ++calls; });
    ADD_FAILURE() << "a cancelled bake returned a table";
  } catch (const Cancelled &c) {
    EXPECT_EQ(c.reason(), 15);
  }
  EXPECT_EQ(calls, 0);

  // Cancelled from inside, after the first block: the bake stops well before
  // its last texel (progress stays below 1).
  CancellationToken midway;
  s.cancellation = &midway;
  double last = 0.0;
  std::mutex lock;
  EXPECT_THROW(BakeTable(TableNamed("E"), s,
                         [&](double done) {
                           std::lock_guard<std::mutex> guard(lock);
                           last = std::max(last, done);
                           midway.Cancel(2);
                         }),
               Cancelled);
  EXPECT_GT(last, 0.0);
  EXPECT_LT(last, 1.0);

  // The same settings with a token never cancelled bake as without one.
  CancellationToken idle;
  s.cancellation = &idle;
  const Table with = BakeTable(TableNamed("E"), s);
  s.cancellation = nullptr;
  EXPECT_EQ(with.values, BakeTable(TableNamed("E"), s).values);
}

TEST(Bake, SeedChangesTheEstimateWithinItsError) {
  BakeSettings a = Small(8, 1024), b = a;
  b.seed = 12345;
  const Table ta = BakeTable(TableNamed("E"), a), tb = BakeTable(TableNamed("E"), b);
  bool anyDifferent = false;
  for (size_t i = 0; i < ta.values.size(); ++i) {
    anyDifferent = anyDifferent || ta.values[i] != tb.values[i];
    EXPECT_NEAR(ta.values[i], tb.values[i], ta.errors[i] + tb.errors[i] + 1e-12);
  }
  EXPECT_TRUE(anyDifferent);
}

TEST(Bake, NoNanOrOutOfRangeForEveryModel) {
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable})
      for (Estimator est : {Estimator::kVisibleNormal, Estimator::kNdf}) {
        BakeSettings s = Small(8, 256);
        s.ndf = ndf;
        s.smith = smith;
        s.estimator = est;
        for (const TableDefinition *kind :
             {&TableNamed("E"), &TableNamed("dfg"), &TableNamed("Eavg")}) {
          const Table t = BakeTable(*kind, s);
          for (double v : t.values) {
            ASSERT_TRUE(std::isfinite(v));
            // NDF sampling has unbounded weights, so its estimate may exceed 1
            // by its own error; the visible-normal estimate is a mean of values in [0, 1].
            EXPECT_GE(v, 0.0);
            if (est == Estimator::kVisibleNormal) {
              EXPECT_LE(v, 1.0);
            }
          }
          for (double e : t.errors) ASSERT_TRUE(std::isfinite(e));
        }
      }
}

TEST(Bake, BeckmannMatchesQuadrature) {
  BakeSettings s = Small(6, 16384);
  s.ndf = NdfKind::kBeckmann;
  const Table t = BakeTable(TableNamed("E"), s);
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const double r = t.y.TexelCenter(y);
      const double ref = IntegrateReferenceAlbedo(Ndf{NdfKind::kBeckmann, r * r},
                                                  SmithForm::kCorrelated, t.x.TexelCenter(x))
                             .E;
      EXPECT_NEAR(t.value(x, y), ref, 1e-3) << x << "," << y;
    }
}

}  // namespace
}  // namespace lutbake
