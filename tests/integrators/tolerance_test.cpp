// Tolerance runs against the quadrature reference: every texel within EPS
// and within its own reported bound; the rounds of a tolerance run are the
// same computation as one run of the final size.
#include <gtest/gtest.h>

#include <cmath>

#include "lutbake/integrators/albedo_estimator.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/integrators/replicated_integrator.h"
#include "lutbake/tables/bake.h"

namespace lutbake {
namespace {

struct Check {
  double maxError = 0;
  int overBound = 0;
  int overTolerance = 0;
};

// Every texel of an E or dfg table against the quadrature at 1e-13.
Check CheckTable(const Table &t, double tolerance) {
  Check check;
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const double r = t.y.TexelCenter(y);
      const ReferenceAlbedo ref = IntegrateReferenceAlbedo(
          Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, t.x.TexelCenter(x), 1e-13);
      bool over = false, overTolerance = false;
      for (int c = 0; c < t.channels; ++c) {
        const double truth = t.definition == &TableNamed("dfg") ? (c ? ref.B : ref.A) : ref.E;
        const double error = std::abs(t.value(x, y, c) - truth);
        check.maxError = std::max(check.maxError, error);
        over = over || error > t.errors[t.index(x, y, c)];
        overTolerance = overTolerance || error > tolerance;
      }
      check.overBound += over;
      check.overTolerance += overTolerance;
    }
  return check;
}

BakeSettings ToleranceSettings(int size, double tolerance) {
  BakeSettings s;
  s.tableSizes = {{"E", size}, {"dfg", size}};
  s.tolerance = tolerance;
  s.samples = kToleranceStartSamples;
  s.replicates = kToleranceReplicates;
  return s;
}

TEST(Tolerance, DefaultEstimatorReachesOneE6EverywhereWithinItsBound) {
  // 1e-6 is below what sampling can certify cheaply, so every texel goes to
  // the quadrature; its reported bound must hold and be at most EPS.
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("dfg")}) {
    BakeStats stats;
    const Table t = BakeTable(*kind, ToleranceSettings(12, 1e-6), {}, &stats);
    EXPECT_LE(t.MaxError(), 1e-6);
    EXPECT_EQ(stats.unconverged, 0u);
    const Check c = CheckTable(t, 1e-6);
    EXPECT_EQ(c.overTolerance, 0) << kind->Name() << " max error " << c.maxError;
    // 144 texels: a 99% bound may fail on at most one.
    EXPECT_LE(c.overBound, 1) << kind->Name();
  }
}

TEST(Tolerance, SamplingRoundsAloneReachALooseTolerance) {
  // Without the quadrature switch, sampling doubles until every bound is
  // below 2e-3; the real error must then be within EPS and the bound.
  BakeSettings s = ToleranceSettings(8, 2e-3);
  s.estimator = Estimator::kVisibleNormal;
  s.allowQuadratureSwitch = false;
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("dfg")}) {
    BakeStats stats;
    const Table t = BakeTable(*kind, s, {}, &stats);
    EXPECT_EQ(stats.quadratureTexels, 0u);
    EXPECT_EQ(stats.unconverged, 0u);
    EXPECT_LE(t.MaxError(), 2e-3);
    // At least 4.6 / EPS samples per texel: the unseen-event term alone.
    EXPECT_GE(static_cast<double>(stats.samples) / 64.0, kUnseenEventCount / 2e-3);
    const Check c = CheckTable(t, 2e-3);
    EXPECT_EQ(c.overTolerance, 0) << kind->Name() << " max error " << c.maxError;
    EXPECT_EQ(c.overBound, 0) << kind->Name();
  }
}

TEST(Tolerance, RoundsGiveTheSameResultAsOneRunOfTheFinalSize) {
  const Ndf ndf{NdfKind::kGgx, 0.09};
  const AlbedoEstimator estimator{ndf, SmithForm::kCorrelated, SampleStrategy::kVisibleNormal};
  const Vec3 o = ViewDirection(0.3);
  const auto sample = [&](const double(&u)[2]) {
    return std::array<double, 1>{estimator.Sample(o, ndf.MuLambda(0.3), u[0], u[1]).weight};
  };
  for (PointSet points : {PointSet::kScrambledSobol, PointSet::kIndependentRandom}) {
    ReplicatedAccumulator<2, 1> rounds(8, 42, points), once(8, 42, points);
    for (uint64_t n : {16, 32, 64, 128}) rounds.Extend(sample, n);
    once.Extend(sample, 128);
    EXPECT_EQ(rounds.Estimate().mean[0], once.Estimate().mean[0]);
    EXPECT_EQ(rounds.Estimate().standardError[0], once.Estimate().standardError[0]);
  }
}

TEST(Tolerance, StudentQuantilesMatchTables) {
  // Two-sided 99% quantiles (published tables): 3 dof 5.841, 7 dof 3.499,
  // 40 dof 2.704, 120 dof 2.617.
  EXPECT_NEAR(StudentT99(3), 5.841, 1e-3);
  EXPECT_NEAR(StudentT99(7), 3.499, 1e-3);
  EXPECT_NEAR(StudentT99(40), 2.704, 2e-3);
  EXPECT_NEAR(StudentT99(120), 2.617, 2e-3);
}

}  // namespace
}  // namespace lutbake
