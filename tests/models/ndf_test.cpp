// The two NDFs and their visible-normal samplers: D and Lambda agree (the
// projected-area identity), the visible-normal pdf integrates to 1, and the
// samplers draw from that pdf (chi-square).
#include "lutbake/models/ndf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lutbake/core/hash.h"
#include "lutbake/integrators/gauss_kronrod.h"

namespace lutbake {
namespace {

// Integral of pdf(theta, phi) sin(theta) over a (theta, phi) rectangle, for
// a pdf with the factor max(0, o.h): the phi integral is split where o.h = 0,
// cos(phi) = -mu cos(theta) / (s sin(theta)), so that no piece holds a kink.
template <typename Pdf>
double IntegrateOverBin(const Pdf &pdf, double mu, double t0, double t1, double p0, double p1) {
  const double s = std::sqrt((1.0 - mu) * (1.0 + mu));
  return IntegrateAdaptive(
             [&](double theta) {
               std::vector<double> cuts = {p0};
               const double c = -mu * std::cos(theta) / (s * std::sin(theta));
               if (std::abs(c) < 1.0) {
                 for (double k : {std::acos(c), 2.0 * kPi - std::acos(c)})
                   if (k > p0 && k < p1) cuts.push_back(k);
               }
               std::sort(cuts.begin(), cuts.end());
               cuts.push_back(p1);
               double sum = 0.0;
               for (size_t i = 0; i + 1 < cuts.size(); ++i)
                 sum += IntegrateAdaptive([&](double phi) { return pdf(theta, phi); }, cuts[i],
                                          cuts[i + 1], 1e-14, 0.0, 4)
                            .value;
               return std::sin(theta) * sum;
             },
             t0, t1, 1e-12, 0.0, 4)
      .value;
}

Vec3 Direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Regularised upper incomplete gamma Q(a, x): the chi-square survival
// function is Q(dof / 2, chi2 / 2). Series below a + 1, continued fraction above.
double UpperIncompleteGamma(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double logPrefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (term < sum * 1e-16) break;
    }
    return 1.0 - sum * std::exp(logPrefix);
  }
  // Lentz's method for the continued fraction of Q.
  double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
  for (int n = 1; n < 1000; ++n) {
    const double an = -n * (n - a);
    b += 2.0;
    d = an * d + b;
    c = b + an / c;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(logPrefix) * h;
}

TEST(ChiSquare, SurvivalFunctionKnownValues) {
  // chi2 with 2 dof: Q = exp(-x/2). With 10 dof, P(chi2 > 23.209) = 0.01.
  EXPECT_NEAR(UpperIncompleteGamma(1.0, 1.5), std::exp(-1.5), 1e-14);
  EXPECT_NEAR(UpperIncompleteGamma(5.0, 23.209 / 2.0), 0.01, 1e-5);
}

struct Case {
  NdfKind kind;
  double alpha, mu;
};

class VisibleNormals : public ::testing::TestWithParam<Case> {};

TEST_P(VisibleNormals, ProjectedAreaIdentity) {
  // integral of D(h) max(0, o.h) d(omega_h) = mu_o + mu_o Lambda(mu_o): ties D
  // to Lambda, so it checks both (and the erf form of Beckmann's Lambda).
  const Case c = GetParam();
  const Ndf ndf{c.kind, c.alpha};
  const Vec3 o = ViewDirection(c.mu);
  const double projected = IntegrateOverBin(
      [&](double theta, double phi) {
        return std::max(0.0, Dot(o, Direction(theta, phi))) * ndf.D(Direction(theta, phi));
      },
      c.mu, 0.0, 0.5 * kPi, 0.0, 2.0 * kPi);
  EXPECT_NEAR(projected, c.mu + ndf.MuLambda(c.mu), 1e-7);
}

TEST_P(VisibleNormals, SamplerMatchesPdfChiSquare) {
  const Case c = GetParam();
  const Ndf ndf{c.kind, c.alpha};
  const Vec3 o = ViewDirection(c.mu);
  constexpr int kThetaBins = 16, kPhiBins = 16;
  constexpr int kSamples = 200000;
  // Bins in theta over the range that holds most of the mass, atan(6 alpha) + 0.2
  // capped at pi/2; one more cell holds everything beyond.
  const double thetaMax = std::min(0.5 * kPi, std::atan(6.0 * c.alpha) + 0.2);
  std::vector<double> expected(kThetaBins * kPhiBins + 1, 0.0);
  double total = 0.0;
  for (int i = 0; i < kThetaBins; ++i)
    for (int j = 0; j < kPhiBins; ++j) {
      const double p = IntegrateOverBin(
          [&](double theta, double phi) { return ndf.VisibleNormalPdf(o, Direction(theta, phi)); },
          c.mu, thetaMax * i / kThetaBins, thetaMax * (i + 1) / kThetaBins,
          2.0 * kPi * j / kPhiBins, 2.0 * kPi * (j + 1) / kPhiBins);
      expected[i * kPhiBins + j] = p;
      total += p;
    }
  const double beyond = IntegrateOverBin(
      [&](double theta, double phi) { return ndf.VisibleNormalPdf(o, Direction(theta, phi)); },
      c.mu, thetaMax, 0.5 * kPi, 0.0, 2.0 * kPi);
  expected.back() = beyond;
  // The pdf integrates to 1 over the hemisphere.
  EXPECT_NEAR(total + beyond, 1.0, 1e-7);

  std::vector<double> observed(expected.size(), 0.0);
  RandomStream rng(HashValues({static_cast<uint64_t>(c.kind), static_cast<uint64_t>(c.alpha * 1e6),
                               static_cast<uint64_t>(c.mu * 1e6)}));
  for (int s = 0; s < kSamples; ++s) {
    const Vec3 h = ndf.SampleVisibleNormal(o, rng.NextDouble(), rng.NextDouble());
    ASSERT_TRUE(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z));
    ASSERT_NEAR(Dot(h, h), 1.0, 1e-12);
    const double theta = std::acos(std::min(1.0, h.z));
    double phi = std::atan2(h.y, h.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    if (theta >= thetaMax) {
      observed.back() += 1.0;
      continue;
    }
    const int i = std::min(kThetaBins - 1, static_cast<int>(theta / thetaMax * kThetaBins));
    const int j = std::min(kPhiBins - 1, static_cast<int>(phi / (2.0 * kPi) * kPhiBins));
    observed[i * kPhiBins + j] += 1.0;
  }
  // Pool cells with fewer than 5 expected samples, then the statistic.
  double chi2 = 0.0, pooledExpected = 0.0, pooledObserved = 0.0;
  int cells = 0;
  for (size_t k = 0; k < expected.size(); ++k) {
    const double e = expected[k] * kSamples;
    if (e < 5.0) {
      pooledExpected += e;
      pooledObserved += observed[k];
      continue;
    }
    chi2 += Sqr(observed[k] - e) / e;
    ++cells;
  }
  if (pooledExpected > 0.0) {
    chi2 += Sqr(pooledObserved - pooledExpected) / std::max(pooledExpected, 1.0);
    ++cells;
  }
  const double pValue = UpperIncompleteGamma(0.5 * (cells - 1), 0.5 * chi2);
  // Significance 1e-4 per case: a correct sampler fails one of the 12 cases
  // with probability about 1e-3.
  EXPECT_GT(pValue, 1e-4) << "chi2 = " << chi2 << " over " << cells << " cells";
}

INSTANTIATE_TEST_SUITE_P(
    Ndfs, VisibleNormals,
    ::testing::Values(Case{NdfKind::kGgx, 0.05, 0.3}, Case{NdfKind::kGgx, 0.3, 0.05},
                      Case{NdfKind::kGgx, 0.6, 0.7}, Case{NdfKind::kGgx, 1.0, 1.0},
                      Case{NdfKind::kGgx, 1.0, 0.01}, Case{NdfKind::kGgx, 0.2, 0.95},
                      Case{NdfKind::kBeckmann, 0.05, 0.3}, Case{NdfKind::kBeckmann, 0.3, 0.05},
                      Case{NdfKind::kBeckmann, 0.6, 0.7}, Case{NdfKind::kBeckmann, 1.0, 1.0},
                      Case{NdfKind::kBeckmann, 1.0, 0.01}, Case{NdfKind::kBeckmann, 0.2, 0.95}));

TEST(Ndf, BeckmannStaysFiniteAtTinyAlpha) {
  // Tiny alpha: D at the peak is 1 / (pi alpha^2), Lambda vanishes away from grazing.
  const Ndf ndf{NdfKind::kBeckmann, 1e-8};
  EXPECT_NEAR(ndf.D({0, 0, 1}) * kPi * 1e-16, 1.0, 1e-12);
  EXPECT_EQ(ndf.MuLambda(0.5), 0.0);
  EXPECT_NEAR(ndf.MuLambda(0.0), 1e-8 / (2.0 * std::sqrt(kPi)), 1e-22);
  const Vec3 h = ndf.SampleVisibleNormal(ViewDirection(0.3), 0.37, 0.81);
  EXPECT_TRUE(std::isfinite(h.x) && h.z > 0.999999);
}

}  // namespace
}  // namespace lutbake
