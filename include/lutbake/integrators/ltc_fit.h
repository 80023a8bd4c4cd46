// Fitting linearly transformed cosines (models/ltc.h) to a cosine-weighted
// lobe f(v, l) (n.l), by a deterministic quadrature: the half-vector rule
// (half_vector_rule.h).
//
// The fit. The lobe is approximated by magnitude D(l). With
// m = int f (n.l) dl, the L1 error on the whole sphere is
//   int |f (n.l) / m - D| dl = 2 - 2 int_{l.z > 0} min(f (n.l) / m, D) dl,
// (|a - b| = a + b - 2 min(a, b), both densities integrate to 1 and f = 0
// below the horizon), and on the upper hemisphere alone (the lobe error)
//   e_lobe = int_{l.z>0} |f (n.l) / m - D| dl = 2 - leakage - 2 int_{l.z>0} min(f (n.l) / m, D) dl.
// The minimum is at most f (n.l) / m, whose peak the rule resolves, so the
// rule integrates it well wherever the LTC lies (to ~3e-4, up to 1.3e-3 at
// grazing views, limited by the kinks of min() inside the panels: measured
// against level 2 and a direct quadrature in the tests); leakage is exact
// (LtcLeakage). The objective minimised is
//   J = e_lobe + leakageWeight * leakage
// (weight 1: the L1 error on the sphere), over the four entries of M^-1 in
// the parameters (theta*, log A, log rho, beta):
//   m00 = rho cos(theta*), m02 = -rho sin(theta*),
//   m20 = A sin(theta*) + B cos(theta*), m22 = A cos(theta*) - B sin(theta*), B = beta rho,
// theta* the axis of the LTC (M^-1 (sin theta*, 0, cos theta*) is along +z),
// A ~ its width out of the view plane, A / rho within it, beta its skew; then
// det M^-1 = rho A > 0 for every parameter. Nelder-Mead from the fitted
// neighbour; at mu = 1 the lobe is axisymmetric and so is the fit (theta* = 0,
// rho = 1, beta = 0: one parameter).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "lutbake/core/math.h"
#include "lutbake/integrators/half_vector_rule.h"
#include "lutbake/models/ltc.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/oren_nayar.h"
#include "lutbake/models/sheen.h"
#include "lutbake/models/smith.h"

namespace lutbake {

// The quadrature a lobe is integrated with (the fit's objective, the errors,
// the rectangles' references):
//   kHalfVector      the half-vector rule (half_vector_rule.h) of width
//                    quadratureAlpha: lobes that follow a half vector
//                    (microfacet; sheen, broad, with its mass graded toward
//                    the horizon of h);
//   kLightDirection  the light-direction rule (light_direction_rule.h):
//                    lobes smooth over the hemisphere (diffuse), panels cut
//                    at theta_o and cos(phi) = 0.
enum class LtcQuadrature { kHalfVector, kLightDirection };

// The lobe: f(v, l) (n.l) at mu_o = v.z for a direction l (unit, any
// hemisphere: it returns 0 for l.z <= 0), with its quadrature (and the
// width the half-vector rule resolves: alpha of a microfacet lobe; 1 for a
// broad one) and, optionally, its exact magnitude int f (n.l) dl and fresnel
// int f (n.l) (1 - v.h)^5 dl (otherwise the rule integrates them).
struct LtcLobe {
  std::function<double(double mu_o, const Vec3 &l)> cosineWeighted;
  double quadratureAlpha = 1.0;
  std::function<void(double mu_o, double *magnitude, double *fresnel)> moments;
  LtcQuadrature quadrature = LtcQuadrature::kHalfVector;
};

// The lobe's rule over the upper hemisphere (halfCircle: phi in [0, pi],
// weights doubled) and over a polygon clipped at the horizon, at a level
// (0: the fit, 1: errors, 2: the check of level 1).
std::vector<LtcNode> LtcLobeRule(const LtcLobe &lobe, double mu_o, int level, bool halfCircle);
std::vector<LtcNode> LtcLobePolygonRule(const LtcLobe &lobe, double mu_o, int level,
                                        const Vec3 *vertices, int count);

// The microfacet lobe f = D G2 / (4 mu_o mu_i) (F = 1) times mu_i, of the
// given NDF and Smith G2; moments from the albedo quadrature (E = A + B and
// B at tolerance 1e-10). At alpha = 0 the lobe is a mirror: its moments are
// E = 1, B = (1 - mu)^5 exactly, and the LTC is fitted at kLtcMinimumAlpha.
LtcLobe MicrofacetLtcLobe(const Ndf &ndf, SmithForm smith);
inline constexpr double kLtcMinimumAlpha = 1e-5;  // ltc_code's MIN_ALPHA

// The sheen lobe D_Charlie V (F = 1) times mu_i (models/sheen.h), of width
// alpha in [0, 1]. The rule follows it with quadratureAlpha = max(alpha,
// kLtcMinimumSheenAlpha) (its mass lies on the tail's panels, graded toward
// the horizon where it peaks). magnitude from IntegrateSheenAlbedo
// (tolerance 1e-10), fresnel by the rule at level 2 (within 6e-9 of
// IntegrateSheenSchlickWeightedAdaptive, which takes 30 ms a point). At
// alpha = 0 there is no lobe: magnitude = fresnel = 0.
LtcLobe SheenLtcLobe(SheenVisibility visibility, double alpha);
inline constexpr double kLtcMinimumSheenAlpha = 1e-3;

// Burley's diffuse (Disney 2012; models/burley.h) times mu_i at perceptual
// roughness r, base colour 1: the light-direction rule; no exact moments
// here (table burley_E holds the closed-form magnitude).
LtcLobe BurleyLtcLobe(double perceptualRoughness);
// Oren-Nayar diffuse (models/oren_nayar.h) times mu_i at sigma (radians),
// reflectance 1: the light-direction rule, whose panels are cut at its kinks
// (theta_i = theta_o, cos(dphi) = 0).
LtcLobe OrenNayarLtcLobe(OrenNayarVariant variant, double sigma);

// int f (n.l) dl and int f (n.l) (1 - v.h)^5 dl by the rule.
void IntegrateLobeMoments(const LtcLobe &lobe, double mu_o, int level, double *magnitude,
                          double *fresnel);

// magnitude and fresnel of a lobe smooth over the hemisphere, by nested
// adaptive Gauss-Kronrod (gauss_kronrod.h) over theta_l (split at theta_o)
// and phi in [0, pi] (split at pi/2; doubled: the lobes are even in l.y),
// the half vector from normalize(v + l): the diffuse LTC tables' reference
// for check, independent of the light-direction rule's fixed panels. Bounds
// 16 x the Gauss-Kronrod estimates of both levels plus 1e-13.
struct LtcMomentsReference {
  double magnitude = 0, fresnel = 0;
  double magnitudeBound = 0, fresnelBound = 0;
  uint64_t evaluations = 0;
};
LtcMomentsReference IntegrateLobeMomentsAdaptive(const LtcLobe &lobe, double mu_o,
                                                 double tolerance);

// A light: a planar rectangle facing the origin; vertices in winding order.
struct LtcRectangle {
  Vec3 vertices[4];
};
// The fixed set of the polygon error: 12 rectangles of half-angles 10 to 60
// degrees, centres from the normal to 88 degrees, around the mirror azimuth
// and elsewhere, rolled; 5 of them cross the horizon. Listed in ltc_fit.cpp.
const std::vector<LtcRectangle> &LtcTestRectangles();

// The reference irradiances of the rectangles: int_{P, l.z >= 0} f (n.l) dl.
std::vector<double> RectangleLobeIntegrals(const LtcLobe &lobe, double mu_o, int level);

// Rectangles that receive less than this share of the lobe are left out of
// the polygon error (their relative error measures the far tail only).
inline constexpr double kLtcPolygonMinimumShare = 0.02;

struct LtcErrors {
  double lobe = 0;     // int_{l.z>0} |f (n.l) - m D| dl / m
  double polygon = 0;  // max over rectangles |m int_P D - int_P f (n.l)| / int_P f (n.l)
  double leakage = 0;  // int_{l.z<0} D dl
};

// The lobe error by the level-1 rule (formula above), the polygon error
// against `references` (RectangleLobeIntegrals; empty: polygon = 0), leakage.
LtcErrors MeasureLtcErrors(const LtcLobe &lobe, double mu_o, double magnitude,
                           const LtcMatrix &minv, const std::vector<double> &references);
// The same for an LTC whose own magnitude ltcMagnitude scales D (a table
// fitted elsewhere, its magnitude not the lobe's): the errors are of
// ltcMagnitude D against f (n.l), divided by the lobe's magnitude (lobe) or
// the reference (polygon).
LtcErrors MeasureLtcErrors(const LtcLobe &lobe, double mu_o, double magnitude, double ltcMagnitude,
                           const LtcMatrix &minv, const std::vector<double> &references);

// The lobe error of ltcMagnitude D against f (n.l), divided by magnitude, by
// the rule at `level` (formula above, with D scaled by c = ltcMagnitude /
// magnitude: Q[f] / m + c (1 - leakage) - 2 Q[min(f (n.l) / m, c D)]).
double LtcLobeError(const LtcLobe &lobe, double mu_o, double magnitude, double ltcMagnitude,
                    const LtcMatrix &minv, int level);

struct LtcFitSettings {
  double leakageWeight = 1.0;  // J = e_lobe + leakageWeight * leakage
  int maxEvaluations = 600;    // Nelder-Mead budget per texel
  // false: FitLtcTexel leaves magnitude and fresnel 0 (a caller that
  // integrates them itself, as table ltc_ggx does with table E's quadrature).
  bool moments = true;
};

struct LtcTexel {
  LtcMatrix minv;
  double magnitude = 0, fresnel = 0;
  double objective = 0;  // J at the fit, by the level-0 rule
  int evaluations = 0;
};

// The parameters (theta*, log A, log rho, beta) above of a matrix with
// det M^-1 > 0 (the cosine's, all 0, otherwise).
std::array<double, 4> LtcParameters(const LtcMatrix &minv);

// Fits one texel from `start`. mu_o == 1 fits the axisymmetric family.
LtcTexel FitLtcTexel(const LtcLobe &lobe, double mu_o, const LtcMatrix &start,
                     const LtcFitSettings &settings);

// The 64 x 64 layout of ltc_code and three.js. Texel (i, j), stored at
// i * size + j (row i, column j; three.js's DataTexture row i is its v):
//   r_j  = j / (size - 1)               (u = r: perceptual roughness)
//   mu_i = 1 - (i / (size - 1))^2        (v = sqrt(1 - mu))
// at texel centres: three.js samples uv * (size - 1) / size + 0.5 / size.
// alpha = r^2 (fitted at max(alpha, kLtcMinimumAlpha)). ltc_code computes
// theta = min(1.57, acos(mu_i)), so its last row is fitted at
// mu = cos(1.57) = 7.96e-4; here it is mu = 0 exactly (the grazing limit).
double LtcTableMu(int i, int size);
double LtcTableRoughness(int j, int size);

struct LtcTable {
  int size = 0;
  std::vector<double> mu, roughness;  // the axes: mu of row i, r of column j
  // size * size each, texel (i, j) at i * size + j.
  std::vector<double> m00, m20, m02, m22, magnitude, fresnel;
  std::vector<double> lobeError, polygonError, leakage;  // empty unless errors were asked
  int64_t evaluations = 0;                               // objective evaluations
  LtcMatrix Matrix(int texel) const { return {m00[texel], m20[texel], m02[texel], m22[texel]}; }
};

// With `errors`, the error maps: lobe error by the level-1 rule (within
// ~1.3e-3 of level 2 at grazing views, 3e-4 elsewhere), polygon errors
// against references by the level-0 rule (within 1.1e-4 relative of
// level 2 for the rectangles counted), leakage exact.
//
// The order that keeps neighbours on one branch and makes the result
// bit-identical for any thread count: the column r = 1 sequentially from
// mu = 1 (axisymmetric, started at the cosine M^-1 = I) to the last row, then
// every row (one mu) in parallel, each sequentially from r = 1 down to r = 0,
// every texel started from the one fitted before it; no value depends on
// which thread ran it, and there are no reductions across rows.
// lobeAt(r) gives the lobe at perceptual roughness r. Row i is fitted at
// max(LtcTableMu(i, size), muFloor).
LtcTable FitLtcTable(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt, int size,
                     const LtcFitSettings &settings, bool errors, double muFloor = 0.0);

// The fit on any grid of view cosines and perceptual roughnesses (a table's
// texel centres), in the order FitLtcTable uses: the largest roughness
// first, sequentially from the largest mu down (started at the cosine
// M^-1 = I), then each mu in parallel from the largest roughness down, every
// texel started from the one fitted before it. The path to texel (i, j) is
// therefore: the mu nodes above mu_i in decreasing order, then mu_i, at the
// top roughness; then the roughness nodes between r_j and the top in
// decreasing order, then r_j. Nothing depends on the thread that runs it.
// Texel (i over mu, j over roughness) at i * roughness.size() + j; mu and
// roughness need not be sorted (but hold no repeats).
std::vector<LtcTexel> FitLtcGrid(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt,
                                 const std::vector<double> &mu,
                                 const std::vector<double> &roughness,
                                 const LtcFitSettings &settings);

// The fit at one point (mu, r) along the same path through a grid's nodes:
// at a node of the grid, bit for bit FitLtcGrid's texel there. A point off
// the nodes is reached from the nodes above it; a roughness above the top
// node is fitted from the top node's fit at mu.
LtcTexel FitLtcPoint(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt, double mu,
                     double perceptualRoughness, const std::vector<double> &gridMu,
                     const std::vector<double> &gridRoughness, const LtcFitSettings &settings);

// The sheen table of issue 28 (F = 1), alpha = r^2 (alphaIsRoughnessSquared)
// or alpha = r. With the Charlie visibility the albedo grows as 1 / mu at
// grazing (its fitted Lambda stays finite at the horizon), so the last row is
// fitted at mu = cos(1.57) = 7.96e-4, where ltc_code fits its own last row.
LtcTable FitSheenLtcTable(SheenVisibility visibility, bool alphaIsRoughnessSquared, int size,
                          const LtcFitSettings &settings, bool errors);

// The GGX table of issue 28 (F = 1).
LtcTable FitGgxLtcTable(NdfKind ndf, SmithForm smith, int size, const LtcFitSettings &settings,
                        bool errors);

}  // namespace lutbake
