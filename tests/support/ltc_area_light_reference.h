// The CPU side of the tests of the emitted area-light code
// (ltc_area_light_code.cpp): rectangle cases as a shader receives them
// (float32 world vectors) beside their geometry in the LTC frame (double),
// the LTC integral in double (models/ltc.h) with the table read as the
// library reads it (Lookup), and a bound, derived below, on what float32
// arithmetic and a GPU's texture filtering may move the shader's result.
//
// The bound is first order, doubled (for the linearisation and the kinks of
// clipping): with I = int_P D over the clipped polygon,
//   |I_gpu - I| <= 2 (sum_k,c |dI/dl_kc| e_l(k) + sum_j |dI/dm_j| e_m(j) + e_sum),
// derivatives by central differences in double, u = 2^-24, and
//   e_l(k) = |p_k| u (20 + 8 / sin theta_v): the corners rounded to float32
//            (u), the frame T1 = normalize(V - N (N.V)) whose direction
//            carries ~4u / sin theta_v (cancellation as V nears N), doubled,
//            T2 = cross(N, T1) (2u), the three dot products (3u) and N, V
//            not exactly unit (2u), per coordinate of each corner;
//   e_m(j) = the lookup's error of matrix entry j (LookupBound) plus 2u |m_j|
//            (the transform M^-1 l, two roundings as a relative change of
//            the entries);
//   e_sum  = (32 u perimeter + 4 u vertices) / (2 pi): per edge the
//            normalisations (2 x 2u), the cross product and its length
//            (4u), atan2 (16u: GPU transcendentals are not correctly
//            rounded), the division and the sum (4u), each relative to the
//            edge's arc angle, whose sum is the clipped polygon's perimeter;
//            plus ~4u absolute per vertex for the clip points.
// The lookup (LookupBound): a GPU interpolates with weights of 8 fractional
// bits (D3D's minimum; truncated, an error below 2^-8), so channel c moves by
// at most 2^-8 |T(i+1) - T(i)| along each axis, plus the texel coordinate's
// own rounding (8u N texels per axis) and the lerp's (4u |value|).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "lutbake/core/math.h"
#include "lutbake/models/ltc.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/table.h"

namespace lutbake::test {

inline constexpr double kFloatUnit = 0x1p-24;

inline Vec3 CrossOf(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 Scaled(const Vec3 &a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline Vec3 Sum(const Vec3 &a, const Vec3 &b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 Difference(const Vec3 &a, const Vec3 &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// One rectangular light at one shading point.
struct AreaLightCase {
  // What the shader receives (float32): unit normal and view, perceptual
  // roughness, corners relative to the shading point (world space).
  std::array<float, 3> N{}, V{};
  float r = 0;
  std::array<std::array<float, 3>, 4> p{};
  // The same in the LTC frame (n = +z, v = (sqrt(1 - mu^2), 0, mu)), double.
  double mu = 0;
  std::array<Vec3, 4> local{};
  int rectangle = -1;  // its index in LtcTestRectangles, or -1
};

// A rotation of the LTC frame into the world, from a unit quaternion.
struct Rotation {
  double m[3][3];
  Vec3 Apply(const Vec3 &v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
};
inline Rotation RandomRotation(std::mt19937 &random) {
  std::normal_distribution<double> g(0.0, 1.0);
  double q[4], n = 0.0;
  for (double &c : q) {
    c = g(random);
    n += c * c;
  }
  n = std::sqrt(n);
  const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

inline std::array<float, 3> ToFloat(const Vec3 &v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

// The case of corners `local` (LTC frame) at (mu, r), turned into the world by R.
inline AreaLightCase MakeCase(double mu, double r, const std::array<Vec3, 4> &local,
                              const Rotation &R) {
  AreaLightCase c;
  c.mu = mu;
  c.r = static_cast<float>(r);
  c.local = local;
  c.N = ToFloat(R.Apply({0, 0, 1}));
  c.V = ToFloat(R.Apply(ViewDirection(mu)));
  for (int k = 0; k < 4; ++k) c.p[k] = ToFloat(R.Apply(local[k]));
  return c;
}

// A random rectangle in the LTC frame: centre at polar angle up to 115
// degrees (some below the horizon, some crossing it), 0.5 to 8 away, its
// plane tilted up to 60 degrees from facing the point, half-sides 0.05 to
// 1.5 times the distance, either winding.
inline std::array<Vec3, 4> RandomRectangle(std::mt19937 &random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double theta = uniform(random) * 115.0 * kPi / 180.0, phi = 2.0 * kPi * uniform(random);
  const Vec3 c{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  const double distance = 0.5 + 7.5 * uniform(random);
  // The plane's normal: c tilted by up to 60 degrees toward a random direction.
  const Vec3 helper = std::fabs(c.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  const Vec3 e1 = Normalize(CrossOf(helper, c)), e2 = CrossOf(c, e1);
  const double tilt = uniform(random) * kPi / 3.0, toward = 2.0 * kPi * uniform(random);
  const Vec3 normal =
      Sum(Scaled(c, std::cos(tilt)),
          Scaled(Sum(Scaled(e1, std::cos(toward)), Scaled(e2, std::sin(toward))), std::sin(tilt)));
  const Vec3 a1 =
      Normalize(CrossOf(normal, std::fabs(normal.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
  const Vec3 a2 = CrossOf(normal, a1);
  const double roll = 2.0 * kPi * uniform(random);
  const Vec3 b1 = Sum(Scaled(a1, std::cos(roll)), Scaled(a2, std::sin(roll)));
  const Vec3 b2 = CrossOf(normal, b1);
  const double hw = distance * (0.05 + 1.45 * uniform(random)),
               hh = distance * (0.05 + 1.45 * uniform(random));
  const Vec3 centre = Scaled(c, distance);
  const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  std::array<Vec3, 4> out;
  for (int k = 0; k < 4; ++k)
    out[k] = Sum(centre, Sum(Scaled(b1, signs[k][0] * hw), Scaled(b2, signs[k][1] * hh)));
  if (uniform(random) < 0.5) std::swap(out[1], out[3]);
  return out;
}

// Whether a one-sided light of these corners shines on the point (the
// origin): three.js's convention, along n_L = (p1 - p0) x (p3 - p0); `margin`
// is |n_L . p0| / (|n_L| |p0|), near 0 when the point is nearly in the plane.
inline bool FacesThePoint(const std::array<Vec3, 4> &p, double *margin) {
  const Vec3 n = CrossOf(Difference(p[1], p[0]), Difference(p[3], p[0]));
  const double d = Dot(n, p[0]);
  *margin = std::fabs(d) / std::sqrt(Dot(n, n) * Dot(p[0], p[0]));
  return d < 0.0;
}

// The six channels of the table at (mu, r) as the library reads them, and
// the bound on a GPU's filtered read of each (header comment).
struct LtcLookup {
  LtcMatrix minv;
  double magnitude = 0, fresnel = 0;
  std::array<double, 6> value{}, bound{};
};
inline LtcLookup LookupLtc(const Table &t, double mu, double r) {
  LtcLookup out;
  int ix = 0, iy = 0;
  double wx = 0, wy = 0;
  LookupCoordinate(t.x, mu, &ix, &wx);
  LookupCoordinate(t.y, r, &iy, &wy);
  const int ix1 = std::min(ix + 1, t.width() - 1), iy1 = std::min(iy + 1, t.height() - 1);
  for (int c = 0; c < 6; ++c) {
    out.value[c] = Lookup(t, mu, r, c);
    const double dx = std::max(std::fabs(t.value(ix1, iy, c) - t.value(ix, iy, c)),
                               std::fabs(t.value(ix1, iy1, c) - t.value(ix, iy1, c)));
    const double dy = std::max(std::fabs(t.value(ix, iy1, c) - t.value(ix, iy, c)),
                               std::fabs(t.value(ix1, iy1, c) - t.value(ix1, iy, c)));
    out.bound[c] = dx * (0x1p-8 + 8.0 * kFloatUnit * t.width()) +
                   dy * (0x1p-8 + 8.0 * kFloatUnit * t.height()) +
                   4.0 * kFloatUnit * std::fabs(out.value[c]);
  }
  out.minv = {out.value[0], out.value[1], out.value[2], out.value[3]};
  out.magnitude = out.value[4];
  out.fresnel = out.value[5];
  return out;
}

// The polygon's perimeter on the sphere after both clippings (the arc angles
// of e_sum) and its vertex count.
inline double ClippedPerimeter(const LtcMatrix &minv, const std::array<Vec3, 4> &local,
                               int *vertices) {
  Vec3 surface[5], transformed[5], clipped[6];
  const int n = ClipPolygonToUpperHalfSpace(local.data(), 4, surface);
  for (int i = 0; i < n; ++i) transformed[i] = minv.Apply(surface[i]);
  const int m = n ? ClipPolygonToUpperHalfSpace(transformed, n, clipped) : 0;
  double perimeter = 0.0;
  for (int i = 0; i < m; ++i) {
    const Vec3 a = Normalize(clipped[i]), b = Normalize(clipped[(i + 1) % m]);
    const Vec3 c = CrossOf(a, b);
    perimeter += std::atan2(std::sqrt(Dot(c, c)), Dot(a, b));
  }
  *vertices = m;
  return perimeter;
}

// |I| = int_P D in double and the bound on |I_gpu - I| (header comment);
// matrixBound[j]: the lookup's bound on entry j (0 for an exact matrix).
struct BoundedIntegral {
  double value = 0, bound = 0;
};
inline BoundedIntegral LtcIntegralWithFloatBound(const LtcMatrix &minv,
                                                 const std::array<double, 4> &matrixBound,
                                                 const std::array<Vec3, 4> &local, double mu) {
  const auto integral = [](const LtcMatrix &m, const std::array<Vec3, 4> &v) {
    return LtcPolygonIntegral(m, v.data(), 4, true);
  };
  BoundedIntegral out;
  out.value = integral(minv, local);
  const double u = kFloatUnit, sinView = std::max(std::sqrt(std::max(1.0 - mu * mu, 0.0)), 1e-3);
  double first = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double size = std::sqrt(Dot(local[k], local[k]));
    const double h = 1e-6 * size, e = size * u * (20.0 + 8.0 / sinView);
    for (int axis = 0; axis < 3; ++axis) {
      std::array<Vec3, 4> plus = local, minus = local;
      double *a = axis == 0 ? &plus[k].x : axis == 1 ? &plus[k].y : &plus[k].z;
      double *b = axis == 0 ? &minus[k].x : axis == 1 ? &minus[k].y : &minus[k].z;
      *a += h;
      *b -= h;
      first += std::fabs(integral(minv, plus) - integral(minv, minus)) / (2.0 * h) * e;
    }
  }
  const double entries[4] = {minv.m00, minv.m20, minv.m02, minv.m22};
  const double scale = std::max(
      {std::fabs(entries[0]), std::fabs(entries[1]), std::fabs(entries[2]), std::fabs(entries[3])});
  for (int j = 0; j < 4; ++j) {
    const double h = 1e-7 * std::max(std::fabs(entries[j]), 1e-3 * scale);
    double plusEntries[4], minusEntries[4];
    std::copy(entries, entries + 4, plusEntries);
    std::copy(entries, entries + 4, minusEntries);
    plusEntries[j] += h;
    minusEntries[j] -= h;
    const LtcMatrix plus{plusEntries[0], plusEntries[1], plusEntries[2], plusEntries[3]};
    const LtcMatrix minus{minusEntries[0], minusEntries[1], minusEntries[2], minusEntries[3]};
    const double e = matrixBound[j] + 2.0 * u * std::fabs(entries[j]);
    first += std::fabs(integral(plus, local) - integral(minus, local)) / (2.0 * h) * e;
  }
  int vertices = 0;
  const double perimeter = ClippedPerimeter(minv, local, &vertices);
  first += (32.0 * u * perimeter + 4.0 * u * vertices) / (2.0 * kPi);
  out.bound = 2.0 * first;
  return out;
}

// What the emitted functions return for a case, in double, with bounds:
// lutbake_rect_light_T_f1 (two-sided and one-sided),
// lutbake_rect_light_T(F0, F90 = 1).x (two-sided) and
// lutbake_rect_light_diffuse (two-sided).
struct AreaLightExpected {
  double f1 = 0, f1Bound = 0;
  double oneSided = 0;  // f1 or 0; bound f1Bound
  double fresnel = 0, fresnelBound = 0;
  double diffuse = 0, diffuseBound = 0;
  double facingMargin = 0;  // FacesThePoint's
  double integral = 0;      // int_P D of the table's LTC
};
inline AreaLightExpected ExpectedAreaLight(const Table &ltc, const AreaLightCase &c, double F0) {
  AreaLightExpected e;
  const LtcLookup at = LookupLtc(ltc, c.mu, c.r);
  const BoundedIntegral I = LtcIntegralWithFloatBound(
      at.minv, {at.bound[0], at.bound[1], at.bound[2], at.bound[3]}, c.local, c.mu);
  const double u = kFloatUnit;
  e.integral = I.value;
  e.f1 = at.magnitude * I.value;
  e.f1Bound = std::fabs(at.magnitude) * I.bound + I.value * at.bound[4] + 4.0 * u * e.f1;
  e.oneSided = FacesThePoint(c.local, &e.facingMargin) ? e.f1 : 0.0;
  const double weight = F0 * (at.magnitude - at.fresnel) + at.fresnel;
  e.fresnel = weight * I.value;
  e.fresnelBound = std::fabs(weight) * I.bound +
                   I.value * (F0 * at.bound[4] + std::fabs(1.0 - F0) * at.bound[5]) +
                   8.0 * u * std::fabs(e.fresnel);
  const BoundedIntegral lambert =
      LtcIntegralWithFloatBound(LtcMatrix{}, {0, 0, 0, 0}, c.local, c.mu);
  e.diffuse = lambert.value;
  e.diffuseBound = lambert.bound;
  return e;
}

}  // namespace lutbake::test
