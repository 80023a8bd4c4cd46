// Beckmann microfacet distribution, isotropic, n = +z, with the exact Smith
// Lambda (erf form, not the rational fit).
//
//   D(h)       = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h))
//   Lambda(mu) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),
//                a = mu / (alpha sqrt(1 - mu^2)) = 1 / (alpha tan(theta))
#pragma once

#include "lutbake/core/math.h"

namespace lutbake::beckmann {

double D(double alpha, const Vec3 &h);

// mu * Lambda(mu) = (alpha s exp(-a^2) / sqrt(pi) - mu erfc(a)) / 2,
// s = sqrt(1 - mu^2). Written this way it is finite at mu = 0, where it equals
// alpha / (2 sqrt(pi)), and needs no 1/a.
double MuLambda(double alpha, double mu);

// Visible-normal sampling after Heitz and d'Eon (2014): in the configuration
// stretched to alpha = 1 with the view at angle theta to n, the visible slopes
// are independent in x and y:
//   p(x) ~ exp(-x^2) (cos(theta) - x sin(theta)),  x < cot(theta),
//   p(y) ~ exp(-y^2).
// Both are drawn by inverting their CDFs with safeguarded Newton iterations
// (SampleVisibleSlope), then unstretched. u in [0,1)^2; density
// VisibleNormalPdf (ndf.h) with respect to solid angle of h.
Vec3 SampleVisibleNormal(double alpha, const Vec3 &o, double u1, double u2);

// Inverse CDF of the visible slope density above, for a view with
// cos(theta) = cosTheta, sin(theta) = sinTheta (cosTheta = 1, sinTheta = 0
// gives the Gaussian of the y slope). The CDF is
//   C(x) = cos(theta) sqrt(pi)/2 erfc(-x) + sin(theta)/2 exp(-x^2).
double SampleVisibleSlope(double cosTheta, double sinTheta, double u);

// NDF sampling: D cos d(omega) has the CDF xi(theta) = 1 - exp(-tan^2 / alpha^2),
// so tan^2(theta) = -alpha^2 log(1 - xi).
void NormalFromCdf(double alpha, double xi, double *cosTheta_h, double *sinTheta_h);
double CdfFromTheta(double alpha, double theta_h);

}  // namespace lutbake::beckmann
