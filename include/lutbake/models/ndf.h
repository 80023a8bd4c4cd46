// A microfacet normal distribution with its width alpha, dispatching to GGX
// or Beckmann, and the densities of its two samplers.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

enum class NdfKind { kGgx, kBeckmann };
// Every kind, in the order the command line offers them.
inline constexpr NdfKind kAllNdfKinds[] = {NdfKind::kGgx, NdfKind::kBeckmann};

std::string_view ToString(NdfKind kind);

struct Ndf {
  NdfKind kind = NdfKind::kGgx;
  double alpha = 1.0;  // NDF width; alpha = perceptualRoughness^2.

  double D(const Vec3 &h) const;
  // mu * Lambda(mu): finite at mu = 0. See ggx.h and beckmann.h.
  double MuLambda(double mu) const;

  // Visible normals: pdf with respect to solid angle of h,
  //   D_o(h) = G1(o) max(0, o.h) D(h) / mu_o = max(0, o.h) D(h) / (mu_o + mu_o Lambda(o)),
  // the second form finite at mu_o = 0.
  Vec3 SampleVisibleNormal(const Vec3 &o, double u1, double u2) const;
  double VisibleNormalPdf(const Vec3 &o, const Vec3 &h) const;

  // NDF sampling: pdf D(h) cos(theta_h) with respect to solid angle of h;
  // u1 is the CDF in theta (NormalFromCdf), u2 the azimuth / (2 pi).
  Vec3 SampleNormal(double u1, double u2) const;
  double NormalPdf(const Vec3 &h) const { return D(h) * h.z; }

  // The map behind SampleNormal, exposed for the quadrature integrator.
  void NormalFromCdf(double xi, double *cosTheta_h, double *sinTheta_h) const;
  double CdfFromTheta(double theta_h) const;
};

}  // namespace lutbake
