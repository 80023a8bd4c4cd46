// The light-direction rule (integrators/light_direction_rule.h): over the
// hemisphere against the cosine's integral and the closed-form diffuse
// albedos (Burley's, tables/burley_E.cpp's formula, written out here again),
// over polygons against the closed-form projected solid angle (models/ltc.h)
// and additivity, and its nodes' half vectors.
#include "lutbake/integrators/light_direction_rule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lutbake/integrators/furnace.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/models/burley.h"
#include "lutbake/models/ltc.h"
#include "lutbake/models/oren_nayar.h"

namespace lutbake {
namespace {

double Integrate(const std::vector<LtcNode> &nodes, const std::function<double(const Vec3 &)> &g) {
  double sum = 0.0;
  for (const LtcNode &n : nodes) sum += n.weight * g(n.l);
  return sum;
}

// int cos / pi = 1 and int (1 - v.h)^5 of the cosine, on both circles; the
// half vectors are normalize(v + l). Burley's albedo against its closed form
// (burley_E.cpp: (492 + 6 r (4 + mu) + (1 - mu)^5 (-246 + 6 r (80 + 55 mu) +
// r^2 (35 + 12 mu - 9 mu^2))) / 504), every level.
TEST(LightDirectionRule, HemisphereIntegrals) {
  for (double mu : {0.0, 0.02, 0.3, 0.7, 1.0}) {
    const Vec3 v = ViewDirection(mu);
    for (int level : {0, 1, 2})
      for (bool half : {true, false}) {
        const std::vector<LtcNode> nodes = LightDirectionRule(mu, level, half);
        EXPECT_NEAR(Integrate(nodes, [](const Vec3 &l) { return l.z * kInvPi; }), 1.0, 1e-13);
        for (const LtcNode &n : nodes) {
          const Vec3 h = Normalize({v.x + n.l.x, v.y + n.l.y, v.z + n.l.z});
          EXPECT_NEAR(Dot(h, n.h), 1.0, 1e-14);
          EXPECT_GE(n.l.z, 0.0);
        }
        for (double r : {0.0, 0.5, 1.0}) {
          const double t = 1.0 - mu, b = t * t * t * t * t;
          const double exact = (492.0 + 6.0 * r * (4.0 + mu) +
                                b * (-246.0 + 6.0 * r * (80.0 + 55.0 * mu) +
                                     r * r * (35.0 + 12.0 * mu - 9.0 * mu * mu))) /
                               504.0;
          EXPECT_NEAR(
              Integrate(nodes, [&](const Vec3 &l) { return BurleyDiffuseBrdf(r, v, l) * l.z; }),
              exact, level == 0 ? 1e-9 : 1e-12)
              << mu << " " << r << " " << level;
        }
      }
  }
}

// Oren-Nayar (kinks at theta_i = theta_o and cos(dphi) = 0, where the
// panels are cut) against the furnace's integrator (the azimuth in closed
// form, adaptive over theta_i) to its bound.
TEST(LightDirectionRule, OrenNayarAlbedo) {
  FurnaceModel model;
  model.kind = FurnaceModelKind::kOrenNayar;
  model.orenNayar = OrenNayarVariant::kQualitative;
  for (double sigma : {0.2, 0.8, 1.5})
    for (double mu : {0.05, 0.4, 0.9, 1.0}) {
      const Vec3 v = ViewDirection(mu);
      const FurnacePoint p = FurnaceIntegrator(model, sigma).Albedo(mu);
      for (int level : {0, 1, 2}) {
        const double q = Integrate(LightDirectionRule(mu, level, true), [&](const Vec3 &l) {
          return OrenNayarBrdf(OrenNayarVariant::kQualitative, sigma, v, l) * l.z;
        });
        EXPECT_NEAR(q, p.albedo.value, (level == 0 ? 1e-7 : 1e-10) + p.albedo.error)
            << sigma << " " << mu << " " << level;
      }
    }
}

// Polygons: the cosine over each test rectangle (5 cross the horizon) is the
// clipped polygon's projected solid angle / pi; a rectangle is the sum of
// its halves; a huge square at height 1 holds all but the last 1e-4 radians.
TEST(LightDirectionRule, PolygonIntegrals) {
  const LtcMatrix identity;
  const auto cosine = [](const Vec3 &l) { return l.z * kInvPi; };
  for (double mu : {0.0, 0.3, 1.0})
    for (int level : {0, 1, 2})
      for (const LtcRectangle &r : LtcTestRectangles()) {
        const double exact = LtcPolygonIntegral(identity, r.vertices, 4, true);
        EXPECT_NEAR(Integrate(LightDirectionPolygonRule(mu, level, r.vertices, 4), cosine), exact,
                    level == 0 ? 2e-7 : 2e-9)
            << mu << " " << level;
      }
  const LtcRectangle &rect = LtcTestRectangles()[2];
  const Vec3 *v = rect.vertices;
  const Vec3 m01{0.5 * (v[0].x + v[1].x), 0.5 * (v[0].y + v[1].y), 0.5 * (v[0].z + v[1].z)};
  const Vec3 m23{0.5 * (v[2].x + v[3].x), 0.5 * (v[2].y + v[3].y), 0.5 * (v[2].z + v[3].z)};
  const Vec3 a[4] = {v[0], m01, m23, v[3]}, b[4] = {m01, v[1], v[2], m23};
  const Vec3 view = ViewDirection(0.4);
  const auto burley = [&](const Vec3 &l) { return BurleyDiffuseBrdf(0.7, view, l) * l.z; };
  EXPECT_NEAR(Integrate(LightDirectionPolygonRule(0.4, 1, v, 4), burley),
              Integrate(LightDirectionPolygonRule(0.4, 1, a, 4), burley) +
                  Integrate(LightDirectionPolygonRule(0.4, 1, b, 4), burley),
              1e-9);
  const Vec3 big[4] = {{1e4, 1e4, 1}, {-1e4, 1e4, 1}, {-1e4, -1e4, 1}, {1e4, -1e4, 1}};
  EXPECT_NEAR(Integrate(LightDirectionPolygonRule(0.4, 1, big, 4), burley),
              Integrate(LightDirectionRule(0.4, 1, false), burley), 2e-4);
}

}  // namespace
}  // namespace lutbake
