// Linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016) in the
// layout three.js and ltc_code store them.
//
// The frame: the normal is +z and the view is v = (sqrt(1 - mu^2), 0, mu)
// (ViewDirection in core/math.h). The inverse transform, normalised so that
// its middle element is 1, is
//   M^-1 = [[m00, 0, m02],
//           [  0, 1,   0],
//           [m20, 0, m22]]      (row index first: (M^-1 l).x = m00 l.x + m02 l.z).
// three.js reads it from its LTC_1 texel t1 as
//   mat3 mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w));
// GLSL's mat3 takes columns, so column 0 is (m00, 0, m20) and column 2 is
// (m02, 0, m22): t1 = (m00, m20, m02, m22), the order of LtcMatrix below.
//
// The distribution. With w = M^-1 l / |M^-1 l| and D_o(w) = max(w.z, 0) / pi,
//   D(l) = D_o(w) |det M^-1| / |M^-1 l|^3,
// the density of l = M w / |M w| when w has density D_o (the Jacobian of
// w -> l is |det M^-1| / |M^-1 l|^3 in solid angle). D is unchanged when M^-1
// is scaled, so the normalisation costs nothing; it integrates to 1 over the
// sphere.
#pragma once

#include "lutbake/core/math.h"

namespace lutbake {

struct LtcMatrix {
  double m00 = 1, m20 = 0, m02 = 0, m22 = 1;  // three.js's t1 = (m00, m20, m02, m22)

  double Determinant() const { return m00 * m22 - m02 * m20; }
  Vec3 Apply(const Vec3 &l) const {  // M^-1 l
    return {m00 * l.x + m02 * l.z, l.y, m20 * l.x + m22 * l.z};
  }
};

// D(l) for any direction l (need not be normalised: D is evaluated at l / |l|).
double LtcDensity(const LtcMatrix &minv, const Vec3 &l);

// The share of D below the horizon, int_{l.z < 0} D(l) dl. The lower
// half-space {l.z < 0} is mapped by M^-1 onto the half-space
// {w : (M w).z < 0} = {w : r.w < 0} with r the last row of M,
//   r = (-m20, 0, m00) / det M^-1,
// so the leakage is the clipped cosine D_o integrated over the hemisphere of
// axis c = -r / |r|. That hemisphere meets {w.z > 0} in a lune bounded by two
// half great circles, one in the plane w.z = 0 and one in the plane normal to
// c, each of angle pi; the edge formula below (projected solid angle =
// sum of arc angle times the arc plane's normal . z, over 2) gives
// (pi / 2)(1 + c.z), divided by pi:
//   leakage = (1 + c.z) / 2 = (1 - sign(det M^-1) m00 / sqrt(m00^2 + m20^2)) / 2.
double LtcLeakage(const LtcMatrix &minv);

// int_P D(l) dl over the spherical polygon P spanned (from the origin) by the
// `count` vertices (count >= 3, at most 8), in either winding order. With
// clipAtSurfaceHorizon the polygon is first clipped to l.z >= 0 (the light a
// surface receives); either way the transformed polygon is clipped to
// w.z >= 0, where D_o vanishes. The integral is the clipped cosine's, in
// closed form (Lambert's vector form factor):
//   int_{M^-1 P} D_o(w) dw = |sum_edges theta_ij (v_i x v_j).z / |v_i x v_j|| / (2 pi),
// v_i the normalised transformed vertices and theta_ij = atan2(|v_i x v_j|,
// v_i . v_j) the arc angle: atan2 keeps theta / sin(theta) accurate for nearly
// parallel vertices, where acos(v_i . v_j) loses half the digits.
double LtcPolygonIntegral(const LtcMatrix &minv, const Vec3 *vertices, int count,
                          bool clipAtSurfaceHorizon = true);

// The edge sum above for a polygon already on the upper side (its vertices
// need not be normalised; 3 to 10 of them): the projected solid angle
// divided by pi.
double ClippedCosinePolygonIntegral(const Vec3 *vertices, int count);

// Sutherland-Hodgman clipping of a polygon (straight edges, any scale) to the
// half-space z >= 0. Returns the vertex count of the result (at most count + 1,
// 0 when nothing is left); `out` must hold count + 1 vertices.
int ClipPolygonToUpperHalfSpace(const Vec3 *vertices, int count, Vec3 *out);

}  // namespace lutbake
