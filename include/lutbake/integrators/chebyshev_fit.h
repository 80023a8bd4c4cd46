// Piecewise Chebyshev fits of a table's closed form, with a certified
// maximum error over the whole fitted domain (--format fit).
//
// The model. A fit maps the table's coordinates (x, y) (mu and r, as
// `lutbake eval` takes them; a 1D table has x only) onto a unit square
// (s_x, s_y) by one of the FitMap maps below, cuts each s axis at breaks
// b_0 < ... < b_P into patches, and holds in each patch a tensor Chebyshev
// series of nx x ny coefficients per channel,
//   p(z_x, z_y) = sum_{i < nx, j < ny} c_ij T_i(z_x) T_j(z_y),
//   z = (2 s - (b_k + b_{k+1})) / (b_{k+1} - b_k) in [-1, 1] on patch k.
// The coefficients interpolate the exact values at the patch's Chebyshev
// points of the first kind. The evaluation (EvaluateFloat) is the float32
// arithmetic of the emitted C++ and shader code, step by step.
//
// The certificate. Per patch and channel the error e = p - f is bounded by
//   max over a (g_x + 1) x (g_y + 1) grid of |p - f~|          (measured)
//   + h_x^2 / 8 max|e_zz_x| + h_y^2 / 8 max|e_zz_y|            (between nodes)
//   + the exact values' own bounds (f~ - f)                     (integrators)
//   + the float32 evaluation's rounding                          (a priori)
// where h = 2 / g is the grid step in z. The middle term is the error of
// bilinear interpolation of e between grid nodes: no spike of e can hide
// between nodes unless its second derivative exceeds the bound used. That
// bound is |p_zz| + |f_zz|: |p_zz| proved from the coefficients (the
// Chebyshev coefficients d_k of the second derivative of every row or
// column, by the recurrence d_{k-1} = d_{k+1} + 2 k c_k applied twice, so
// |p_zz_x| <= sum over rows of sum |d_k|, never above the cruder
// sum |c_ij| i^2 (i^2 - 1) / 3), |f_zz| estimated: twice the largest second
// difference (f(z - h) - 2 f(z) + f(z + h)) / h^2 of the exact values along
// every grid line of the patch (a mean-value of f_zz over two steps; the
// factor 2 is the safety against f_zz peaking between nodes; it is an
// estimate, not a proof, and the one term of the bound that is not proved).
// The rounding term follows the float32 evaluation under one of two
// precision models (FitPrecision): +, -, * correctly rounded (u / 2
// relative, u = 2^-24), log within 3 ulp (6 u) or 2^-21 absolute near 1,
// and / and sqrt correctly rounded (kIeee: the emitted C++, IEEE binary32
// without -ffast-math, and EvaluateFloat) or within 2.5 ulp (5 u) and 4.5
// ulp (9 u: GLSL ES 3.00's and WGSL's 1 / inversesqrt) (kShader: the
// emitted shaders, whose files state that bound). The coordinate map's error ds in s (per map and
// patch, FitRoundingBound), then z = (2 s - lo - hi) / (hi - lo) within
// dz <= (2 ds + u) / w + 7 u, times the proved slope |p_z| <= sum |d_k| of
// the first derivative's coefficients (as above); and Clenshaw's recurrence
// (each step's rounding at most 2 u (|c_k| + 2 |b_k+1| + |b_k+2|),
// propagated by |U_k| <= k + 1, with |b_k| <= sum_{m >= k} |c_m| (m - k + 1)).
// The coefficients are float32 values when the grid term is measured, so
// their own rounding is in it already.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lutbake {

inline constexpr int kMaxFitChannels = 4;

// How (x, y) maps onto (s_x, s_y) in [0, 1]^2, with the unit coordinates
// a = (x - xLo) / (xHi - xLo) and b = (y - yLo) / (yHi - yLo), clamped to
// [0, 1]:
enum class FitMap {
  kLinear,  // s = (a, b)
  kSqrtX,   // s = (sqrt(a), b): a square-root edge at x = xLo (mu = 0)
  // s = ((log x - log xLo) / (log xHi - log xLo), b), xLo > 0: a table that
  // changes by about as much per decade of mu near its edge (sheen_E).
  kLogX,
  // The corner blow-up around (x, y) = (xLo, yLo): with q = sqrt(a),
  //   s_x = q / (q + b) (0 where q = 0), s_y = max(q, b).
  // A table with a boundary layer of width ~ alpha at mu = 0 (microfacet
  // albedo near the mirror: it depends on mu / alpha there and has no limit
  // at (0, 0)) is smooth in (s_x, s_y): rays into the corner become lines
  // s_x = const. Patches break at s_x = 1/2 (where max(q, b) switches), and
  // s_y >= breaksY[0] > 0 leaves out the corner's box q, b < breaksY[0]
  // where the table has no limit at the corner (0 where it is a regular point).
  kCorner,
  // s = ((log(x + c) - log(xLo + c)) / (log(xHi + c) - log(xLo + c)),
  //      (log y - log yLo) / (log yHi - log yLo)), c = xShift >= 0, yLo > 0:
  // a table that changes by about as much per decade of both coordinates
  // (sheen_E: ~ r^-1/2 toward small r, log-like toward small mu, with c
  // keeping the polynomial degree in mu from going to the last decades).
  kLogXY,
};

const char *ToString(FitMap map);
bool ParseFitMap(const std::string &text, FitMap *map);

struct PiecewiseChebyshev {
  int dims = 2;  // 1: x only (ny = 1, one y patch)
  int channels = 1;
  FitMap map = FitMap::kLinear;
  double xLo = 0.0, xHi = 1.0, yLo = 0.0, yHi = 1.0;
  double xShift = 0.0;                   // kLogXY's c (a float32 value)
  std::vector<double> breaksX, breaksY;  // in s, increasing
  int nx = 1, ny = 1;                    // coefficients per patch along each axis
  // c_ij of channel c, patch (kx, ky):
  //   coefficients[(((c * patchesY + ky) * patchesX + kx) * ny + j) * nx + i],
  // each exactly a float32 (rounded when fitted), as the emitted code holds it.
  std::vector<double> coefficients;

  int PatchesX() const { return static_cast<int>(breaksX.size()) - 1; }
  int PatchesY() const { return static_cast<int>(breaksY.size()) - 1; }
  int CoefficientsPerChannel() const { return PatchesX() * PatchesY() * nx * ny; }
  const double *Patch(int channel, int kx, int ky) const {
    return coefficients.data() +
           static_cast<size_t>(((channel * PatchesY() + ky) * PatchesX() + kx) * ny * nx);
  }
  // s of (x, y) in double, clamped to the breaks' range.
  void Map(double x, double y, double *sx, double *sy) const;
  // (x, y) of s (inverse of Map inside the domain).
  void Unmap(double sx, double sy, double *x, double *y) const;
  // The series in double at (x, y).
  double Evaluate(int channel, double x, double y) const;
  // As the emitted code evaluates it: float32 throughout, x and y rounded
  // to float first.
  float EvaluateFloat(int channel, double x, double y) const;
};

// The map's float32 constants, as the evaluation and the emitted code use
// them: a = (X - xOrigin) xScale with X = x, or log(max(x, xLo) + xShift)
// where logX; b likewise from y (log(max(y, yLo)) where logY).
struct FitMapConstants {
  bool logX = false, logY = false;
  float xOrigin = 0.0f, xScale = 1.0f, yOrigin = 0.0f, yScale = 1.0f;
};
FitMapConstants FitMapConstantsOf(const PiecewiseChebyshev &f);

// The float32 arithmetic a rounding bound assumes (see the top).
enum class FitPrecision { kIeee, kShader };

// The certificate of one channel (all bounds absolute, in the table's units).
struct FitChannelBound {
  double gridError = 0.0;             // max |p - f~| over the grid nodes
  double betweenNodes = 0.0;          // the interpolation term (worst patch)
  double exactError = 0.0;            // max bound of the exact values used
  double rounding = 0.0;              // float32 evaluation, kIeee (worst patch)
  double shaderRounding = 0.0;        // the same, kShader
  double bound = 0.0;                 // max over patches of the sum, + exactError
  double shaderBound = 0.0;           // the same with shaderRounding
  double worstX = 0.0, worstY = 0.0;  // where gridError is
};

struct FitCertificate {
  std::vector<FitChannelBound> channels;
  double maxError = 0.0;        // max over channels of bound (the C++: kIeee)
  double shaderMaxError = 0.0;  // max over channels of shaderBound (the shaders)
  uint64_t gridPoints = 0;      // exact values evaluated for the certificate
  uint64_t fitPoints = 0;       // exact values evaluated to choose and fit
  std::string method;           // the bound's method in words
};

// An exact value of the table at (x, y) with its error bound, per channel.
struct FitExactValue {
  std::array<double, kMaxFitChannels> value{};
  std::array<double, kMaxFitChannels> error{};
};
using FitExact = std::function<FitExactValue(double x, double y)>;

struct FitRequest {
  int dims = 2;
  int channels = 1;
  double xLo = 0.0, xHi = 1.0, yLo = 0.0, yHi = 1.0;
  FitExact exact;
  double tolerance = 4.9e-4;      // the certified bound to reach
  int maxCoefficients = 256;      // per channel
  std::vector<FitMap> maps;       // the maps to try (empty: by dims)
  double xShift = 0.0;            // kLogXY's c
  double cornerExclusion = 1e-2;  // kCorner's breaksY[0]
};

struct FitResult {
  PiecewiseChebyshev fit;
  FitCertificate certificate;
  bool met = false;  // certificate.maxError <= tolerance within maxCoefficients
};

// Chooses the map, patches and degrees (greedy refinement of the axis whose
// Chebyshev tail is largest, for each map and grading), fits, and certifies.
// The result is the certified fit with the fewest coefficients that meets
// the tolerance, else the one with the smallest bound. Deterministic, and
// bit-identical for any thread count (points evaluated in parallel into
// their own slots; maxima are order-free).
FitResult FitPiecewiseChebyshev(const FitRequest &request);

// The certificate of a given fit against the exact values (used by
// FitPiecewiseChebyshev; `tolerance` sizes the grid, gridScale refines it).
FitCertificate CertifyFit(const PiecewiseChebyshev &fit, const FitExact &exact, double tolerance,
                          double gridScale = 1.0);

// The a-priori float32 rounding bound of one patch of one channel.
double FitRoundingBound(const PiecewiseChebyshev &fit, int channel, int kx, int ky,
                        FitPrecision precision = FitPrecision::kShader);

// The certificate as a shader states it: bounds and maxError with the
// kShader rounding in place of the kIeee one.
FitCertificate ShaderCertificate(const FitCertificate &certificate);

}  // namespace lutbake
