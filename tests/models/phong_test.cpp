#include "lutbake/models/phong.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/models/blinn_phong.h"

namespace lutbake {
namespace {

TEST(Phong, ConeIntegralMatchesBruteForce) {
  // W(u) = int_0^2pi max(0, n.i) db over the cone at cos(a) = u about the
  // mirror direction, against Gauss-Legendre on [0, b_max] with b_max, where
  // n.i changes sign, found by bisection (n.i is a trigonometric polynomial
  // of degree 1 there: 48 nodes are exact to rounding).
  const GaussLegendreRule &rule = GaussLegendre(48);
  for (double mu_o : {0.0, 0.2, 0.7, 1.0})
    for (double u : {0.01, 0.3, 0.6, 0.95, 1.0}) {
      const double s_o = std::sqrt(1.0 - mu_o * mu_o), sinA = std::sqrt(1.0 - u * u);
      const Vec3 r{-s_o, 0.0, mu_o}, t1{mu_o, 0.0, s_o}, t2{0.0, 1.0, 0.0};
      const auto nDotI = [&](double b) {
        return u * r.z + sinA * (std::cos(b) * t1.z + std::sin(b) * t2.z);
      };
      // n.i is even in b and decreasing on [0, pi]: its zero by bisection.
      double lo = 0.0, hi = kPi;
      if (nDotI(kPi) >= 0.0)
        lo = kPi;
      else if (nDotI(0.0) <= 0.0)
        hi = 0.0;
      for (int k = 0; k < 200 && hi > lo; ++k) {
        const double mid = 0.5 * (lo + hi);
        (nDotI(mid) > 0.0 ? lo : hi) = mid;
      }
      double sum = 0.0;
      for (int j = 0; j < rule.n; ++j) sum += lo * rule.w[j] * nDotI(lo * rule.x[j]);
      EXPECT_NEAR(PhongConeIntegral(mu_o, u), 2.0 * sum, 1e-13) << mu_o << " " << u;
    }
}

TEST(Phong, Normalisations) {
  EXPECT_DOUBLE_EQ(PhongNormalisationFactor(PhongNormalisation::kNPlus2, 10.0), 12.0 / (2 * kPi));
  EXPECT_DOUBLE_EQ(PhongNormalisationFactor(PhongNormalisation::kNPlus1, 10.0), 11.0 / (2 * kPi));
  // The Phong lobe peaks at the mirror direction.
  const Vec3 o{0.6, 0.0, 0.8}, mirror{-0.6, 0.0, 0.8};
  EXPECT_DOUBLE_EQ(PhongBrdf(PhongNormalisation::kNone, 50.0, o, mirror), 1.0);
}

TEST(BlinnPhong, RingIntegralMatchesBruteForce) {
  // P(u) = int 4 (o.h) max(0, mu_i) dp against Gauss-Legendre on [0, p_max]
  // with p_max found by bisection.
  const GaussLegendreRule &rule = GaussLegendre(48);
  for (double mu_o : {0.0, 0.2, 0.7, 1.0})
    for (double u : {0.05, 0.4, 0.7, 0.95, 1.0}) {
      const double s_o = std::sqrt(1.0 - mu_o * mu_o), sinH = std::sqrt(1.0 - u * u);
      const auto integrand = [&](double p) {
        const double oh = s_o * sinH * std::cos(p) + mu_o * u;
        return 4.0 * oh * (2.0 * oh * u - mu_o);
      };
      double lo = 0.0, hi = kPi;
      if (integrand(kPi) >= 0.0 && 2.0 * (mu_o * u - s_o * sinH) * u >= mu_o)
        lo = kPi;
      else if (2.0 * (mu_o * u + s_o * sinH) * u <= mu_o)
        hi = 0.0;
      for (int k = 0; k < 200 && hi > lo; ++k) {
        const double mid = 0.5 * (lo + hi);
        const double oh = s_o * sinH * std::cos(mid) + mu_o * u;
        (2.0 * oh * u - mu_o > 0.0 ? lo : hi) = mid;
      }
      double sum = 0.0;
      for (int j = 0; j < rule.n; ++j) sum += lo * rule.w[j] * integrand(lo * rule.x[j]);
      EXPECT_NEAR(BlinnPhongRingIntegral(mu_o, u), 2.0 * sum, 1e-12) << mu_o << " " << u;
    }
}

TEST(BlinnPhong, ExactNormalisationClosedForm) {
  // n = 0 is Lambert (1 / pi); n = 2: (4 * 6) / (8 pi (2 + 1/2)) = 6 / (5 pi).
  EXPECT_NEAR(BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kExact, 0.0), kInvPi, 1e-16);
  EXPECT_NEAR(BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kExact, 2.0),
              6.0 / (5.0 * kPi), 1e-16);
  // The horizon breaks: at normal incidence both are cos(45 degrees).
  const BlinnPhongBreaks b = BlinnPhongHorizonBreaks(1.0);
  EXPECT_NEAR(b.none, std::sqrt(0.5), 3e-16);
  EXPECT_NEAR(b.full, std::sqrt(0.5), 3e-16);
}

}  // namespace
}  // namespace lutbake
