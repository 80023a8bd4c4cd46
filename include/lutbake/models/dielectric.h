// A rough dielectric interface (Walter, Marschner, Li and Torrance 2007):
// reflection and refraction by microfacets of a GGX or Beckmann NDF, Smith
// masking, the exact unpolarised dielectric Fresnel. Local frame n = +z; o
// is the direction the energy arrives from (the view), mu_o = o.z in (0, 1].
//
// Relative index. eta = (index on the far side) / (index on the side of o):
// eta > 1 entering a denser medium, eta < 1 leaving it. With c = o.h > 0
// (h a microfacet normal, h.z > 0) and
//   W = sqrt(eta^2 - 1 + c^2)          (= eta cos of the refracted angle),
// the facet refracts when eta^2 - 1 + c^2 > 0; otherwise (eta < 1, c below
// the critical cosine c_crit = sqrt(1 - eta^2)) it reflects everything.
//
// Directions. The mirror direction i_r = 2 c h - o; the refracted one
//   i_t = ((c - W) h - o) / eta,   c - W = (1 - eta^2) / (c + W),
// the second form exact at eta = 1 (i_t = -o) without cancellation. Then
// i_t.h = -W / eta and mu_t = i_t.z = ((c - W) h.z - mu_o) / eta. Conversely
// the generalised half vector of a pair (o, i_t) is h = -+(o + eta i_t) / |.|,
// the sign that makes h.z > 0 (for a true refraction pair o.h > 0 and
// i.h < 0 follow).
//
// Jacobians (d omega_h / d omega_i):
//   reflection:  1 / (4 |o.h|)
//   refraction:  eta^2 |i.h| / (o.h + eta i.h)^2
//
// Fresnel. F = (r_s^2 + r_p^2) / 2 with, for a refracting facet,
//   r_s = (c - W) / (c + W)          = (1 - eta^2) / (c + W)^2,
//   r_p = (eta^2 c - W) / (eta^2 c + W) = (eta^2 - 1) ((eta^2 + 1) c^2 - 1) / (eta^2 c + W)^2,
// and 1 - F = (t_s + t_p) / 2, t_s = 4 c W / (c + W)^2, t_p = 4 eta^2 c W /
// (eta^2 c + W)^2; the rewritten forms keep F and 1 - F to full relative
// precision as eta -> 1 and c -> 0. This is ExactFresnel(eta, 0, c)
// (fresnel.h), which the tests compare it to.
//
// The scattered energy, per unit energy arriving along o, with visible
// normals h ~ D_o(h) = G1(o) max(0, o.h) D(h) / mu_o:
//   glass:      E = E_h[F(c) G2(o, i_r)/G1(o) 1{mu_r > 0} + (1 - F(c)) G2(o, i_t)/G1(o) 1{mu_t <
//   0}] reflection: E = E_h[F(c) G2(o, i_r)/G1(o) 1{mu_r > 0}]
// G2 of (o, i) is the Smith form's (smith.h) with Lambda(|mu_i|) for the
// light on either side. The bracket is the facet weight (DielectricFacetWeight):
// it lies in [0, 1], as G2 / G1(o) does for both forms. In solid angle of i
// the same energy is int f(o, i) |mu_i| d(omega_i) with the BSDF (the
// transmission term without the eta^2 radiance factor):
//   f_r = F D G2 / (4 mu_o mu_i),
//   f_t = |o.h| |i.h| eta^2 (1 - F) D G2 / (mu_o |mu_i| (o.h + eta i.h)^2),
// by the Jacobians above (DielectricBsdfCosine).
//
// Closed forms:
//  - alpha = 0 (smooth interface): glass E = F + (1 - F) = 1, reflection E
//    = F(mu_o) (DielectricSmoothAlbedo).
//  - eta = 1: F = 0 and i_t = -o for every facet, so glass E = G2(o, -o) /
//    G1(o): (1 + Lambda(mu_o)) / (1 + 2 Lambda(mu_o)) correlated, G1(mu_o)
//    separable; reflection E = 0 (DielectricIndexMatchedAlbedo). The model
//    keeps its shadowing: a rough interface between equal indices still
//    loses energy (light blocked by a facet is not redirected).
//
// Reciprocity. The eta^2-free transmission BSDF above obeys, for the same
// pair of directions and facet (F, G2 and D are symmetric in o and i),
//   f_t,eta(o, i) = eta^2 f_t,1/eta(i, o).
// The cosine-weighted averages T_avg = (1/pi) int int f_t |mu_o| |mu_i| then give
//   T_avg(eta) = eta^2 T_avg(1/eta),   T_avg = glass E_avg - reflection E_avg,
// i.e. (glass_Eavg(eta) - spec_Eavg(eta)) = eta^2 (glass_Eavg(1/eta) - spec_Eavg(1/eta)).
// (For a smooth interface this is 1 - F_avg(eta) = eta^2 (1 - F_avg(1/eta)).)
// No such identity holds between the reflection parts or pointwise in mu_o.
#pragma once

#include <string_view>

#include "lutbake/core/math.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"

namespace lutbake {

enum class DielectricLobes { kReflection, kReflectionAndTransmission };

// The relative IORs the integrators accept, [1/128, 128]: beyond any real
// pair of media, and wide enough for Blender Cycles' last IOR slice
// (99.503, and 1/99.503 in its inverse table), where the panel rule, the
// adaptive reference and the sampler were checked against one another
// (dielectric_quadrature_test.cpp, dielectric_estimator_test.cpp).
inline constexpr double kMinRelativeIor = 1.0 / 128.0;
inline constexpr double kMaxRelativeIor = 128.0;

// "reflection", "reflection+transmission".
std::string_view ToString(DielectricLobes lobes);

struct DielectricFresnelTerms {
  double F = 1.0;  // reflectance
  double T = 0.0;  // 1 - F, computed without cancellation
  double W = 0.0;  // sqrt(eta^2 - 1 + c^2); 0 under total internal reflection
};

// F and 1 - F at c = o.h in [0, 1] for relative index eta > 0 (see above).
DielectricFresnelTerms DielectricFresnel(double eta, double cosTheta_oh);

// The refracted direction of o through h (o.h > 0), relative index eta.
// Returns false under total internal reflection (i is then untouched).
bool Refract(const Vec3 &o, const Vec3 &h, double eta, Vec3 *i);

// The generalised half vector of a refraction pair: -+(o + eta i) normalised,
// oriented so that h.z >= 0. The caller checks o.h > 0 and i.h < 0.
Vec3 RefractionHalfVector(const Vec3 &o, const Vec3 &i, double eta);

// d(omega_h) / d(omega_i) for reflection and refraction (see above).
double ReflectionJacobian(double cosTheta_oh);
double RefractionJacobian(double eta, double cosTheta_oh, double cosTheta_ih);

// The facet weight: the bracket of E above for the facet h (o.h > 0) with
// the view o (o.z = mu_o, L_o = mu_o Lambda(mu_o)), in [0, 1]. The arguments
// are the cosines c = o.h, h.z and the mirror's mu_r = 2 c h.z - mu_o, which
// callers compute in their own stable form.
double DielectricFacetWeight(const Ndf &ndf, SmithForm smith, DielectricLobes lobes, double eta,
                             double mu_o, double L_o, double cosTheta_oh, double cosTheta_h,
                             double mu_r);

// f(o, i) |mu_i| for any light direction i (upper: reflection; lower:
// transmission without eta^2), the integrand of E in solid angle of i.
double DielectricBsdfCosine(const Ndf &ndf, SmithForm smith, DielectricLobes lobes, double eta,
                            const Vec3 &o, const Vec3 &i);

// E at alpha = 0 and at eta = 1 (see above).
double DielectricSmoothAlbedo(DielectricLobes lobes, double eta, double mu_o);
double DielectricIndexMatchedAlbedo(const Ndf &ndf, SmithForm smith, DielectricLobes lobes,
                                    double mu_o);

// The standard rough-dielectric sampler, for renderers and tests: a visible
// normal h (u0, u1; Ndf::SampleVisibleNormal), then reflection with
// probability F(o.h), refraction otherwise (u2 in [0, 1)). The weight is
// f |mu_i| / pdf = G2(o, i) / G1(o) (0 when i ends on the wrong side), the
// pdf with respect to solid angle of i: F D_o(h) J_r or (1 - F) D_o(h) J_t.
struct DielectricSample {
  Vec3 i;
  double weight = 0.0;
  bool reflected = true;
};
DielectricSample SampleDielectric(const Ndf &ndf, SmithForm smith, DielectricLobes lobes,
                                  double eta, const Vec3 &o, double u0, double u1, double u2);

}  // namespace lutbake
