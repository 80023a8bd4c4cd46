// The light-direction rule: a deterministic product Gauss rule over light
// directions l = (sin(theta) cos(phi), sin(theta) sin(phi), cos(theta)) for
// lobes that are smooth over the hemisphere (diffuse lobes: Burley, Oren-
// Nayar), over the upper hemisphere or over a spherical polygon clipped at
// the horizon (integrators/ltc_fit.h fits LTCs with it).
//
// The quadrature. int g(l) dl = int dphi int sin(theta) g dtheta, Gauss-
// Legendre panels in theta and phi. The panels are cut where the diffuse
// lobes kink: theta = theta_o (Oren-Nayar's max/min of the polar angles)
// and cos(phi) = 0 (its max(0, cos(dphi))), besides phi = 0 and pi; theta
// panels at most kMaxThetaPanel wide, phi panels at most kMaxPhiPanel.
//
// Polygons. A convex spherical polygon P (smaller than a hemisphere) is the
// intersection of the half-spaces n_e . l >= 0 of its edges (n_e oriented
// inward). Along one azimuth, n_e . l = a sin(theta) + b cos(theta) with a =
// n_e.x cos(phi) + n_e.y sin(phi), b = n_e.z: on [0, pi/2] it changes sign
// at most once, at theta* = atan2(|b|, |a|), so P meets the meridian in one
// interval whose ends are exact. The ends are smooth in phi between the
// azimuths of the vertices of P clipped at the horizon (where the active
// edge changes, or the interval appears), so the azimuth panels are cut
// there too.
#pragma once

#include <vector>

#include "lutbake/integrators/half_vector_rule.h"

namespace lutbake {

// Rule density: level 0 (the fit), level 1 (errors), level 2 (the check of
// level 1). Nodes of the upper hemisphere; with halfCircle the azimuths phi
// in [0, pi] only, weights doubled (for integrands even in l.y). Each node's
// h is the half vector normalize(v + l) of the view v = (sqrt(1 - mu^2), 0,
// mu) (the normal where v + l = 0).
std::vector<LtcNode> LightDirectionRule(double mu_o, int level, bool halfCircle);

// Nodes covering the convex polygon P (count vertices from the origin, 3 <=
// count <= 8, either winding) clipped at the horizon, on the whole circle.
std::vector<LtcNode> LightDirectionPolygonRule(double mu_o, int level, const Vec3 *vertices,
                                               int count);

}  // namespace lutbake
