// The sheen albedo integrators against tests/data/sheen (an independent
// numpy computation over the half vector, README there), against each other,
// a brute-force rule written here, closed forms, limits and the domain.
#include "lutbake/integrators/sheen_quadrature.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include "lutbake/integrators/gauss_legendre.h"
#include "support/csv.h"

namespace lutbake {
namespace {

SheenVisibility Visibility(const std::string &name) {
  SheenVisibility v = SheenVisibility::kCharlie;
  EXPECT_TRUE(ParseSheenVisibility(name, &v)) << name;
  return v;
}

std::vector<test::CsvRow> ReferenceE() {
  const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath("sheen/sheen_E.csv"));
  EXPECT_GE(rows.size(), 300u);
  return rows;
}

// Every reference point: |value - ref| <= bound + ref error, and the bound
// meets the target tolerance max(1, E). Prints the largest ratio of the real
// error (less the reference's) to the bound.
void CheckAgainstReference(bool adaptive, double tolerance) {
  double worstRatio = 0.0, worstError = 0.0;
  int points = 0;
  for (const test::CsvRow &row : ReferenceE()) {
    const SheenVisibility v = Visibility(row.Text("visibility"));
    const double alpha = row.Number("alpha"), mu = row.Number("mu");
    const double ref = row.Number("E"), refError = row.Number("error");
    const SheenIntegral r = adaptive ? IntegrateSheenAlbedoAdaptive(v, alpha, mu, tolerance)
                                     : IntegrateSheenAlbedo(v, alpha, mu, tolerance);
    const double error = std::abs(r.value - ref);
    EXPECT_LE(error, r.bound + refError) << row.Text("visibility") << " alpha " << alpha << " mu "
                                         << mu << " value " << r.value << " ref " << ref;
    EXPECT_LE(r.bound, tolerance * std::max(1.0, ref))
        << row.Text("visibility") << " alpha " << alpha << " mu " << mu;
    worstRatio = std::max(worstRatio, std::max(0.0, error - refError) / r.bound);
    worstError = std::max(worstError, error / std::max(1.0, ref));
    ++points;
  }
  std::printf(
      "%s at %g: %d points, worst relative error %.3g, worst (error - ref error) / bound %.3g\n",
      adaptive ? "adaptive" : "default", tolerance, points, worstError, worstRatio);
}

TEST(SheenQuadrature, DefaultMatchesReference) {
  CheckAgainstReference(false, 1e-8);
  CheckAgainstReference(false, 1e-10);
}

TEST(SheenQuadrature, AdaptiveMatchesReference) { CheckAgainstReference(true, 1e-9); }

TEST(SheenQuadrature, AverageMatchesReference) {
  const std::vector<test::CsvRow> rows = test::ReadCsv(test::DataPath("sheen/sheen_Eavg.csv"));
  ASSERT_GE(rows.size(), 8u);
  for (const test::CsvRow &row : rows) {
    const SheenVisibility v = Visibility(row.Text("visibility"));
    const double alpha = row.Number("alpha"), ref = row.Number("Eavg");
    const SheenIntegral r = IntegrateSheenAlbedoAverage(v, alpha, 1e-8);
    EXPECT_LE(std::abs(r.value - ref), r.bound + row.Number("error"))
        << row.Text("visibility") << " alpha " << alpha << " value " << r.value << " ref " << ref;
    EXPECT_LE(r.bound, 1e-8);
  }
}

// E_avg three ways: the default; the adaptive reference (tolerance 1e-7: it
// nests the adaptive E, 1.5 s, so at alpha = 1 with ashikhmin only); and a
// Gauss-Legendre rule over mu (16 nodes on 16 panels, below) of the default
// point integrator at 1e-10, allowed the default's bound, the points' bounds
// and 1e-9 for its own error in mu (E(mu) has mu^c and square-root branch
// points at the ends, which the panels leave at ~1e-10).
TEST(SheenQuadrature, AverageThreeWays) {
  for (auto [v, alpha] :
       {std::pair{SheenVisibility::kAshikhmin, 1.0}, std::pair{SheenVisibility::kCharlie, 0.25}}) {
    const SheenIntegral def = IntegrateSheenAlbedoAverage(v, alpha, 1e-9);
    SheenIntegral ada;
    if (v == SheenVisibility::kAshikhmin) {
      ada = IntegrateSheenAlbedoAverageAdaptive(v, alpha, 1e-7);
      EXPECT_LE(std::abs(def.value - ada.value), def.bound + ada.bound);
    }
    // [0, 1/16] in y = mu^c (mu = y^(1/c)), 4 uniform panels: Charlie's
    // Lambda(mu_o) has its mu^c branch point at 0, analytic in y; then
    // dyadic panels to 1/2 and [1/2, 1] graded by 2 toward 1.
    const double c = CharlieLambdaExponent(alpha);
    const GaussLegendreRule &rule = GaussLegendre(16);
    double sum = 0.0, pointBounds = 0.0;
    const auto add = [&](double mu, double weight) {
      const SheenIntegral e = IntegrateSheenAlbedo(v, alpha, mu, 1e-10);
      sum += weight * 2.0 * mu * e.value;
      pointBounds += weight * 2.0 * mu * e.bound;
    };
    const double Y = std::pow(1.0 / 16.0, c);
    for (int p = 0; p < 4; ++p)
      for (int j = 0; j < rule.n; ++j) {
        const double y = Y * (p + rule.x[j]) / 4.0, mu = std::pow(y, 1.0 / c);
        add(mu, Y / 4.0 * rule.w[j] * mu / (c * y));
      }
    std::vector<double> edges{1.0 / 16.0, 1.0 / 8.0, 0.25, 0.5};
    for (int k = 2; k <= 10; ++k) edges.push_back(1.0 - std::ldexp(1.0, -k));
    edges.push_back(1.0);
    for (size_t p = 0; p + 1 < edges.size(); ++p)
      for (int j = 0; j < rule.n; ++j)
        add(edges[p] + (edges[p + 1] - edges[p]) * rule.x[j],
            (edges[p + 1] - edges[p]) * rule.w[j]);
    EXPECT_NEAR(sum, def.value, def.bound + pointBounds + 1e-9) << ToString(v) << " " << alpha;
    std::printf("E_avg %s alpha %g: default %.15g (bound %.2g), GL over points %.15g\n",
                ToString(v).data(), alpha, def.value, def.bound, sum);
    if (v == SheenVisibility::kAshikhmin)
      std::printf("  adaptive %.15g (bound %.2g)\n", ada.value, ada.bound);
  }
}

// A brute-force rule written here: midpoint in s and phi over the light
// direction, mu_i = sin(pi s / 2)^8 (which flattens Lambda's mu^c branch
// point at mu_i = 0 under the Jacobian and makes s_i analytic at mu_i = 1),
// phi in [0, pi] (even and periodic: the midpoint rule is spectral there).
// At alpha = 0.5 (q = 2: D is analytic at h = n) the integrand is smooth but
// for Lambda's C1 point at mu_i = 1/2. N and 2N cells in s, Richardson
// R = (4 M_2N - M_N) / 3; the quadrature must agree with R within the
// midpoint estimate |M_2N - M_N| (which bounds M_2N's error by 3x when the
// error goes as N^-2).
double BruteForce(SheenVisibility v, double alpha, double mu_o, int n, int m) {
  double sum = 0.0;
  for (int a = 0; a < n; ++a) {
    const double s = (a + 0.5) / n;
    const double sh = std::sin(0.5 * kPi * s);
    const double mu_i = std::pow(sh, 8);
    const double jacobian = 8.0 * std::pow(sh, 7) * std::cos(0.5 * kPi * s) * 0.5 * kPi / n;
    const double w = SheenCosineVisibility(v, alpha, mu_o, mu_i);
    double inner = 0.0;
    for (int b = 0; b < m; ++b) {
      const double phi = kPi * (b + 0.5) / m;
      inner += CharlieDFromDirections(alpha, mu_o, mu_i, std::cos(0.5 * phi));
    }
    sum += jacobian * w * inner * kPi / m;
  }
  return 2.0 * sum;
}

TEST(SheenQuadrature, BruteForceProductRuleAgrees) {
  for (SheenVisibility v :
       {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin, SheenVisibility::kOspray})
    for (double mu : {0.5, 0.8}) {
      const double mN = BruteForce(v, 0.5, mu, 1500, 48), m2N = BruteForce(v, 0.5, mu, 3000, 48);
      const double richardson = (4.0 * m2N - mN) / 3.0, estimate = std::abs(m2N - mN);
      const SheenIntegral r = IntegrateSheenAlbedo(v, 0.5, mu, 1e-10);
      EXPECT_NEAR(r.value, richardson, estimate + r.bound) << ToString(v) << " mu " << mu;
      std::printf(
          "brute force %s alpha 0.5 mu %g: quadrature %.15g, Richardson %.15g (midpoint estimate "
          "%.2g)\n",
          ToString(v).data(), mu, r.value, richardson, estimate);
    }
}

// OSPRay's visibility (Charlie's with the light's Lambda softened): the
// panel rule and the adaptive one (half-vector variables, another rule)
// agree within their bounds over OSPRay's texels and the fit's extremes,
// and the softening changes E by more than either bound.
TEST(SheenQuadrature, OsprayVisibilityTwoRulesAgree) {
  int changed = 0;
  for (double alpha : {0.001, 0.01, 0.0711, 0.3, 0.64, 1.0})
    for (double mu : {1e-6, 1e-3, 1.0 / 15.0, 0.2, 0.5, 0.8, 1.0}) {
      const SheenIntegral panel = IntegrateSheenAlbedo(SheenVisibility::kOspray, alpha, mu, 1e-9);
      const SheenIntegral adaptive =
          IntegrateSheenAlbedoAdaptive(SheenVisibility::kOspray, alpha, mu, 1e-10);
      EXPECT_NEAR(panel.value, adaptive.value, panel.bound + adaptive.bound)
          << "alpha " << alpha << " mu " << mu;
      EXPECT_LE(panel.bound, 1e-9 * std::max(1.0, panel.value));
      const double charlie = IntegrateSheenAlbedo(SheenVisibility::kCharlie, alpha, mu, 1e-9).value;
      if (std::abs(charlie - panel.value) > 1e3 * (panel.bound + 1e-12)) ++changed;
    }
  EXPECT_GT(changed, 20);
}

// Closed forms (ashikhmin). At mu_o = 1, theta_h = theta_i / 2 and W = mu_i / 4,
// so E = (pi K / 2) int_0^(pi/2) sin(t/2)^q cos(t) sin(t) dt: alpha = 1
// (q = 1, K = 3 / (2 pi)): (3/4)(2 sqrt(2) / 15) = sqrt(2) / 10; alpha = 1/4
// (q = 4, K = 6 / (2 pi)): with sin(t/2)^2 = (1 - c)/2, (3/2) int_0^1
// ((1 - c)/2)^2 c dc = (3/2)(1/48) = 1/32. At alpha = 1 and mu_o -> 0,
// E -> 2 / pi (W = 1/4; at mu_o = 1e-15 the O(mu_o log mu_o) difference is
// below 1e-12).
TEST(SheenQuadrature, AshikhminClosedForms) {
  const SheenIntegral one = IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 1.0, 1.0, 1e-10);
  EXPECT_NEAR(one.value, std::sqrt(2.0) / 10.0, one.bound);
  const SheenIntegral quarter = IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 0.25, 1.0, 1e-10);
  EXPECT_NEAR(quarter.value, 1.0 / 32.0, quarter.bound);
  const SheenIntegral grazing =
      IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 1.0, 1e-15, 1e-10);
  EXPECT_NEAR(grazing.value, 2.0 / kPi, grazing.bound + 1e-12);
  const SheenIntegral zero = IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 1.0, 0.0, 1e-10);
  EXPECT_NEAR(zero.value, 2.0 / kPi, zero.bound);
}

// alpha -> 0: E(mu_o > 0) -> 0; alpha = 0 is exact.
TEST(SheenQuadrature, SmoothLimit) {
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin}) {
    const SheenIntegral tiny = IntegrateSheenAlbedo(v, 1e-6, 0.5, 1e-8);
    EXPECT_LE(tiny.value, tiny.bound);
    EXPECT_LE(tiny.bound, 1e-8);
    EXPECT_FALSE(tiny.exact);
    const SheenIntegral zero = IntegrateSheenAlbedo(v, 0.0, 0.5, 1e-8);
    EXPECT_TRUE(zero.exact);
    EXPECT_EQ(zero.value, 0.0);
    EXPECT_EQ(zero.bound, 0.0);
    const SheenIntegral average = IntegrateSheenAlbedoAverage(v, 0.0, 1e-8);
    EXPECT_TRUE(average.exact);
    EXPECT_EQ(average.value, 0.0);
    // E decreases toward 0 along alpha at fixed mu_o = 0.3 (at alpha = 1e-4
    // the lobe is 100x narrower than mu_o: E ~ exp(-(q/2) mu_o^2 / 4) ~ e^-110).
    double previous = 2.0;
    for (double alpha : {0.1, 0.03, 0.01, 3e-3, 1e-3, 3e-4, 1e-4}) {
      const SheenIntegral e = IntegrateSheenAlbedo(v, alpha, 0.3, 1e-9);
      EXPECT_LT(e.value, previous) << alpha;
      previous = e.value + e.bound;
    }
    EXPECT_LT(previous, 1e-40);
  }
}

// Charlie: E ~ C / mu_o at grazing view, mu_o E(mu_o) -> C; at mu_o = 1e-200
// and 1e-250 the two products agree to their bounds (Lambda(mu_o) differs
// from Lambda(0) by ~a b mu_o^c < 1e-30 there).
TEST(SheenQuadrature, CharlieGrowsLikeOneOverMu) {
  for (double alpha : {1.0, 0.1, 1e-4}) {
    const SheenIntegral a = IntegrateSheenAlbedo(SheenVisibility::kCharlie, alpha, 1e-200, 1e-9);
    const SheenIntegral b = IntegrateSheenAlbedo(SheenVisibility::kCharlie, alpha, 1e-250, 1e-9);
    const double ca = a.value * 1e-200, cb = b.value * 1e-250;
    EXPECT_NEAR(ca, cb, a.bound * 1e-200 + b.bound * 1e-250) << alpha;
    EXPECT_GT(ca, 0.0);
    // and E itself is huge, not infinite
    EXPECT_TRUE(std::isfinite(b.value));
    EXPECT_GT(b.value, 1e240);
  }
}

TEST(SheenQuadrature, DomainErrors) {
  for (double alpha : {0.0, 1e-6, 0.5, 1.0}) {
    EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kCharlie, alpha, 0.0, 1e-8),
                 std::domain_error);
    EXPECT_THROW(IntegrateSheenAlbedoAdaptive(SheenVisibility::kCharlie, alpha, 0.0, 1e-8),
                 std::domain_error);
  }
  EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 0.0, 0.0, 1e-8),
               std::domain_error);
  EXPECT_NO_THROW(IntegrateSheenAlbedo(SheenVisibility::kAshikhmin, 1e-6, 0.0, 1e-8));
  EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kCharlie, -0.1, 0.5, 1e-8),
               std::invalid_argument);
  EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kCharlie, 0.5, 1.5, 1e-8),
               std::invalid_argument);
  EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kCharlie, 0.5, std::nan(""), 1e-8),
               std::invalid_argument);
  EXPECT_THROW(IntegrateSheenAlbedo(SheenVisibility::kCharlie, 0.5, 0.5, 0.0),
               std::invalid_argument);
}

// No NaN or Inf anywhere on a dense extreme grid, and every bound at its target.
TEST(SheenQuadrature, ExtremeGridIsFinite) {
  const double alphas[] = {1e-24, 1e-20, 1e-16, 1e-12, 1e-8, 1e-6, 1e-4, 1e-3, 0.01, 0.1, 0.5, 1.0};
  const double mus[] = {1e-300, 1e-200, 1e-100, 1e-30, 1e-16, 1e-12, 1e-8,     1e-6,
                        1e-4,   1e-3,   0.01,   0.1,   0.5,   0.9,   0.999999, 1.0};
  for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin})
    for (double alpha : alphas)
      for (double mu : mus) {
        const SheenIntegral r = IntegrateSheenAlbedo(v, alpha, mu, 1e-8);
        EXPECT_TRUE(std::isfinite(r.value) && std::isfinite(r.bound))
            << ToString(v) << " alpha " << alpha << " mu " << mu;
        EXPECT_GE(r.value, 0.0);
        EXPECT_LE(r.bound, 1e-8 * std::max(1.0, r.value))
            << ToString(v) << " alpha " << alpha << " mu " << mu;
      }
}

// The same bits on every call, in any thread (the node caches are per thread).
TEST(SheenQuadrature, BitIdenticalAcrossCalls) {
  const auto run = [] {
    std::vector<double> out;
    for (SheenVisibility v : {SheenVisibility::kCharlie, SheenVisibility::kAshikhmin})
      for (double alpha : {1e-5, 0.3, 1.0})
        for (double mu : {1e-9, 0.2, 0.7}) {
          const SheenIntegral r = IntegrateSheenAlbedo(v, alpha, mu, 1e-8);
          out.push_back(r.value);
          out.push_back(r.bound);
        }
    out.push_back(IntegrateSheenAlbedoAverage(SheenVisibility::kCharlie, 0.3, 1e-7).value);
    return out;
  };
  const std::vector<double> first = run(), second = run();
  std::vector<double> third;
  std::thread([&] { third = run(); }).join();
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(first.data(), third.data(), first.size() * sizeof(double)), 0);
}

}  // namespace
}  // namespace lutbake
