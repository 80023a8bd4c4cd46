// The LTC distribution (models/ltc.h) against independent quadratures: its
// integral over the sphere, its leakage below the horizon and its integral
// over polygons (clipped at either horizon), each by Gauss rules on domains
// where the integrand is smooth, so that the rules converge to ~1e-12.
#include "lutbake/models/ltc.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "lutbake/integrators/gauss_legendre.h"

namespace lutbake {
namespace {

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 Add(const Vec3 &a, const Vec3 &b, double t = 1.0) {
  return {a.x + t * b.x, a.y + t * b.y, a.z + t * b.z};
}

// Random inverse matrices with det > 0 and moderate anisotropy (D stays
// within a few orders of magnitude of 1/pi, so the rules below converge).
std::vector<LtcMatrix> RandomMatrices(int count) {
  std::mt19937_64 rng(28);
  std::uniform_real_distribution<double> diag(0.3, 2.0), off(-0.6, 0.6);
  std::vector<LtcMatrix> out;
  while (static_cast<int>(out.size()) < count) {
    const LtcMatrix m{diag(rng), off(rng), off(rng), diag(rng)};
    if (m.Determinant() > 0.2) out.push_back(m);
  }
  return out;
}

// int of g over the directions l = (cos b sin c, cos c, sin b sin c) with b in
// [b0, b1] and c in [0, pi]: the lunes between two planes through the y-axis.
// Both horizons (l.z = 0 and (M^-1 l).z = m20 l.x + m22 l.z = 0) are such
// planes, so every region below is a union of lunes and the integrand is
// smooth on each: 8 x 8 panels of 24 x 24 Gauss nodes (converged to ~1e-14
// for these matrices: halving the panels changes the results by < 1e-12).
template <typename G>
double IntegrateLune(double b0, double b1, G &&g) {
  const GaussLegendreRule &rule = GaussLegendre(24);
  constexpr int kPanels = 8;
  double sum = 0.0;
  for (int pb = 0; pb < kPanels; ++pb)
    for (int pc = 0; pc < kPanels; ++pc)
      for (int i = 0; i < rule.n; ++i) {
        const double b = b0 + (b1 - b0) * (pb + rule.x[i]) / kPanels;
        for (int k = 0; k < rule.n; ++k) {
          const double c = kPi * (pc + rule.x[k]) / kPanels;
          const Vec3 l{std::cos(b) * std::sin(c), std::cos(c), std::sin(b) * std::sin(c)};
          sum += rule.w[i] * rule.w[k] * g(l) * std::sin(c);
        }
      }
  return sum * (b1 - b0) * kPi / (kPanels * kPanels);
}

// The b-interval where (M^-1 l).z > 0: m20 cos b + m22 sin b > 0, i.e.
// b in (beta - pi/2, beta + pi/2) with beta = atan2(m22, m20).
double LtcAxisAngle(const LtcMatrix &m) { return std::atan2(m.m22, m.m20); }

// The texel convention: three.js builds
//   mat3 mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w));
// from its LTC_1 texel t1, and GLSL's mat3 takes columns, so mInv * l =
// l.x col0 + l.y col1 + l.z col2. With t1 = (m00, m20, m02, m22) that is
// LtcMatrix::Apply (row-major M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]).
TEST(Ltc, ThreeJsTexelConvention) {
  const double t1[4] = {0.9, -0.2, 0.35, 0.4};  // x, y, z, w
  const Vec3 col0{t1[0], 0, t1[1]}, col1{0, 1, 0}, col2{t1[2], 0, t1[3]};
  const LtcMatrix m{t1[0], t1[1], t1[2], t1[3]};
  for (const Vec3 &l : {Vec3{0.3, -0.4, 0.7}, Vec3{-0.6, 0.1, 0.2}, Vec3{1, 0, 0}, Vec3{0, 0, 1}}) {
    const Vec3 glsl =
        Add(Add(Vec3{col0.x * l.x, col0.y * l.x, col0.z * l.x}, col1, l.y), col2, l.z);
    const Vec3 ours = m.Apply(l);
    EXPECT_EQ(glsl.x, ours.x);
    EXPECT_EQ(glsl.y, ours.y);
    EXPECT_EQ(glsl.z, ours.z);
  }
  // Its row 0, column 0 texel (mu = 1, r = 0) is (1, 0, 0, 2e-5): m00 = 1 =
  // the middle element, m22 = 2e-5 ~ 2 alpha at ltc_code's MIN_ALPHA = 1e-5.
}

TEST(Ltc, IdentityIsTheClippedCosine) {
  const LtcMatrix identity;
  for (const Vec3 &l : {Vec3{0, 0, 1}, Vec3{0.6, 0, 0.8}, Vec3{0.48, 0.6, 0.64}, Vec3{0, 1, 0},
                        Vec3{0.6, 0, -0.8}}) {
    EXPECT_NEAR(LtcDensity(identity, l), std::max(l.z, 0.0) / kPi, 1e-16);
  }
  EXPECT_EQ(LtcLeakage(identity), 0.0);
}

// D by its definition for the general inverse c M^-1 (middle element c):
// D = (w.z / |w|) / pi |det(c M^-1)| / |w|^3 for a unit l, w = c M^-1 l; the
// normalisation to c = 1 changes nothing, nor does the length of l.
TEST(Ltc, DensityIsTheDefinitionAtAnyScale) {
  for (const LtcMatrix &m : RandomMatrices(20)) {
    for (const Vec3 &dir : {Vec3{0.3, -0.4, 0.7}, Vec3{-0.5, 0.2, 0.4}, Vec3{0.1, 0.9, 0.2}}) {
      const Vec3 l = Normalize(dir);
      const double c = 3.5;
      const Vec3 w{c * (m.m00 * l.x + m.m02 * l.z), c * l.y, c * (m.m20 * l.x + m.m22 * l.z)};
      const double len = std::sqrt(Dot(w, w));
      const double det = c * c * c * m.Determinant();
      const double expected = std::max(w.z, 0.0) / len / kPi * std::fabs(det) / (len * len * len);
      const double d = LtcDensity(m, l);
      EXPECT_NEAR(d, expected, 1e-14 * expected);
      EXPECT_NEAR(LtcDensity(m, {2 * l.x, 2 * l.y, 2 * l.z}), d, 1e-14 * d);
    }
  }
}

// D integrates to 1 over the sphere; its support is the lune of width pi
// where (M^-1 l).z > 0.
TEST(Ltc, IntegratesToOneOverTheSphere) {
  for (const LtcMatrix &m : RandomMatrices(50)) {
    const double beta = LtcAxisAngle(m);
    const double total = IntegrateLune(beta - 0.5 * kPi, beta + 0.5 * kPi,
                                       [&](const Vec3 &l) { return LtcDensity(m, l); });
    EXPECT_NEAR(total, 1.0, 1e-11);
  }
}

// Leakage: D over {l.z < 0} (b in (-pi, 0)) intersected with its support.
TEST(Ltc, LeakageMatchesQuadrature) {
  for (const LtcMatrix &m : RandomMatrices(50)) {
    const double beta = LtcAxisAngle(m);
    // Support (beta - pi/2, beta + pi/2) and lower half (-pi, 0), modulo 2 pi.
    double leak = 0.0;
    for (int shift = -1; shift <= 1; ++shift) {
      const double lo = std::max(beta - 0.5 * kPi + 2 * kPi * shift, -kPi);
      const double hi = std::min(beta + 0.5 * kPi + 2 * kPi * shift, 0.0);
      if (hi > lo) leak += IntegrateLune(lo, hi, [&](const Vec3 &l) { return LtcDensity(m, l); });
    }
    EXPECT_NEAR(LtcLeakage(m), leak, 1e-11)
        << m.m00 << " " << m.m20 << " " << m.m02 << " " << m.m22;
  }
}

// The integral of D over a planar polygon's directions, by brute force: the
// polygon in its plane's coordinates is clipped (2D Sutherland-Hodgman) to
// the lines where l.z = 0 and (M^-1 l).z = 0 cross the plane, so that D is
// smooth on what is left; that is cut into triangles, each integrated by a
// collapsed 24 x 24 Gauss rule of dl = |n . p| / |p|^3 dA.
struct Plane2 {
  Vec3 origin, e1, e2;  // p = origin + s e1 + t e2
};
struct P2 {
  double s, t;
};
std::vector<P2> ClipHalfPlane(const std::vector<P2> &poly, double a, double b, double c) {
  // keeps a s + b t + c >= 0
  std::vector<P2> out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const P2 &p = poly[i], &q = poly[(i + 1) % n];
    const double fp = a * p.s + b * p.t + c, fq = a * q.s + b * q.t + c;
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) {
      const double u = fp / (fp - fq);
      out.push_back({p.s + u * (q.s - p.s), p.t + u * (q.t - p.t)});
    }
  }
  return out;
}
double BruteForcePolygon(const LtcMatrix &m, const Vec3 *v, bool clipSurface) {
  const Plane2 pl{v[0], Add(v[1], v[0], -1.0), Add(v[3], v[0], -1.0)};
  const Vec3 normal = Normalize(Cross(pl.e1, pl.e2));
  std::vector<P2> poly{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // f(p) = k . p for k = e_z or the last row of M^-1: linear in (s, t).
  auto clip = [&](const Vec3 &k) {
    poly = ClipHalfPlane(poly, Dot(k, pl.e1), Dot(k, pl.e2), Dot(k, pl.origin));
  };
  if (clipSurface) clip({0, 0, 1});
  clip({m.m20, 0, m.m22});
  if (poly.size() < 3) return 0.0;
  const double area = std::sqrt(Dot(Cross(pl.e1, pl.e2), Cross(pl.e1, pl.e2)));
  const GaussLegendreRule &rule = GaussLegendre(24);
  double sum = 0.0;
  for (size_t k = 1; k + 1 < poly.size(); ++k) {
    const P2 a = poly[0], b = poly[k], c = poly[k + 1];
    const double jac = std::fabs((b.s - a.s) * (c.t - a.t) - (c.s - a.s) * (b.t - a.t));
    for (int i = 0; i < rule.n; ++i)
      for (int j = 0; j < rule.n; ++j) {
        // Collapsed square: x = u, y = v (1 - u), dA = (1 - u) du dv.
        const double u = rule.x[i], w = rule.x[j] * (1 - u);
        const double s = a.s + u * (b.s - a.s) + w * (c.s - a.s);
        const double t = a.t + u * (b.t - a.t) + w * (c.t - a.t);
        const Vec3 p = Add(Add(pl.origin, pl.e1, s), pl.e2, t);
        const double r2 = Dot(p, p);
        const double solid = std::fabs(Dot(normal, p)) / (r2 * std::sqrt(r2));
        sum += rule.w[i] * rule.w[j] * (1 - u) * jac * area * solid * LtcDensity(m, p);
      }
  }
  return sum;
}

// Rectangles facing the origin at distance 1, as {centre polar angle,
// azimuth, half-width, half-height} in degrees: above, crossing the horizon,
// and below it.
std::vector<std::array<Vec3, 4>> TestPolygons() {
  const double spec[][4] = {{0, 0, 20, 20},  {35, 180, 25, 10}, {70, 150, 30, 20},
                            {85, 0, 30, 15}, {95, 90, 10, 40},  {120, 200, 10, 10}};
  std::vector<std::array<Vec3, 4>> out;
  const double deg = kPi / 180;
  for (const auto &s : spec) {
    const double th = s[0] * deg, ph = s[1] * deg;
    const Vec3 c{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
    const Vec3 e1 = s[0] == 0 ? Vec3{1, 0, 0} : Normalize(Cross({0, 0, 1}, c));
    const Vec3 e2 = Cross(c, e1);
    const double hw = std::tan(s[2] * deg), hh = std::tan(s[3] * deg);
    out.push_back({Add(Add(c, e1, hw), e2, hh), Add(Add(c, e1, -hw), e2, hh),
                   Add(Add(c, e1, -hw), e2, -hh), Add(Add(c, e1, hw), e2, -hh)});
  }
  return out;
}

TEST(Ltc, PolygonIntegralMatchesBruteForce) {
  for (const LtcMatrix &m : RandomMatrices(20)) {
    for (const auto &poly : TestPolygons()) {
      for (bool clip : {true, false}) {
        const double exact = LtcPolygonIntegral(m, poly.data(), 4, clip);
        const double brute = BruteForcePolygon(m, poly.data(), clip);
        EXPECT_NEAR(exact, brute, 1e-9) << clip;
      }
    }
  }
}

TEST(Ltc, HorizonClipping) {
  const auto polys = TestPolygons();
  const LtcMatrix identity;
  // Entirely below the surface: nothing with clipping; the identity's own
  // horizon is the surface's, so it gives nothing either way.
  EXPECT_EQ(LtcPolygonIntegral(identity, polys[5].data(), 4, true), 0.0);
  EXPECT_EQ(LtcPolygonIntegral(identity, polys[5].data(), 4, false), 0.0);
  for (const LtcMatrix &m : RandomMatrices(20)) {
    // Above the horizon: clipping changes nothing. Crossing it: it only removes.
    EXPECT_EQ(LtcPolygonIntegral(m, polys[0].data(), 4, true),
              LtcPolygonIntegral(m, polys[0].data(), 4, false));
    for (int k : {3, 4})
      EXPECT_LE(LtcPolygonIntegral(m, polys[k].data(), 4, true),
                LtcPolygonIntegral(m, polys[k].data(), 4, false) + 1e-15);
    // Below the horizon only what leaks is seen, and only without clipping.
    EXPECT_EQ(LtcPolygonIntegral(m, polys[5].data(), 4, true), 0.0);
  }
  // The upper hemisphere as a polygon (the equator's square at infinity is
  // approximated by a flat square of half-size 1e7 at height 1): 1 - 1e-14.
  const Vec3 big[4] = {{1e7, 1e7, 1}, {-1e7, 1e7, 1}, {-1e7, -1e7, 1}, {1e7, -1e7, 1}};
  EXPECT_NEAR(LtcPolygonIntegral(identity, big, 4, true), 1.0, 1e-12);
}

TEST(Ltc, WindingDoesNotMatter) {
  for (const LtcMatrix &m : RandomMatrices(10))
    for (const auto &poly : TestPolygons()) {
      const Vec3 reversed[4] = {poly[3], poly[2], poly[1], poly[0]};
      // Equal up to the rounding of the edge sum (terms of order 1, summed in
      // another order).
      EXPECT_NEAR(LtcPolygonIntegral(m, poly.data(), 4), LtcPolygonIntegral(m, reversed, 4), 1e-15);
    }
}

// A rectangle of half-size h = 1e-5 around direction c: the integral is
// D(c) times its solid angle (4 h^2 for a square facing the origin at
// distance 1) to relative O(h^2) (~1e-10 here). The edge sum cancels from
// terms of order h to a result of order h^2; with acos(v_i . v_j) for the arc
// angle (1 - cos(2e-5) = 2e-10) the result is off by ~3e-3, with atan2 by
// 1e-10 to 2e-8.
TEST(Ltc, TinyPolygonsKeepTheirDigits) {
  for (const LtcMatrix &m : RandomMatrices(10)) {
    const Vec3 c = Normalize({0.2, 0.1, 0.9});
    const Vec3 e1 = Normalize(Cross({0, 0, 1}, c)), e2 = Cross(c, e1);
    const double h = 1e-5;
    const Vec3 v[4] = {Add(Add(c, e1, h), e2, h), Add(Add(c, e1, -h), e2, h),
                       Add(Add(c, e1, -h), e2, -h), Add(Add(c, e1, h), e2, -h)};
    const double expected = LtcDensity(m, c) * 4 * h * h;
    EXPECT_NEAR(LtcPolygonIntegral(m, v, 4), expected, 1e-7 * expected);
  }
}

}  // namespace
}  // namespace lutbake
