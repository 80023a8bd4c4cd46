// The panel quadrature (the default integrator) against independent values:
// tests/data (another program, two parameterisations), the closed-form
// azimuthal integral of GGX's D (another formulation: over the light
// direction, 1D), and the adaptive Gauss-Kronrod reference. Its bounds hold
// at every point and reach the tolerance asked, its analytic limits are
// right, and it gives the same bits on every instruction set.
#include "lutbake/integrators/albedo_quadrature.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>

#include "integrators/albedo_kernel.h"
#include "lutbake/core/hash.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/tables/bake.h"
#include "support/azimuth_closed_form.h"
#include "support/csv.h"

namespace lutbake {
namespace {

constexpr SmithForm kForms[] = {SmithForm::kCorrelated, SmithForm::kSeparable};

// Every row of tests/data's E, A and B (290 per NDF, mu from 1e-6, alpha
// from 1e-4), both Smith forms: within the quadrature's bound plus the
// reference's own (~1e-12), and within 1e-9.
void CheckAgainstTable(NdfKind kind, const std::string &file) {
  const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath(file));
  ASSERT_EQ(rows.size(), 290u);
  struct Outcome {
    double error[3], bound[3], referenceError[3];
  };
  std::vector<Outcome> out(rows.size() * 2);
  tbb::parallel_for(size_t(0), out.size(), [&](size_t k) {
    const test::CsvRow &row = rows[k / 2];
    const SplitSumQuadrature q =
        IntegrateSplitSumQuadrature(Ndf{kind, row.Number("alpha")}, kForms[k % 2], row.Number("mu"),
                                    kDefaultQuadratureTolerance, true);
    const std::string s = k % 2 == 0 ? "_hc" : "_sep";
    out[k] = {{std::abs(q.A + q.B - row.Number("E" + s)), std::abs(q.A - row.Number("A" + s)),
               std::abs(q.B - row.Number("B" + s))},
              {q.boundE, q.boundA, q.boundB},
              {row.Number("err_E" + s), row.Number("err_A" + s), row.Number("err_B" + s)}};
  });
  double worst = 0.0;
  for (size_t k = 0; k < out.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, out[k].error[c]);
      const std::string where = file + " mu=" + rows[k / 2].Text("mu") +
                                " alpha=" + rows[k / 2].Text("alpha") +
                                (k % 2 ? " separable" : " correlated") + " channel " + "EAB"[c];
      EXPECT_LE(out[k].error[c], out[k].bound[c] + out[k].referenceError[c]) << where;
      EXPECT_LE(out[k].error[c], 1e-9) << where;
      // split = true: A's and B's bounds reach the tolerance (E's is their sum at most).
      if (c > 0) {
        EXPECT_LE(out[k].bound[c], kDefaultQuadratureTolerance) << where;
      }
    }
  std::printf("%s: worst |quadrature - reference| %.2e\n", file.c_str(), worst);
}

TEST(AlbedoQuadrature, MatchesIndependentGgxValues) {
  CheckAgainstTable(NdfKind::kGgx, "ggx_E_AB.csv");
}

TEST(AlbedoQuadrature, MatchesIndependentBeckmannValues) {
  CheckAgainstTable(NdfKind::kBeckmann, "beckmann_E_AB.csv");
}

// GGX's E from the closed-form azimuthal integral (azimuth_closed_form.h):
// every texel centre of a 32 x 32 table and the stiff corner of a 1024 x
// 1024 one (r and mu down to 1/2048), both Smith forms.
TEST(AlbedoQuadrature, MatchesTheClosedFormAzimuthalIntegral) {
  struct Point {
    double mu, r;
  };
  std::vector<Point> points;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) points.push_back({(x + 0.5) / 32, (y + 0.5) / 32});
  for (int y : {0, 1, 3, 15, 31, 63})
    for (int x : {0, 1, 3, 15, 31, 63}) points.push_back({(x + 0.5) / 1024, (y + 0.5) / 1024});
  std::vector<double> error(points.size() * 2), bound(points.size() * 2);
  tbb::parallel_for(size_t(0), error.size(), [&](size_t k) {
    const Point &p = points[k / 2];
    const double alpha = p.r * p.r;
    const SplitSumQuadrature q = IntegrateSplitSumQuadrature(
        Ndf{NdfKind::kGgx, alpha}, kForms[k % 2], p.mu, kDefaultQuadratureTolerance, false);
    error[k] = std::abs(q.A + q.B - test::ClosedFormAzimuthE(alpha, p.mu, kForms[k % 2]));
    bound[k] = q.boundE;
  });
  double worst = 0.0;
  for (size_t k = 0; k < error.size(); ++k) {
    worst = std::max(worst, error[k]);
    EXPECT_LE(error[k], bound[k]) << "mu " << points[k / 2].mu << " r " << points[k / 2].r;
    EXPECT_LE(error[k], 1e-10) << "mu " << points[k / 2].mu << " r " << points[k / 2].r;
  }
  std::printf("worst |E - closed-form azimuth E| %.2e over %zu points\n", worst, error.size());
}

// E_avg against tests/data (alpha from 1e-8 to 1, Blender's grid among them).
TEST(AlbedoQuadrature, AveragesMatchIndependentValues) {
  for (auto [kind, file] : {std::pair{NdfKind::kGgx, "ggx_Eavg.csv"},
                            std::pair{NdfKind::kBeckmann, "beckmann_Eavg.csv"}}) {
    const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath(file));
    ASSERT_GT(rows.size(), 10u);
    std::vector<AverageQuadrature> q(rows.size() * 2);
    tbb::parallel_for(size_t(0), q.size(), [&](size_t k) {
      q[k] = IntegrateAverageQuadrature(Ndf{kind, rows[k / 2].Number("alpha")}, kForms[k % 2],
                                        kDefaultQuadratureTolerance);
    });
    double worst = 0.0, worstRatio = 0.0;
    for (size_t k = 0; k < q.size(); ++k) {
      const std::string s = k % 2 == 0 ? "_hc" : "_sep";
      const double error = std::abs(q[k].value - rows[k / 2].Number("Eavg" + s));
      worst = std::max(worst, error);
      worstRatio = std::max(worstRatio, error / q[k].bound);
      EXPECT_LE(error, q[k].bound + rows[k / 2].Number("err_Eavg" + s))
          << file << " alpha " << rows[k / 2].Text("alpha") << s;
      EXPECT_LE(error, 1e-9) << file << " alpha " << rows[k / 2].Text("alpha") << s;
      EXPECT_TRUE(q[k].converged);
    }
    std::printf("%s: worst |E_avg - reference| %.2e, at most %.2f of its bound\n", file, worst,
                worstRatio);
  }
}

// Every tolerance the command line accepts down to 1e-9 is reached, and the
// bound holds, against the adaptive reference at 1e-13 on a grid with the
// corners: texel centres of a 12 x 12 table and mu, r in {1e-3, 1e-2}.
TEST(AlbedoQuadrature, ReachesTheToleranceAndTheBoundHolds) {
  std::vector<std::pair<double, double>> points;  // (mu, r)
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) points.push_back({(x + 0.5) / 12, (y + 0.5) / 12});
  for (double mu : {1e-3, 1e-2})
    for (double r : {1e-3, 1e-2, 0.5}) points.push_back({mu, r});
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann}) {
    std::vector<ReferenceAlbedo> truth(points.size());
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
      const double r = points[i].second;
      truth[i] =
          IntegrateReferenceAlbedo(Ndf{ndf, r * r}, SmithForm::kCorrelated, points[i].first, 1e-13);
    });
    for (double tolerance : {1e-4, 1e-6, 1e-9}) {
      std::vector<SplitSumQuadrature> q(points.size());
      tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
        const double r = points[i].second;
        q[i] = IntegrateSplitSumQuadrature(Ndf{ndf, r * r}, SmithForm::kCorrelated, points[i].first,
                                           tolerance, true);
      });
      for (size_t i = 0; i < points.size(); ++i) {
        const std::string where = std::string(ToString(ndf)) + " mu " +
                                  std::to_string(points[i].first) + " r " +
                                  std::to_string(points[i].second);
        EXPECT_TRUE(q[i].converged) << where;
        EXPECT_LE(std::max(q[i].boundA, q[i].boundB), tolerance) << where;
        // The reference's own error is below 1e-12.
        EXPECT_LE(std::abs(q[i].A - truth[i].A), q[i].boundA + 1e-12) << where;
        EXPECT_LE(std::abs(q[i].B - truth[i].B), q[i].boundB + 1e-12) << where;
      }
    }
  }
}

// Unreal's Vis_SmithJointApprox at grazing view (its pole at mu_i ~ -mu_o):
// points where, from levels 0 and 1, the two values of B agreed by chance
// and B was 2.3 to 3.0 times its bound off (before kJointApproxFirstLevel).
// The reference is the rule at its finest level; its own error is taken as
// its last two levels' difference (below 6e-13 here).
TEST(AlbedoQuadrature, FittedJointApproxBoundsHoldAtGrazingView) {
  const double points[][2] = {{0.000654696, 0.209423},
                              {0.000325782, 0.145603},
                              {0.0117188, 0.628906},
                              {0.00099484, 0.221039}};  // (mu, r)
  for (const auto &p : points) {
    const double mu = p[0], alpha = p[1] * p[1];
    const SplitSumQuadrature q = IntegrateFittedSplitSumQuadrature(
        alpha, FittedVisibility::kSmithJointApprox, mu, kDefaultQuadratureTolerance);
    const SplitSumQuadrature truth =
        IntegrateFittedSplitSumQuadrature(alpha, FittedVisibility::kSmithJointApprox, mu, 1e-30);
    const std::string where = "mu " + std::to_string(mu) + " alpha " + std::to_string(alpha);
    EXPECT_LE(std::max(q.boundA, q.boundB), kDefaultQuadratureTolerance) << where;
    EXPECT_LE(std::abs(q.A - truth.A), q.boundA + (truth.boundA - kQuadratureBoundFloor)) << where;
    EXPECT_LE(std::abs(q.B - truth.B), q.boundB + (truth.boundB - kQuadratureBoundFloor)) << where;
  }
}

TEST(AlbedoQuadrature, AnalyticLimits) {
  // GGX at alpha = 1 (refdata/README): the grazing limit of correlated E is
  // 1 with B = 1/21; separable E -> 2 - 2 ln 2; at mu = 1, E = 1 - ln 2.
  const Ndf rough{NdfKind::kGgx, 1.0};
  const double tol = 1e-10;
  const SplitSumQuadrature hc =
      IntegrateSplitSumQuadrature(rough, SmithForm::kCorrelated, 0.0, tol, true);
  EXPECT_NEAR(hc.A + hc.B, 1.0, hc.boundE);
  EXPECT_NEAR(hc.B, 1.0 / 21.0, hc.boundB);
  const SplitSumQuadrature sep =
      IntegrateSplitSumQuadrature(rough, SmithForm::kSeparable, 0.0, tol, false);
  EXPECT_NEAR(sep.A + sep.B, 2.0 - 2.0 * std::log(2.0), sep.boundE);
  const SplitSumQuadrature normal =
      IntegrateSplitSumQuadrature(rough, SmithForm::kCorrelated, 1.0, tol, false);
  EXPECT_NEAR(normal.A + normal.B, 1.0 - std::log(2.0), normal.boundE);
  // A smooth surface: E -> 1 and B -> (1 - mu)^5 (to O(alpha) at mu >= 0.25).
  for (double mu : {0.25, 0.5, 0.875}) {
    const SplitSumQuadrature q = IntegrateSplitSumQuadrature(Ndf{NdfKind::kGgx, 1e-8},
                                                             SmithForm::kCorrelated, mu, tol, true);
    EXPECT_NEAR(q.A + q.B, 1.0, 1e-7);
    EXPECT_NEAR(q.B, std::pow(1 - mu, 5), 1e-7);
    EXPECT_LE(q.A + q.B, 1.0);  // never above the truth's range
  }
}

// The quadrature's values at a spread of points, for comparing runs.
std::vector<double> Sample() {
  std::vector<double> values;
  for (SmithForm smith : kForms)
    for (double mu : {0.0, 1e-3, 0.3, 0.99})
      for (double alpha : {1e-6, 0.04, 0.7}) {
        const SplitSumQuadrature q =
            IntegrateSplitSumQuadrature(Ndf{NdfKind::kGgx, alpha}, smith, mu, 1e-9, true);
        values.insert(values.end(), {q.A, q.B, q.boundA, q.boundB});
        const F82Quadrature c = IntegrateF82Quadrature(Ndf{NdfKind::kGgx, alpha}, smith, mu, 1e-9);
        values.insert(values.end(), {c.C, c.bound});
      }
  return values;
}

// The SIMD kernel on every instruction set this build has and the processor
// runs (AVX-512, AVX2, SSE4, ..., scalar): the same bits, because every
// operation is correctly rounded and the sums are split the same way.
TEST(AlbedoQuadrature, SameBitsOnEveryInstructionSet) {
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  std::vector<double> first;
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    const std::vector<double> values = Sample();
    if (first.empty()) first = values;
    ASSERT_EQ(values.size(), first.size());
    for (size_t i = 0; i < values.size(); ++i)
      EXPECT_EQ(values[i], first[i]) << hwy::TargetName(target) << " value " << i;
  }
  hwy::SetSupportedTargetsForTest(0);
  std::printf("%zu instruction sets compared\n", targets.size());
}

// The kernel's rewritten integrand (two divisions, two square roots) against
// the library's formulas (ggx.h, smith.h, math.h) at random panels.
TEST(AlbedoQuadrature, KernelMatchesTheLibraryFormulas) {
  RandomStream random(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const double alpha = std::pow(10.0, -6.0 * random.NextDouble());
    const double mu_o = random.NextDouble();
    const SmithForm smith = kForms[trial % 2];
    const bool tail = trial % 3 == 0;
    const double sc = (2 * random.NextDouble() - 1) * std::sqrt(1 - mu_o * mu_o);
    const double from = 0.05 + 0.9 * random.NextDouble(), width = 1e-3;
    const double scale = 1.0;
    const double x = 0.5, w = 1.0;  // one node in the middle, weight 1
    const kernel::Panels panels{&from, &width, &sc, &scale, 1};
    double sums[2], withC[3];
    const double L_o = ggx::MuLambda(alpha, mu_o);
    kernel::SumGgxSplitSum({alpha, mu_o, L_o, smith}, tail, 1, &x, &w, panels, sums);
    // The F82 entry point: A and B the same bits, and C besides.
    kernel::SumGgxSplitSumF82({alpha, mu_o, L_o, smith}, tail, 1, &x, &w, panels, withC);
    EXPECT_EQ(withC[0], sums[0]) << trial;
    EXPECT_EQ(withC[1], sums[1]) << trial;
    // The same point by the library's own functions.
    const double at = from + width * x;
    const double T = tail ? alpha / at : alpha * at;
    const double q = sc * T + mu_o;
    const double mu_i = (2 * T * sc + mu_o * (1 - T * T)) / (1 + T * T);
    double a = 0.0, b = 0.0, c = 0.0;
    if (mu_i > 0 && q > 0) {
      const double f = scale * w * 2 * at / Sqr(1 + at * at) * (tail ? q : q) *
                       SmithG2OverMuO(smith, mu_o, mu_i, L_o, ggx::MuLambda(alpha, mu_i));
      const SchlickWeights fc = Schlick(q / std::sqrt(1 + T * T));
      a = f * fc.complement;
      b = f * fc.fc;
      const double oh = q / std::sqrt(1 + T * T);
      c = f * oh * std::pow(1 - oh, 6);
    }
    EXPECT_NEAR(sums[0], a, 1e-12 * std::abs(a) + 1e-300) << trial;
    EXPECT_NEAR(sums[1], b, 1e-12 * std::abs(b) + 1e-300) << trial;
    EXPECT_NEAR(withC[2], c, 1e-12 * std::abs(c) + 1e-300) << trial;
  }
}

}  // namespace
}  // namespace lutbake
