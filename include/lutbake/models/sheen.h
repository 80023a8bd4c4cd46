// The sheen lobe of glTF's KHR_materials_sheen (Estevez and Kulla 2017,
// "Production Friendly Microfacet Sheen BRDF"), sheen colour 1, F = 1:
//
//   f(o, i) = D(h) V(o, i),  h = normalize(o + i),  mu = cos(theta) = n.v.
//
// The Charlie NDF of width alpha in (0, 1] (q = 1 / alpha):
//   D(h) = (2 + q) sin(theta_h)^q / (2 pi),
// normalised so that the integral of D cos(theta_h) over the hemisphere is 1:
// with x = sin(theta_h), cos(theta_h) sin(theta_h) d(theta_h) = x dx and
// int_0^1 x^(q + 1) dx = 1 / (q + 2).
//
// Two visibility terms:
//   charlie:   V = 1 / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i),
//   ashikhmin: V = 1 / (4 (mu_i + mu_o - mu_i mu_o)),
// with Charlie's fitted Lambda exactly as the glTF extension's README writes
// it (CharlieLambda below). Integrals of f mu_i need only W = V mu_i, which
// stays finite as mu_i -> 0 for both (SheenCosineVisibility).
//
// In terms of the light i at azimuth phi from the view (s = sqrt(1 - mu^2)):
//   |o + i|^2 = T + (mu_o + mu_i)^2,
//   T = |o + i|^2 sin^2(theta_h) = (s_o - s_i)^2 + 4 s_o s_i cos^2(phi / 2),
// both terms non-negative, so sin^2(theta_h) = T / (T + (mu_o + mu_i)^2) is
// formed without cancellation and
//   D = (2 + q) / (2 pi) exp(-(q / 2) log1p((mu_o + mu_i)^2 / T)).
// This is the only form that keeps D's relative accuracy when q is huge
// (alpha = 1e-24: sin^2 = 1 - 1e-20 would round to 1 and D would be lost).
#pragma once

#include <array>
#include <string_view>

#include "lutbake/core/math.h"

namespace lutbake {

// The sheen's visibility V (see SheenCosineVisibility): Charlie's
// height-correlated Smith form with Estevez-Kulla's fitted Lambda, OSPRay's
// variant of it (the light's Lambda softened, SheenDistribution.ih
// evalLambdaI), or Ashikhmin's closed form.
enum class SheenVisibility { kCharlie, kAshikhmin, kOspray };
// Every form, in the order the command line offers them.
inline constexpr SheenVisibility kAllSheenVisibilities[] = {
    SheenVisibility::kCharlie, SheenVisibility::kAshikhmin, SheenVisibility::kOspray};

// "charlie", "ashikhmin", "ospray".
std::string_view ToString(SheenVisibility visibility);
// The inverse of ToString; false (and *visibility unchanged) for any other text.
bool ParseSheenVisibility(std::string_view text, SheenVisibility *visibility);

// (2 + 1 / alpha) / (2 pi): D at theta_h = pi/2, its largest value.
double CharlieNormalization(double alpha);

// D from sin^2(theta_h) in [0, 1].
double CharlieD(double alpha, double sin2Theta_h);
// D from cos(theta_h) in [0, 1], with sin^2 = (1 - c)(1 + c) and its logarithm
// taken as log1p(-c^2) near the horizon: accurate however small alpha is.
double CharlieDFromCos(double alpha, double cosTheta_h);
// D at h = normalize(o + i) from the two cosines and cos(phi / 2), phi the
// azimuth between o and i (the form above). mu_o + mu_i > 0 or T > 0.
double CharlieDFromDirections(double alpha, double mu_o, double mu_i, double cosHalfPhi);

// The glTF fit of Charlie's Lambda, mu in [0, 1]:
//   l(x) = a / (1 + b x^c) + d x + e, each coefficient mix(p, q, w) = p (1 - w) + q w
//   between its values for alpha = 1 and alpha = 0, w = (1 - alpha)^2;
//   Lambda(mu) = exp(l(mu))                    for mu < 0.5,
//                exp(2 l(0.5) - l(1 - mu))     otherwise.
// Lambda is decreasing, C1 but not C2 at mu = 0.5, and has the x^c (c ~ 0.17
// to 0.2) branch points at mu = 0 and mu = 1; Lambda(0) = exp(a + e) is
// 3e7 (alpha = 1) to 8e8 (alpha = 0).
double CharlieLambda(double mu, double alpha);

// The fit's exponent c (the branch-point order of Lambda at mu = 0 and 1).
double CharlieLambdaExponent(double alpha);

// Whether the visibility is Charlie's form 1 / (1 + Lambda(mu_o) +
// Lambda_i(mu_i)) (charlie, ospray): its 1 / mu_o, its branch points.
bool UsesCharlieLambda(SheenVisibility visibility);
// The light's Lambda_i in that form: Lambda(mu_i) (charlie), or OSPRay's
// artistic "softer light terminator" (SheenDistribution.ih, evalLambdaI),
//   Lambda_i(mu_i) = Lambda(mu_i)^(1 + 2 (1 - mu_i)^8)     (ospray),
// computed as exp((1 + 2 (1 - mu_i)^8) l) from the fit's log l. Like
// Lambda, it decreases with mu_i (its exponent grows where Lambda > 1, and
// where Lambda < 1, mu_i > ~0.6, the exponent's slope 16 (1 - mu_i)^7 <
// 0.03 is dwarfed by log Lambda's; SheenModel.OsprayLightLambdaSoftens-
// Charlies checks it on a grid), so W below grows with mu_i.
double SheenLightLambda(SheenVisibility visibility, double mu_i, double alpha);

// W = V mu_i, the cosine-weighted visibility, for mu_o in (0, 1] (charlie) or
// [0, 1] (ashikhmin) and mu_i in [0, 1]:
//   charlie:   W = 1 / (4 mu_o (1 + Lambda(mu_o) + Lambda(mu_i))),
//   ospray:    W = 1 / (4 mu_o (1 + Lambda(mu_o) + Lambda_i(mu_i))) (above),
//   ashikhmin: W = mu_i / (4 (mu_i + mu_o (1 - mu_i)))   (0 at mu_i = mu_o = 0).
// The directional albedo is the integral of D W over the light directions.
double SheenCosineVisibility(SheenVisibility visibility, double alpha, double mu_o, double mu_i);

// Charlie lobe sampling: the measure D(h) cos(theta_h) d(omega_h) is
//   (2 + q) x^(q + 1) dx d(phi) / (2 pi),  x = sin(theta_h),
// whose CDF in theta is xi = x^(q + 2). So x = xi^(alpha / (2 alpha + 1)),
// computed as exp(e log(xi)) with e = alpha / (2 alpha + 1), and
// cos(theta_h) = sqrt(-expm1(2 e log(xi))), which keeps its relative
// accuracy where x rounds to 1 (tiny alpha). phi = 2 pi u1. u in [0,1)^2.
// The density of the result is CharlieHalfVectorPdf with respect to solid
// angle of h.
Vec3 SampleCharlieHalfVector(double alpha, double u0, double u1);
// D(h) cos(theta_h), with respect to solid angle of h; 0 below the horizon.
double CharlieHalfVectorPdf(double alpha, double cosTheta_h);
// The inverse of SampleCharlieHalfVector: {u0, u1} with u0 = sin(theta_h)^(q + 2)
// and u1 = phi / (2 pi) in [0, 1).
std::array<double, 2> InvertCharlieHalfVectorSample(double alpha, const Vec3 &h);

}  // namespace lutbake
