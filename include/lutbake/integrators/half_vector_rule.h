// The half-vector rule: a deterministic product Gauss rule over light
// directions for lobes that follow a microfacet half vector, over the upper
// hemisphere or over a spherical polygon (integrators/ltc_fit.h fits LTCs
// with it).
//
// The quadrature (the "half-vector rule"). Every integral over light
// directions l is taken over the half vector h = normalize(v + l) of the
// reflection l = 2 (v.h) h - v, h at polar angle theta (T = tan theta) and
// azimuth phi about the normal:
//   int g(l) dl = int dphi int dT 4 (v.h) T / (1 + T^2)^(3/2) g(l(h)),
// (dl = 4 (v.h) dw_h, dw_h = sin(theta) dtheta dphi). For a microfacet lobe of
// width alpha the integrand is ~ D(h), so T is changed, as in the albedo
// quadrature (albedo_quadrature.h), to t = T / alpha on the core T <= alpha
// (two Gauss panels) and to w = alpha / T on the tail, whose panels shrink
// geometrically (ratio 1/3) toward w_min = alpha / T_max(phi), the horizon:
//   l.z >= 0  <=>  T <= T_max(phi) = (sc + sqrt(sc^2 + mu^2)) / mu,  sc = s cos(phi),
// the positive root of l.z (1 + T^2) = -mu T^2 + 2 sc T + mu. The azimuth is
// phi = pi/2 -+ a sinh(u), a = asinh(mu / s), panels of width <= 1.2 in u
// (T_max has its complex singularity at cos(phi) = +-i mu / s), and the other
// half circle by symmetry about the view plane (lobes and LTCs are even in l.y).
//
// Polygons. A spherical polygon P is the intersection of the half-spaces
// n_e . l >= 0 of its edges. Along one azimuth, with h~ = (T cos, T sin, 1),
//   (n_e . l) (1 + T^2) = 2 (v.h~)(n_e.h~) - (1 + T^2)(n_e . v),
// a quadratic in T: its roots give the T-intervals inside P exactly, and the
// panels above are cut at them. The azimuth panels are cut where the
// intervals change their structure: at the azimuths of the half vectors of
// P's vertices (those of P clipped at the horizon included), and where an
// edge's quadratic has a double root (the meridian's curve touches the edge),
// next to which the integrand goes like sqrt(phi - phi_c); each such panel's
// variable is mapped by x -> 3x^2 - 2x^3, which makes that smooth.
#pragma once

#include <vector>

#include "lutbake/core/math.h"

namespace lutbake {

// One node of the half-vector rule: int g(l) dl ~= sum weight * g(l).
struct LtcNode {
  Vec3 l, h;
  double weight;
};

// Rule density: level 0 (the fit), level 1 (errors; about 2.3x the nodes),
// level 2 (the check of level 1; about 2.3x again).
// Nodes of the upper hemisphere; with halfCircle the azimuths phi in [0, pi]
// only, weights doubled (for integrands even in l.y).
std::vector<LtcNode> HalfVectorRule(double mu_o, double quadratureAlpha, int level,
                                    bool halfCircle);

// Nodes covering P (count vertices, from the origin, 3 <= count <= 8) clipped
// at the horizon, on the whole circle of azimuths.
std::vector<LtcNode> HalfVectorPolygonRule(double mu_o, double quadratureAlpha, int level,
                                           const Vec3 *vertices, int count);

}  // namespace lutbake
