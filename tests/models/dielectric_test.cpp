// The rough-dielectric model: its Fresnel against the complex-index form,
// Snell's law, the generalised half vector, the refraction Jacobian against
// a finite solid-angle ratio, the BSDF's reciprocity, the closed forms.
#include "lutbake/models/dielectric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lutbake/models/fresnel.h"

namespace lutbake {
namespace {

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Vec3 UnitFromAngles(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The textbook form in long double (64-bit mantissa): r_s = (c - w) / (c +
// w), r_p = (eta^2 c - w) / (eta^2 c + w), w = sqrt(eta^2 - 1 + c^2).
double LongDoubleFresnel(double eta, double c) {
  const long double e = eta, cc = c, w2 = e * e - 1.0L + cc * cc;
  if (w2 <= 0.0L) return 1.0;
  const long double w = std::sqrt(w2);
  const long double rs = (cc - w) / (cc + w), rp = (e * e * cc - w) / (e * e * cc + w);
  return static_cast<double>(0.5L * (rs * rs + rp * rp));
}

// F from the rewritten forms equals the textbook form in long double to
// a few ulps (ExactFresnel's c - w cancels as eta -> 1 and c -> 0:
// 6e-14 off at eta = 1 - 1e-6, c = 0.005, so it is compared more loosely),
// F + (1 - F) = 1 to a few ulps, both sides, through total internal reflection.
TEST(DielectricModel, FresnelMatchesExactForm) {
  for (double eta : {0.25, 1.0 / 2.42, 1.0 / 1.5, 0.999999, 1.0, 1.000001, 1.33, 1.5, 2.42, 4.0})
    for (int k = 0; k <= 200; ++k) {
      const double c = k / 200.0;
      const DielectricFresnelTerms f = DielectricFresnel(eta, c);
      // Just above the critical cosine dF/dc is unbounded: rounding c^2 alone
      // moves F by ~1e-15 there, hence an absolute 4e-15.
      EXPECT_NEAR(f.F, LongDoubleFresnel(eta, c), 4e-15) << eta << " " << c;
      EXPECT_NEAR(f.F, ExactFresnel(eta, 0.0, c), 1e-13) << eta << " " << c;
      EXPECT_NEAR(f.F + f.T, 1.0, 2e-15) << eta << " " << c;
      EXPECT_GE(f.T, 0.0);
    }
  // eta = 1: no reflection at all (c > 0).
  EXPECT_EQ(DielectricFresnel(1.0, 0.3).F, 0.0);
  // Total internal reflection: c below sqrt(1 - eta^2).
  EXPECT_EQ(DielectricFresnel(0.5, 0.8).T, 0.0);
  EXPECT_GT(DielectricFresnel(0.5, 0.9).T, 0.0);
}

// Snell: eta sin(theta_t) = sin(theta_o) about h, i on the far side of the
// facet, unit length; the generalised half vector recovers h; eta = 1
// passes o straight through.
TEST(DielectricModel, RefractionObeysSnell) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double eta : {1.0 / 2.42, 1.0 / 1.33, 1.0, 1.33, 2.42})
    for (int k = 0; k < 200; ++k) {
      const Vec3 h = UnitFromAngles(1.2 * u(rng), 2.0 * kPi * u(rng));
      const Vec3 o = UnitFromAngles(0.5 * kPi * u(rng), 2.0 * kPi * u(rng));
      const double c = Dot(o, h);
      if (!(c > 0.0)) continue;
      Vec3 i;
      if (!Refract(o, h, eta, &i)) {
        EXPECT_LT(eta, 1.0);
        EXPECT_LE(c * c, 1.0 - eta * eta + 1e-15);
        continue;
      }
      EXPECT_NEAR(Dot(i, i), 1.0, 1e-14);
      const double ih = Dot(i, h);
      EXPECT_LT(ih, 0.0);
      const double sinO = std::sqrt(std::max(0.0, 1.0 - c * c));
      const double sinT = std::sqrt(std::max(0.0, 1.0 - ih * ih));
      EXPECT_NEAR(eta * sinT, sinO, 1e-13);
      // i, o and h coplanar.
      EXPECT_NEAR(Dot(Cross(o, h), i), 0.0, 1e-14);
      if (h.z > 0.0 && std::abs(eta - 1.0) > 1e-3) {
        const Vec3 hb = RefractionHalfVector(o, i, eta);
        EXPECT_NEAR(Dot(hb, h), 1.0, 1e-12);
      }
      if (eta == 1.0) {
        EXPECT_EQ(i.x, -o.x);
        EXPECT_EQ(i.y, -o.y);
        EXPECT_EQ(i.z, -o.z);
      }
    }
}

// d(omega_h) / d(omega_i) = eta^2 |i.h| / (o.h + eta i.h)^2: the ratio of
// the solid angles of a small triangle of facet normals and of its image
// under refraction (spherical excess ~ planar area at this size; the
// tolerance is the triangle's relative size squared, 1e-8, times 100).
TEST(DielectricModel, RefractionJacobianMatchesSolidAngles) {
  const double eps = 1e-4;
  for (double eta : {1.0 / 2.42, 1.0 / 1.33, 1.33, 2.42}) {
    const Vec3 o = UnitFromAngles(0.4, 0.3);
    const Vec3 h = UnitFromAngles(0.2, 1.1);
    Vec3 t1 = Normalize(Cross(h, {0.0, 0.0, 1.0}));
    Vec3 t2 = Cross(h, t1);
    const Vec3 hs[3] = {h, Normalize({h.x + eps * t1.x, h.y + eps * t1.y, h.z + eps * t1.z}),
                        Normalize({h.x + eps * t2.x, h.y + eps * t2.y, h.z + eps * t2.z})};
    Vec3 is[3];
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(Refract(o, hs[k], eta, &is[k]));
    const auto area = [](const Vec3 *v) {
      const Vec3 a{v[1].x - v[0].x, v[1].y - v[0].y, v[1].z - v[0].z};
      const Vec3 b{v[2].x - v[0].x, v[2].y - v[0].y, v[2].z - v[0].z};
      const Vec3 n = Cross(a, b);
      return 0.5 * std::sqrt(Dot(n, n));
    };
    const double ratio = area(hs) / area(is);
    const double J = RefractionJacobian(eta, Dot(o, h), Dot(is[0], h));
    EXPECT_NEAR(ratio / J, 1.0, 1e-3) << eta;
    // Reflection: 1 / (4 o.h), the same way.
    Vec3 rs[3];
    for (int k = 0; k < 3; ++k) rs[k] = Reflect(o, hs[k]);
    EXPECT_NEAR(area(hs) / area(rs) / ReflectionJacobian(Dot(o, h)), 1.0, 1e-3) << eta;
  }
}

// f_t,eta(o, i) = eta^2 f_t,1/eta(i, o) for the eta^2-free BSDF, with the
// reverse path seen from the far side (z mirrored), both NDFs and Smith forms.
TEST(DielectricModel, TransmissionBsdfReciprocity) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (NdfKind kind : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable})
      for (double eta : {1.33, 1.5, 2.42, 1.0 / 1.5})
        for (int k = 0; k < 200; ++k) {
          const Ndf ndf{kind, 0.3};
          const Vec3 o = UnitFromAngles(0.5 * kPi * u(rng), 0.0);
          const Vec3 i = UnitFromAngles(0.5 * kPi * (1.0 + u(rng)), 2.0 * kPi * u(rng));
          const auto lobes = DielectricLobes::kReflectionAndTransmission;
          const double forward = DielectricBsdfCosine(ndf, smith, lobes, eta, o, i) / std::abs(i.z);
          const Vec3 o2{i.x, i.y, -i.z}, i2{o.x, o.y, -o.z};
          const double backward =
              DielectricBsdfCosine(ndf, smith, lobes, 1.0 / eta, o2, i2) / std::abs(i2.z);
          EXPECT_NEAR(forward, eta * eta * backward, 1e-12 * (1.0 + forward)) << eta;
          checked += forward > 0.0;
        }
  EXPECT_GT(checked, 500);
}

// Every facet weight lies in [0, 1].
TEST(DielectricModel, FacetWeightIsBounded) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (NdfKind kind : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable})
      for (double eta : {0.3, 1.0 / 1.33, 1.0, 1.5, 3.0})
        for (int k = 0; k < 2000; ++k) {
          const Ndf ndf{kind, u(rng)};
          const double mu_o = u(rng);
          const Vec3 o = ViewDirection(mu_o);
          const Vec3 h = ndf.SampleVisibleNormal(o, u(rng), u(rng));
          const double c = Dot(o, h);
          const double w =
              DielectricFacetWeight(ndf, smith, DielectricLobes::kReflectionAndTransmission, eta,
                                    mu_o, ndf.MuLambda(mu_o), c, h.z, 2.0 * c * h.z - mu_o);
          EXPECT_GE(w, 0.0);
          EXPECT_LE(w, 1.0);
        }
}

// eta = 1: (1 + Lambda) / (1 + 2 Lambda) correlated, G1 separable, from
// Lambda = L / mu; alpha = 0: 1 and F(mu_o).
TEST(DielectricModel, ClosedForms) {
  for (NdfKind kind : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (double mu : {0.05, 0.3, 0.8, 1.0}) {
      const Ndf ndf{kind, 0.5};
      const double lambda = ndf.MuLambda(mu) / mu;
      EXPECT_NEAR(DielectricIndexMatchedAlbedo(ndf, SmithForm::kCorrelated,
                                               DielectricLobes::kReflectionAndTransmission, mu),
                  (1.0 + lambda) / (1.0 + 2.0 * lambda), 1e-15);
      EXPECT_NEAR(DielectricIndexMatchedAlbedo(ndf, SmithForm::kSeparable,
                                               DielectricLobes::kReflectionAndTransmission, mu),
                  1.0 / (1.0 + lambda), 1e-15);
      EXPECT_EQ(DielectricIndexMatchedAlbedo(ndf, SmithForm::kCorrelated,
                                             DielectricLobes::kReflection, mu),
                0.0);
      EXPECT_EQ(DielectricSmoothAlbedo(DielectricLobes::kReflectionAndTransmission, 1.5, mu), 1.0);
      EXPECT_NEAR(DielectricSmoothAlbedo(DielectricLobes::kReflection, 1.5, mu),
                  ExactFresnel(1.5, 0.0, mu), 4e-15);
    }
}

}  // namespace
}  // namespace lutbake
