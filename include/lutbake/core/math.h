// Numeric helpers shared by the whole library.
//
// Everything here is double precision: lutbake accumulates and evaluates in
// double and only rounds to float when a table is written.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

namespace lutbake {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInvPi = 0.31830988618379067154;
inline constexpr double kSqrtPi = 1.77245385090551602730;

template <typename T>
constexpr T Sqr(T x) {
  return x * x;
}

// x^5 with three multiplications; used for the Schlick weight (1 - o.h)^5.
constexpr double Pow5(double x) {
  const double x2 = x * x;
  return x2 * x2 * x;
}

// The Schlick weight Fc = (1 - c)^5 and its complement 1 - Fc, for c =
// o.h in [0, 1]. The complement is written as c (1 + y + y^2 + y^3 + y^4),
// y = 1 - c (the geometric sum of 1 - y^5): 1 - Fc cancels for small c
// (grazing view, where A ~ 5 mu_o), this does not.
struct SchlickWeights {
  double fc, complement;
};
constexpr SchlickWeights Schlick(double c) {
  const double y = 1.0 - c;
  const double y2 = y * y;
  return {y2 * y2 * y, c * (1.0 + y + y2 + y2 * y + y2 * y2)};
}

constexpr double Clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

// sqrt of a quantity that is non-negative in exact arithmetic but may come out
// as a tiny negative number after rounding (1 - mu^2 at mu = 1, for example).
// A large negative argument is a bug, not rounding.
inline double SafeSqrt(double x) {
  assert(x > -1e-9);
  return std::sqrt(std::max(0.0, x));
}

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline double Dot(const Vec3 &a, const Vec3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

inline Vec3 Normalize(const Vec3 &v) {
  const double inv = 1.0 / std::sqrt(Dot(v, v));
  return {v.x * inv, v.y * inv, v.z * inv};
}

// The view direction of every table: in the local frame with n = +z and the
// view in the xz-plane, o = (sqrt(1 - mu_o^2), 0, mu_o).
inline Vec3 ViewDirection(double mu_o) { return {SafeSqrt(1.0 - mu_o * mu_o), 0.0, mu_o}; }

// Reflection of o about the microfacet normal h: i = 2 (o.h) h - o.
inline Vec3 Reflect(const Vec3 &o, const Vec3 &h) {
  const double oh2 = 2.0 * Dot(o, h);
  return {oh2 * h.x - o.x, oh2 * h.y - o.y, oh2 * h.z - o.z};
}

}  // namespace lutbake
