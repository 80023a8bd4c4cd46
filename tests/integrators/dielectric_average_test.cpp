// The rough-dielectric average over the half vector first
// (IntegrateDielectricAverage) against: the rule it replaced, which
// integrates E(mu) from the albedo rule over the view (a different
// parameterisation: light direction's half vector per view, then the view),
// at the kinds of points that are hardest for it (eta = 1/128 and 128, eta ->
// 1 from both sides, the critical cosine reaching the peak, r -> 0, r = 1);
// and the index-matched closed form (eta = 1: 2 int G2(o, -o) / G1(o) mu
// dmu, integrated here by graded Gauss-Legendre panels in mu).
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrators/dielectric_kernel.h"
#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {
namespace {

constexpr auto kGlass = DielectricLobes::kReflectionAndTransmission;
constexpr auto kReflectionOnly = DielectricLobes::kReflection;

struct Case {
  NdfKind ndf;
  SmithForm smith;
  DielectricLobes lobes;
  double r, eta, tolerance;
};

std::string Describe(const Case &c) {
  return std::string(c.ndf == NdfKind::kGgx ? "ggx" : "beckmann") +
         (c.smith == SmithForm::kCorrelated ? " correlated" : " separable") +
         (c.lobes == kGlass ? " glass" : " reflection") + " r " + std::to_string(c.r) + " eta " +
         std::to_string(c.eta) + " tol " + std::to_string(c.tolerance);
}

void ExpectAgreement(const Case &c, double *worst) {
  const double alpha = c.r * c.r;
  const DielectricIntegral now =
      IntegrateDielectricAverage(c.ndf, c.smith, c.lobes, alpha, c.eta, c.tolerance);
  const DielectricIntegral before =
      IntegrateDielectricAverageOverAlbedo(c.ndf, c.smith, c.lobes, alpha, c.eta, c.tolerance);
  EXPECT_TRUE(now.converged) << Describe(c);
  EXPECT_LE(now.bound, c.tolerance) << Describe(c);
  EXPECT_GE(now.value, 0.0) << Describe(c);
  EXPECT_LE(now.value, 1.0) << Describe(c);
  const double difference = std::abs(now.value - before.value);
  EXPECT_LE(difference, now.bound + before.bound)
      << Describe(c) << ": " << now.value << " against " << before.value;
  *worst = std::max(*worst, difference / (now.bound + before.bound));
}

// GGX correlated, both lobes, at the bake's tolerance on the hidden points'
// kinds: the extreme indices, eta within 1e-6 of 1, r from 0.01 to 1; the
// critical cosine c_crit = sqrt(1 - eta^2) at the NDF's peak (eta = 0.9999,
// c_crit = 0.014 ~ alpha at r = 0.12).
TEST(DielectricAverage, AgreesWithTheRuleOverTheAlbedoAtHardPoints) {
  double worst = 0.0;
  for (DielectricLobes lobes : {kGlass, kReflectionOnly})
    for (double eta : {1.0 / 128.0, 1.0 / 1.5, 0.9999, 1.0 - 1e-6, 1.0 + 1e-6, 1.5, 128.0})
      for (double r : {0.01, 0.12, 1.0})
        ExpectAgreement({NdfKind::kGgx, SmithForm::kCorrelated, lobes, r, eta, 1e-8}, &worst);
  RecordProperty("worst_share_of_summed_bounds", std::to_string(worst));
}

// Where the half-vector rule's outer panels keep splitting (eta < 0.15 at r
// ~ 0.5: Cycles' inside slices), the rule over the albedos answers: still
// converged at the bake's tolerance and within the summed bounds.
TEST(DielectricAverage, FallsBackWhereThePanelsKeepSplitting) {
  double worst = 0.0;
  ExpectAgreement({NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5333, 0.06888359, 1e-8},
                  &worst);
  RecordProperty("worst_share_of_summed_bounds", std::to_string(worst));
}

// Beckmann and the separable form, both lobes, a few materials and
// roughnesses (at 1e-7: the rule before is slow for Beckmann).
TEST(DielectricAverage, AgreesWithTheRuleOverTheAlbedoForBeckmannAndSeparable) {
  double worst = 0.0;
  for (DielectricLobes lobes : {kGlass, kReflectionOnly})
    for (double eta : {1.0 / 2.42, 1.33}) {
      ExpectAgreement({NdfKind::kBeckmann, SmithForm::kCorrelated, lobes, 0.6, eta, 1e-7}, &worst);
      ExpectAgreement({NdfKind::kGgx, SmithForm::kSeparable, lobes, 0.35, eta, 1e-7}, &worst);
      ExpectAgreement({NdfKind::kBeckmann, SmithForm::kSeparable, lobes, 0.9, eta, 1e-7}, &worst);
    }
  RecordProperty("worst_share_of_summed_bounds", std::to_string(worst));
}

// 2 int_0^1 G2(o, -o) / G1(o) mu dmu, the index-matched glass average, by
// 24-node Gauss-Legendre panels in mu graded geometrically toward 0 (ratio 2,
// from alpha 2^-30), where the integrand varies on the scale alpha.
double IndexMatchedAverage(const Ndf &ndf, SmithForm smith) {
  const GaussLegendreRule &rule = GaussLegendre(24);
  double sum = 0.0, a = 0.0;
  double b = std::min(1.0, ndf.alpha * std::ldexp(1.0, -30));
  while (a < 1.0) {
    for (int j = 0; j < rule.n; ++j) {
      const double mu = a + (b - a) * rule.x[j];
      sum += rule.w[j] * (b - a) * 2.0 * mu * DielectricIndexMatchedAlbedo(ndf, smith, kGlass, mu);
    }
    a = b;
    b = std::min(1.0, 2.0 * b);
  }
  return sum;
}

TEST(DielectricAverage, IndexMatchedGlassMatchesItsClosedForm) {
  for (NdfKind kind : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable})
      for (double alpha : {1e-4, 0.04, 0.36, 1.0}) {
        const DielectricIntegral q =
            IntegrateDielectricAverage(kind, smith, kGlass, alpha, 1.0, 1e-8);
        const double exact = IndexMatchedAverage(Ndf{kind, alpha}, smith);
        EXPECT_NEAR(q.value, exact, q.bound) << "alpha " << alpha;
        EXPECT_TRUE(q.converged);
        // Reflection alone: F = 0 everywhere, exactly 0.
        EXPECT_EQ(IntegrateDielectricAverage(kind, smith, kReflectionOnly, alpha, 1.0, 1e-8).value,
                  0.0);
      }
}

TEST(DielectricAverage, RejectsArgumentsOutsideItsDomain) {
  EXPECT_THROW(
      IntegrateDielectricAverage(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 1.5, 1.5, 1e-8),
      std::invalid_argument);
  EXPECT_THROW(
      IntegrateDielectricAverage(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 200.0, 1e-8),
      std::invalid_argument);
  EXPECT_THROW(
      IntegrateDielectricAverage(NdfKind::kGgx, SmithForm::kCorrelated, kGlass, 0.5, 1.5, 0.0),
      std::invalid_argument);
}

// The average's azimuth kernel (kernel::ArcTerms) on every instruction set
// this build has and the processor runs: the same bits as its scalar form,
// lane by lane, and within 1e-13 of rule weight / (1 + v^2) x SmithG2 from
// the Ndf's Lambda (smith.h), 0 where a cosine is not positive; lines that
// cross both horizons, cosines past 1 (clamped), alpha from 1e-4 to 1.
TEST(DielectricAverage, ArcKernelSameBitsOnEveryInstructionSetAndMatchesSmithG2) {
  std::vector<double> v, ruleW;
  for (int k = 0; k <= 36; ++k) {
    v.push_back(k / 12.0);  // tan(psi / 2) from 0 to 3
    ruleW.push_back(0.25 + k / 100.0);
  }
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  std::vector<double> terms(v.size());
  int compared = 0, zeros = 0;
  for (double alpha : {1e-4, 0.09, 0.5, 1.0})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable})
      for (const std::array<double, 5> &line :
           {std::array<double, 5>{0.3, 0.6, 0.3, -0.6, 1.0},
            std::array<double, 5>{0.7, 0.2, 0.5, 0.2, 1.5},
            std::array<double, 5>{0.05, 0.9, 0.8, 0.9, 1.0 / 3.0},
            std::array<double, 5>{0.9, 0.3, 1.2, -0.1, 1.0}}) {
        const kernel::ArcConstants k{alpha * alpha, smith,   line[0],      line[1],
                                     line[2],       line[3], 1.0 / line[4]};
        const Ndf ndf{NdfKind::kGgx, alpha};
        for (int64_t target : targets) {
          hwy::SetSupportedTargetsForTest(target);
          kernel::ArcTerms(k, v.data(), ruleW.data(), v.size(), terms.data());
          for (size_t i = 0; i < v.size(); ++i) {
            ASSERT_EQ(terms[i], kernel::ArcTermScalar(k, v[i], ruleW[i]))
                << hwy::TargetName(target) << " alpha " << alpha << " v " << v[i];
            const double q = 1.0 / (1.0 + v[i] * v[i]), cosPsi = (1.0 - v[i] * v[i]) * q;
            const double mo = std::min(line[0] + line[1] * cosPsi, 1.0);
            const double mi = std::min((line[2] + line[3] * cosPsi) / line[4], 1.0);
            double expected = 0.0;
            if (mo > 0.0 && mi > 0.0)
              expected = ruleW[i] * q * SmithG2(smith, mo, mi, ndf.MuLambda(mo), ndf.MuLambda(mi));
            else
              ++zeros;
            EXPECT_NEAR(terms[i], expected, 1e-13) << "alpha " << alpha << " v " << v[i];
            ++compared;
          }
        }
      }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GT(zeros, 0);
  std::printf("%d arc terms compared on %zu instruction sets (%d outside the horizons)\n", compared,
              targets.size(), zeros);
}

}  // namespace
}  // namespace lutbake
