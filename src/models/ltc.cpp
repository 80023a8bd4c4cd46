#include "lutbake/models/ltc.h"

#include <cmath>

namespace lutbake {

namespace {

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

constexpr int kMaxPolygonVertices = 8;

}  // namespace

double LtcDensity(const LtcMatrix &minv, const Vec3 &l) {
  const Vec3 w = minv.Apply(l);
  if (w.z <= 0.0) return 0.0;
  // D = (w.z / |w|) / pi * |det| / (|w| / |l|)^3, the factor |l|^3 making D
  // independent of the length of l.
  const double len2 = Dot(w, w);
  const double l2 = Dot(l, l);
  const double ratio = std::sqrt(l2 / len2);  // |l| / |w|
  const double ratio3 = ratio * ratio * ratio;
  return kInvPi * w.z / std::sqrt(len2) * std::fabs(minv.Determinant()) * ratio3;
}

double LtcLeakage(const LtcMatrix &minv) {
  const double det = minv.Determinant();
  const double sign = det >= 0.0 ? 1.0 : -1.0;
  return 0.5 * (1.0 - sign * minv.m00 / std::hypot(minv.m00, minv.m20));
}

int ClipPolygonToUpperHalfSpace(const Vec3 *vertices, int count, Vec3 *out) {
  int n = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3 &a = vertices[i];
    const Vec3 &b = vertices[(i + 1) % count];
    const bool aIn = a.z >= 0.0, bIn = b.z >= 0.0;
    if (aIn) out[n++] = a;
    if (aIn != bIn) {
      // The point of the segment a-b on z = 0; t in (0, 1) because the signs differ.
      const double t = a.z / (a.z - b.z);
      out[n++] = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0};
    }
  }
  return n >= 3 ? n : 0;
}

double ClippedCosinePolygonIntegral(const Vec3 *vertices, int count) {
  // LtcPolygonIntegral passes up to count + 2 vertices (two clippings).
  assert(count >= 3 && count <= kMaxPolygonVertices + 2);
  Vec3 v[kMaxPolygonVertices + 2];
  for (int i = 0; i < count; ++i) v[i] = Normalize(vertices[i]);
  double sum = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec3 &a = v[i];
    const Vec3 &b = v[(i + 1) % count];
    const Vec3 c = Cross(a, b);
    const double sinTheta = std::sqrt(Dot(c, c));
    if (sinTheta == 0.0) continue;  // repeated vertex: an edge of zero length
    const double theta = std::atan2(sinTheta, Dot(a, b));
    sum += theta * (c.z / sinTheta);
  }
  return std::fabs(sum) / (2.0 * kPi);
}

double LtcPolygonIntegral(const LtcMatrix &minv, const Vec3 *vertices, int count,
                          bool clipAtSurfaceHorizon) {
  assert(count >= 3 && count <= kMaxPolygonVertices);
  Vec3 surface[kMaxPolygonVertices + 1];
  int n = count;
  if (clipAtSurfaceHorizon) {
    n = ClipPolygonToUpperHalfSpace(vertices, count, surface);
  } else {
    for (int i = 0; i < count; ++i) surface[i] = vertices[i];
  }
  if (n == 0) return 0.0;
  Vec3 transformed[kMaxPolygonVertices + 2];
  for (int i = 0; i < n; ++i) transformed[i] = minv.Apply(surface[i]);
  Vec3 clipped[kMaxPolygonVertices + 3];
  const int m = ClipPolygonToUpperHalfSpace(transformed, n, clipped);
  if (m == 0) return 0.0;
  return ClippedCosinePolygonIntegral(clipped, m);
}

}  // namespace lutbake
