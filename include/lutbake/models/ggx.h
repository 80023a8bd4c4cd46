// GGX (Trowbridge-Reitz) microfacet distribution, isotropic, n = +z.
//
//   D(h)      = alpha^2 / (pi (alpha^2 cos^2(theta_h) + sin^2(theta_h))^2)
//   Lambda(mu) = (sqrt(1 + alpha^2 (1 - mu^2) / mu^2) - 1) / 2
//
// The denominator of D is written as alpha^2 c^2 + s^2 instead of the usual
// c^2 (alpha^2 - 1) + 1: the two are equal, but the second cancels near the
// peak when alpha is small.
#pragma once

#include "lutbake/core/math.h"

namespace lutbake::ggx {

double D(double alpha, const Vec3 &h);

// mu * Lambda(mu), rewritten without cancellation:
//   mu Lambda(mu) = alpha^2 (1 - mu^2) / (2 (sqrt(mu^2 + alpha^2 (1 - mu^2)) + mu)).
// Finite at mu = 0, where it equals alpha / 2 (the grazing limit).
double MuLambda(double alpha, double mu);

// Visible-normal sampling by the spherical-cap construction (Dupuy and
// Benyoub 2023): in the configuration stretched to alpha = 1 the visible
// normals are h_s = c + o_s with c uniform on the spherical cap
// z in (-o_s.z, 1]; unstretching gives h. u in [0,1)^2. The density of the
// result is VisibleNormalPdf (ndf.h) with respect to solid angle of h.
Vec3 SampleVisibleNormal(double alpha, const Vec3 &o, double u1, double u2);

// NDF sampling: the measure D(h) cos(theta_h) d(omega_h) has the CDF in theta
//   xi(theta) = tan^2(theta) / (alpha^2 + tan^2(theta)),
// so tan^2(theta) = alpha^2 xi / (1 - xi) and phi = 2 pi u2. The returned
// cos and sin are computed without forming 1 - cos^2.
void NormalFromCdf(double alpha, double xi, double *cosTheta_h, double *sinTheta_h);
// Inverse of the above: xi(theta) for theta in [0, pi/2].
double CdfFromTheta(double alpha, double theta_h);

}  // namespace lutbake::ggx
