#include "lutbake/models/oren_nayar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/azimuth_rule.h"

namespace lutbake {
namespace {

TEST(OrenNayar, ClosedFormAzimuthMatchesTheBrdf) {
  // The closed-form ring cos(theta_i) int f dphi against Gauss-Legendre over
  // phi of the BRDF itself, split at pi/2 where cos(dphi) changes sign (the
  // BRDF is a polynomial in cos(phi) on each side, so 64 nodes are exact to
  // rounding).
  for (OrenNayarVariant variant : {OrenNayarVariant::kFull, OrenNayarVariant::kQualitative})
    for (double sigma : {0.0, 0.2, 0.7, 1.5})
      for (double theta_o : {0.0, 0.3, 1.0, 1.5})
        for (double theta_i : {0.05, 0.3, 0.9, 1.2, 1.55}) {
          const double brute = std::cos(theta_i) * test::AzimuthIntegral(
                                                       [&](const Vec3 &o, const Vec3 &i) {
                                                         return OrenNayarBrdf(variant, sigma, o, i);
                                                       },
                                                       theta_o, theta_i, {0.0, 0.5 * kPi, kPi});
          EXPECT_NEAR(OrenNayarCosineRing(variant, sigma, theta_o, theta_i), brute, 1e-13)
              << ToString(variant) << " sigma " << sigma << " " << theta_o << " " << theta_i;
        }
}

TEST(OrenNayar, SmoothIsLambert) {
  // sigma = 0: A = C1 = 1 and every other term vanishes.
  const Vec3 o{0.6, 0.0, 0.8}, i{-0.3, 0.5, std::sqrt(1.0 - 0.34)};
  EXPECT_DOUBLE_EQ(OrenNayarBrdf(OrenNayarVariant::kFull, 0.0, o, i), kInvPi);
  EXPECT_DOUBLE_EQ(OrenNayarBrdf(OrenNayarVariant::kQualitative, 0.0, o, i), kInvPi);
}

TEST(OrenNayar, Reciprocal) {
  const Vec3 o{0.6, 0.0, 0.8}, i{-0.3, 0.5, std::sqrt(1.0 - 0.34)};
  for (OrenNayarVariant variant : {OrenNayarVariant::kFull, OrenNayarVariant::kQualitative})
    EXPECT_NEAR(OrenNayarBrdf(variant, 0.8, o, i), OrenNayarBrdf(variant, 0.8, i, o), 1e-15);
}

}  // namespace
}  // namespace lutbake
