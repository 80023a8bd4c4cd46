// Piecewise Chebyshev fits with a certified maximum error (chebyshev_fit.h).
#include "lutbake/integrators/chebyshev_fit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lutbake {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kUnit = 0x1p-24;  // float32 unit roundoff u

double ToFloat(double v) { return static_cast<double>(static_cast<float>(v)); }

// b_0 + sum_{k>=1} ... : Clenshaw's recurrence for sum c_k T_k(z), in T.
template <typename T>
T Clenshaw(const double *c, int n, int stride, T z) {
  const T twoZ = z + z;
  T b1 = 0, b2 = 0;
  for (int k = n - 1; k >= 1; --k) {
    const T b0 = static_cast<T>(c[k * stride]) + twoZ * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return static_cast<T>(c[0]) + z * b1 - b2;
}

template <typename T>
T ClenshawValues(const T *c, int n, T z) {
  const T twoZ = z + z;
  T b1 = 0, b2 = 0;
  for (int k = n - 1; k >= 1; --k) {
    const T b0 = c[k] + twoZ * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

// The patch of s (k = number of inner breaks <= s) and its z.
template <typename T>
void Locate(const std::vector<double> &breaks, T s, int *patch, T *z) {
  int k = 0;
  for (size_t m = 1; m + 1 < breaks.size(); ++m) k += s >= static_cast<T>(breaks[m]) ? 1 : 0;
  const T lo = static_cast<T>(breaks[static_cast<size_t>(k)]);
  const T hi = static_cast<T>(breaks[static_cast<size_t>(k) + 1]);
  T t = (s + s - (lo + hi)) / (hi - lo);
  t = std::min(std::max(t, static_cast<T>(-1)), static_cast<T>(1));
  *patch = k;
  *z = t;
}

// The map of chebyshev_fit.h in T; its constants (FitMapConstantsOf) and
// the breaks are float32 values, so the double and float paths compute the
// same formula.
template <typename T>
void MapIn(const PiecewiseChebyshev &f, T x, T y, T *sx, T *sy) {
  const T zero = 0, one = 1;
  const FitMapConstants k = FitMapConstantsOf(f);
  *sx = zero;
  *sy = zero;
  const T X = k.logX ? std::log(std::max(x, static_cast<T>(f.xLo)) + static_cast<T>(f.xShift)) : x;
  T a = (X - static_cast<T>(k.xOrigin)) * static_cast<T>(k.xScale);
  a = std::min(std::max(a, zero), one);
  T b = zero;
  if (f.dims == 2) {
    const T Y = k.logY ? std::log(std::max(y, static_cast<T>(f.yLo))) : y;
    b = (Y - static_cast<T>(k.yOrigin)) * static_cast<T>(k.yScale);
    b = std::min(std::max(b, zero), one);
  }
  switch (f.map) {
    case FitMap::kLinear:
    case FitMap::kLogX:
    case FitMap::kLogXY: *sx = a, *sy = b; break;
    case FitMap::kSqrtX: *sx = std::sqrt(a), *sy = b; break;
    case FitMap::kCorner: {
      const T q = std::sqrt(a), sum = q + b;
      *sx = sum > zero ? q / sum : zero;
      *sy = std::max(q, b);
      break;
    }
  }
  *sx =
      std::min(std::max(*sx, static_cast<T>(f.breaksX.front())), static_cast<T>(f.breaksX.back()));
  *sy =
      std::min(std::max(*sy, static_cast<T>(f.breaksY.front())), static_cast<T>(f.breaksY.back()));
}

template <typename T>
T EvaluateIn(const PiecewiseChebyshev &f, int channel, T x, T y) {
  T sx, sy, zx, zy = 0;
  MapIn<T>(f, x, y, &sx, &sy);
  int kx = 0, ky = 0;
  Locate<T>(f.breaksX, sx, &kx, &zx);
  if (f.dims == 2) Locate<T>(f.breaksY, sy, &ky, &zy);
  const double *c = f.Patch(channel, kx, ky);
  T rows[64];
  for (int j = 0; j < f.ny; ++j) rows[j] = Clenshaw<T>(c + j * f.nx, f.nx, 1, zx);
  return f.ny == 1 ? rows[0] : ClenshawValues<T>(rows, f.ny, zy);
}

// Clenshaw's float32 rounding for sum c_k T_k (|c_k| <= magnitude[k]), as
// the header states. One step b_k = c_k + (z + z) b_{k+1} - b_{k+2} rounds
// three times (z + z is exact): u/2 |2 z b_{k+1}| + u/2 |c_k + 2 z b_{k+1}|
// + u/2 |b_k| <= 1.5 u (|c_k| + 2 |b_{k+1}| + |b_{k+2}|) (a fused
// multiply-add rounds less); 2 u covers it with the computed b's a few u
// above the exact ones.
double ClenshawRounding(const std::vector<double> &magnitude) {
  const int n = static_cast<int>(magnitude.size());
  std::vector<double> beta(static_cast<size_t>(n) + 2, 0.0);
  for (int k = n - 1; k >= 0; --k)
    for (int m = k; m < n; ++m)
      beta[static_cast<size_t>(k)] += magnitude[static_cast<size_t>(m)] * (m - k + 1);
  double bound = 0.0;
  for (int k = 0; k < n; ++k)
    bound += (k + 1) * (magnitude[static_cast<size_t>(k)] + 2.0 * beta[static_cast<size_t>(k) + 1] +
                        beta[static_cast<size_t>(k) + 2]);
  return 2.0 * kUnit * bound;
}

// The Chebyshev coefficients of the derivative of sum_{k < n} c_k T_k:
// d_{n-1} = d_n = 0, d_{k-1} = d_{k+1} + 2 k c_k, then d_0 / 2.
std::vector<double> ChebyshevDerivative(const std::vector<double> &c) {
  const int n = static_cast<int>(c.size());
  std::vector<double> d(static_cast<size_t>(std::max(n, 1)) + 1, 0.0);
  for (int k = n - 1; k >= 1; --k)
    d[static_cast<size_t>(k) - 1] =
        d[static_cast<size_t>(k) + 1] + 2.0 * k * c[static_cast<size_t>(k)];
  d[0] *= 0.5;
  d.resize(static_cast<size_t>(std::max(n - 1, 1)));
  return d;
}

// A proved bound of |d^order p / dz^order| along x (alongX) or y over the
// patch [-1, 1]^2: each line's series (a row j for x, a column i for y)
// differentiated `order` times, sum_j |T_j| <= 1 over the other axis, so
// |p_z...| <= sum over lines and k of |d_k|. Never above the cruder
// sum |c_k| k^2 (order 1) or sum |c_k| k^2 (k^2 - 1) / 3 (order 2). The
// double arithmetic of the recurrence (exact float32 inputs, n^2 terms of
// relative rounding 2^-53) is covered by the factor 1 + 1e-9.
double DerivativeBound(const double *c, int nx, int ny, bool alongX, int order) {
  const int lines = alongX ? ny : nx, length = alongX ? nx : ny;
  double bound = 0.0;
  for (int line = 0; line < lines; ++line) {
    std::vector<double> series(static_cast<size_t>(length));
    for (int k = 0; k < length; ++k)
      series[static_cast<size_t>(k)] = alongX ? c[line * nx + k] : c[k * nx + line];
    for (int o = 0; o < order; ++o) series = ChebyshevDerivative(series);
    for (double d : series) bound += std::abs(d);
  }
  return bound * (1.0 + 1e-9);
}

// The precision model's relative rounding of / and sqrt (FitPrecision):
// IEEE binary32 rounds both correctly (u / 2); a shader's / is within 2.5
// ulp (5 u) and its sqrt, 1 / inversesqrt, within 4.5 ulp (9 u) (GLSL ES
// 3.00, WGSL).
double DivisionRounding(FitPrecision p) {
  return p == FitPrecision::kIeee ? 0.5 * kUnit : 5.0 * kUnit;
}
double SqrtRounding(FitPrecision p) { return p == FitPrecision::kIeee ? 0.5 * kUnit : 9.0 * kUnit; }

// The coordinate map's rounding in s (absolute), per axis. The unit
// coordinates a, b carry 2 u relative (x rounded to float, the subtraction,
// the product and the float32 constant), clamped into [0, 1].
//   linear: 2 u.  sqrt-x: q = sqrt(a) carries e_q = e_sqrt + 2 u / 2 of q <= 1.
//   corner: s_x = q / (q + b): s_x (1 - s_x) (e_q + 2 u) from q and b,
//           s_x (u / 2 + e_div) from the sum and the division, taken at the
//           patch's worst s; s_y = max(q, b) <= max(e_q, 2 u).
// A square root near a = 0 of an a that is a difference x - xLo with
// xLo != 0 adds sqrt(4 u |xLo| / (xHi - xLo)).
double MapRounding(double lo, double hi, bool squareRoot, FitPrecision p) {
  double d = squareRoot ? std::max(SqrtRounding(p) + kUnit, 2.0 * kUnit) : 2.0 * kUnit;
  if (squareRoot && lo != 0.0) d += std::sqrt(4.0 * kUnit * std::abs(lo) / (hi - lo));
  return d;
}
double CornerRoundingX(double lo, double hi, double sLo, double sHi, FitPrecision p) {
  const double widest =
      sLo <= 0.5 && sHi >= 0.5 ? 0.25 : std::max(sLo * (1.0 - sLo), sHi * (1.0 - sHi));
  double d = widest * (SqrtRounding(p) + 3.0 * kUnit) + sHi * (0.5 * kUnit + DivisionRounding(p));
  if (lo != 0.0) d += std::sqrt(4.0 * kUnit * std::abs(lo) / (hi - lo));
  return d;
}

// Breaks from `first` to 1: b_k = first + (1 - first) (k / P)^grade, or
// (grade 0, first > 0) geometric, b_k = first^(1 - k / P).
std::vector<double> Breaks(int patches, double first, double grade) {
  std::vector<double> b;
  for (int k = 0; k <= patches; ++k) {
    const double t = static_cast<double>(k) / patches;
    b.push_back(ToFloat(grade == 0.0 ? std::pow(first, 1.0 - t)
                                     : first + (1.0 - first) * std::pow(t, grade)));
  }
  b.front() = ToFloat(first);
  b.back() = 1.0;
  return b;
}

// kCorner's x breaks: each half [0, 1/2], [1/2, 1] cut into patches / 2.
std::vector<double> CornerBreaks(int patches) {
  std::vector<double> b;
  const int half = patches / 2;
  for (int k = 0; k <= patches; ++k)
    b.push_back(ToFloat(k <= half ? 0.5 * k / half : 0.5 + 0.5 * (k - half) / half));
  return b;
}

// Exact values at many points, in parallel, each into its own slot.
std::vector<FitExactValue> EvaluateAll(const FitExact &exact,
                                       const std::vector<std::pair<double, double>> &points) {
  std::vector<FitExactValue> values(points.size());
  tbb::parallel_for(size_t(0), points.size(),
                    [&](size_t i) { values[i] = exact(points[i].first, points[i].second); });
  return values;
}

// Fits every patch by interpolation at Chebyshev points of the first kind.
void FitCoefficients(PiecewiseChebyshev *f, const FitExact &exact, uint64_t *evaluations) {
  const int px = f->PatchesX(), py = f->PatchesY(), nx = f->nx, ny = f->ny;
  std::vector<std::pair<double, double>> points;
  for (int ky = 0; ky < py; ++ky)
    for (int kx = 0; kx < px; ++kx)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const double zx = std::cos(kPi * (i + 0.5) / nx);
          const double zy = ny == 1 ? 0.0 : std::cos(kPi * (j + 0.5) / ny);
          const double x0 = f->breaksX[kx], x1 = f->breaksX[kx + 1];
          const double sx = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * zx;
          double sy = f->breaksY[0];
          if (f->dims == 2) {
            const double y0 = f->breaksY[ky], y1 = f->breaksY[ky + 1];
            sy = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * zy;
          }
          double x, y;
          f->Unmap(sx, sy, &x, &y);
          points.emplace_back(x, y);
        }
  const std::vector<FitExactValue> values = EvaluateAll(exact, points);
  *evaluations += points.size();
  f->coefficients.assign(static_cast<size_t>(f->channels) * px * py * nx * ny, 0.0);
  for (int c = 0; c < f->channels; ++c)
    for (int ky = 0; ky < py; ++ky)
      for (int kx = 0; kx < px; ++kx) {
        const size_t base = static_cast<size_t>((ky * px + kx) * ny * nx);
        double *out =
            f->coefficients.data() + static_cast<size_t>(((c * py + ky) * px + kx) * ny * nx);
        for (int q = 0; q < ny; ++q)
          for (int p = 0; p < nx; ++p) {
            double sum = 0.0;
            for (int j = 0; j < ny; ++j)
              for (int i = 0; i < nx; ++i)
                sum +=
                    values[base + static_cast<size_t>(j * nx + i)].value[static_cast<size_t>(c)] *
                    std::cos(kPi * p * (i + 0.5) / nx) * std::cos(kPi * q * (j + 0.5) / ny);
            const double weight = (p == 0 ? 1.0 : 2.0) / nx * (q == 0 ? 1.0 : 2.0) / ny;
            out[q * nx + p] = ToFloat(weight * sum);
          }
      }
}

// max |p - f| over every patch's Chebyshev extrema z_k = cos(pi k / n),
// k = 0..n, per axis (between the interpolation nodes, edges included), all
// channels: the greedy search's measure of a shape.
double CheckError(const PiecewiseChebyshev &f, const FitExact &exact, uint64_t *evaluations) {
  std::vector<std::pair<double, double>> points;
  std::vector<std::array<double, 4>> where;  // kx, ky, zx, zy
  const int mx = f.nx, my = f.dims == 2 ? f.ny : 0;
  for (int ky = 0; ky < f.PatchesY(); ++ky)
    for (int kx = 0; kx < f.PatchesX(); ++kx)
      for (int j = 0; j <= my; ++j)
        for (int i = 0; i <= mx; ++i) {
          const double zx = std::cos(kPi * i / mx), zy = my ? std::cos(kPi * j / my) : 0.0;
          const double x0 = f.breaksX[kx], x1 = f.breaksX[kx + 1];
          const double y0 = f.breaksY[ky], y1 = f.breaksY[ky + 1];
          double x, y;
          f.Unmap(0.5 * (x0 + x1) + 0.5 * (x1 - x0) * zx,
                  f.dims == 2 ? 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * zy : y0, &x, &y);
          points.emplace_back(x, y);
          where.push_back({double(kx), double(ky), zx, zy});
        }
  const std::vector<FitExactValue> values = EvaluateAll(exact, points);
  *evaluations += points.size();
  double worst = 0.0;
  for (size_t p = 0; p < points.size(); ++p)
    for (int c = 0; c < f.channels; ++c) {
      const double *coef = f.Patch(c, static_cast<int>(where[p][0]), static_cast<int>(where[p][1]));
      double rows[64];
      for (int r = 0; r < f.ny; ++r)
        rows[r] = Clenshaw<double>(coef + r * f.nx, f.nx, 1, where[p][2]);
      const double v = f.ny == 1 ? rows[0] : ClenshawValues<double>(rows, f.ny, where[p][3]);
      worst = std::max(worst, std::abs(v - values[p].value[static_cast<size_t>(c)]));
    }
  return worst;
}

struct Shape {
  FitMap map;
  double gradeX, gradeY;
  int px, py, nx, ny;
};

PiecewiseChebyshev Build(const FitRequest &r, const Shape &s) {
  PiecewiseChebyshev f;
  f.dims = r.dims;
  f.channels = r.channels;
  f.map = s.map;
  f.xLo = ToFloat(r.xLo), f.xHi = ToFloat(r.xHi);
  f.yLo = ToFloat(r.yLo), f.yHi = ToFloat(r.yHi);
  if (s.map == FitMap::kLogXY) f.xShift = ToFloat(r.xShift);
  f.breaksX = s.map == FitMap::kCorner ? CornerBreaks(s.px) : Breaks(s.px, 0.0, s.gradeX);
  f.breaksY = r.dims == 1
                  ? std::vector<double>{0.0, 1.0}
                  : Breaks(s.py, s.map == FitMap::kCorner ? r.cornerExclusion : 0.0, s.gradeY);
  f.nx = s.nx;
  f.ny = r.dims == 1 ? 1 : s.ny;
  return f;
}

}  // namespace

const char *ToString(FitMap map) {
  switch (map) {
    case FitMap::kLinear: return "linear";
    case FitMap::kSqrtX: return "sqrt-x";
    case FitMap::kCorner: return "corner";
    case FitMap::kLogX: return "log-x";
    case FitMap::kLogXY: return "log-xy";
  }
  return "?";
}

bool ParseFitMap(const std::string &text, FitMap *map) {
  for (FitMap m : {FitMap::kLinear, FitMap::kSqrtX, FitMap::kCorner, FitMap::kLogX, FitMap::kLogXY})
    if (text == ToString(m)) {
      *map = m;
      return true;
    }
  return false;
}

FitMapConstants FitMapConstantsOf(const PiecewiseChebyshev &f) {
  FitMapConstants k;
  k.logX = f.map == FitMap::kLogX || f.map == FitMap::kLogXY;
  k.logY = f.map == FitMap::kLogXY;
  const double x0 = f.xLo + f.xShift, x1 = f.xHi + f.xShift;
  k.xOrigin = static_cast<float>(k.logX ? std::log(x0) : f.xLo);
  k.xScale =
      static_cast<float>(k.logX ? 1.0 / (std::log(x1) - std::log(x0)) : 1.0 / (f.xHi - f.xLo));
  k.yOrigin = static_cast<float>(k.logY ? std::log(f.yLo) : f.yLo);
  k.yScale = static_cast<float>(k.logY ? 1.0 / (std::log(f.yHi) - std::log(f.yLo))
                                       : 1.0 / (f.yHi - f.yLo));
  return k;
}

void PiecewiseChebyshev::Map(double x, double y, double *sx, double *sy) const {
  MapIn<double>(*this, x, y, sx, sy);
}

void PiecewiseChebyshev::Unmap(double sx, double sy, double *x, double *y) const {
  double a = sx, b = sy;
  if (map == FitMap::kSqrtX) a = sx * sx;
  if (map == FitMap::kCorner) {
    double q;
    if (sx <= 0.5) {
      b = sy;
      q = sy * sx / (1.0 - sx);
    } else {
      q = sy;
      b = sy * (1.0 - sx) / sx;
    }
    a = q * q;
  }
  a = std::min(std::max(a, 0.0), 1.0);
  b = std::min(std::max(b, 0.0), 1.0);
  double X = xLo + a * (xHi - xLo), Y = yLo + b * (yHi - yLo);
  if (map == FitMap::kLogX) X = xLo * std::pow(xHi / xLo, a);
  if (map == FitMap::kLogXY) {
    X = (xLo + xShift) * std::pow((xHi + xShift) / (xLo + xShift), a) - xShift;
    Y = yLo * std::pow(yHi / yLo, b);
  }
  *x = std::min(std::max(X, xLo), xHi);
  *y = dims == 2 ? std::min(std::max(Y, yLo), yHi) : 0.0;
}

double PiecewiseChebyshev::Evaluate(int channel, double x, double y) const {
  return EvaluateIn<double>(*this, channel, x, y);
}

float PiecewiseChebyshev::EvaluateFloat(int channel, double x, double y) const {
  return EvaluateIn<float>(*this, channel, static_cast<float>(x), static_cast<float>(y));
}

double FitRoundingBound(const PiecewiseChebyshev &f, int channel, int kx, int ky,
                        FitPrecision precision) {
  const double *c = f.Patch(channel, kx, ky);
  const bool sqrtX = f.map == FitMap::kSqrtX || f.map == FitMap::kCorner;
  double dsx = MapRounding(f.xLo, f.xHi, sqrtX, precision);
  // log: 3 ulp (6 u) of |log x| (GLSL ES 3.00's log outside [0.5, 2]; a
  // shader's log is not correctly rounded) and an absolute 2^-21 (its log
  // inside [0.5, 2]), over the span of the logs; the subtraction of the
  // origin and the product by the scale 2 u of a <= 1.
  double dsy = MapRounding(f.yLo, f.yHi, f.map == FitMap::kCorner, precision);
  if (f.map == FitMap::kCorner)
    dsx = CornerRoundingX(f.xLo, f.xHi, f.breaksX[kx], f.breaksX[kx + 1], precision);
  if (f.map == FitMap::kLogX)
    dsx = 2.0 * kUnit +
          (0x1p-21 + 6.0 * kUnit * std::abs(std::log(f.xLo))) / (std::log(f.xHi) - std::log(f.xLo));
  if (f.map == FitMap::kLogXY) {
    // As kLogX's, each log's argument rounded first (2 u in the log) and
    // the larger |log| of the two ends.
    const auto logRounding = [](double lo, double hi) {
      return 2.0 * kUnit +
             (0x1p-21 + 2.0 * kUnit +
              6.0 * kUnit * std::max(std::abs(std::log(lo)), std::abs(std::log(hi)))) /
                 (std::log(hi) - std::log(lo));
    };
    dsx = logRounding(f.xLo + f.xShift, f.xHi + f.xShift);
    dsy = logRounding(f.yLo, f.yHi);
  }
  const double wx = f.breaksX[kx + 1] - f.breaksX[kx];
  const double wy = f.dims == 2 ? f.breaksY[ky + 1] - f.breaksY[ky] : 1.0;
  // z = (s + s - (lo + hi)) / (hi - lo): lo + hi rounds by u (lo + hi <= 2),
  // the subtraction by u / 2 of |2 s - lo - hi| <= w (1 + 2 ds + u), hi - lo
  // by u / 2 relative and the division by e_div of |z| <= 1:
  // dz <= (2 ds + u) / w + u + e_div, and 2 u + e_div for the second-order
  // terms.
  const double dzx = (2.0 * dsx + kUnit) / wx + 2.0 * kUnit + DivisionRounding(precision);
  const double dzy = (2.0 * dsy + kUnit) / wy + 2.0 * kUnit + DivisionRounding(precision);
  // The slopes |p_zx|, |p_zy| over the patch, proved (DerivativeBound).
  const double slopeX = DerivativeBound(c, f.nx, f.ny, true, 1);
  const double slopeY = f.dims == 2 ? DerivativeBound(c, f.nx, f.ny, false, 1) : 0.0;
  double inner = 0.0;
  std::vector<double> rowMagnitude(static_cast<size_t>(f.ny), 0.0);
  for (int j = 0; j < f.ny; ++j) {
    std::vector<double> m(static_cast<size_t>(f.nx));
    for (int i = 0; i < f.nx; ++i) {
      const double a = std::abs(c[j * f.nx + i]);
      m[static_cast<size_t>(i)] = a;
      rowMagnitude[static_cast<size_t>(j)] += a;
    }
    inner += ClenshawRounding(m);
  }
  const double outer = f.ny > 1 ? ClenshawRounding(rowMagnitude) : 0.0;
  return slopeX * dzx + (f.dims == 2 ? slopeY * dzy : 0.0) + inner + outer;
}

FitCertificate ShaderCertificate(const FitCertificate &certificate) {
  FitCertificate shader = certificate;
  shader.maxError = certificate.shaderMaxError;
  for (FitChannelBound &c : shader.channels) {
    c.rounding = c.shaderRounding;
    c.bound = c.shaderBound;
  }
  const size_t at = shader.method.find("(a priori; IEEE");
  if (at != std::string::npos)
    shader.method =
        shader.method.substr(0, at) +
        "(a priori; a shader's / within 2.5 ulp, sqrt within 4.5 ulp, log within 3 ulp)";
  return shader;
}

FitCertificate CertifyFit(const PiecewiseChebyshev &f, const FitExact &exact, double tolerance,
                          double gridScale) {
  FitCertificate cert;
  cert.channels.assign(static_cast<size_t>(f.channels), {});
  const int px = f.PatchesX(), py = f.PatchesY();
  // Per patch: the grid, sized so that the interpolation term with
  // |f_zz| ~ 2 |p_zz| stays near a third of the tolerance.
  struct PatchGrid {
    int kx, ky, gx, gy;
    size_t first;
  };
  std::vector<PatchGrid> grids;
  std::vector<std::pair<double, double>> points;
  std::vector<double> secondX(static_cast<size_t>(f.channels * px * py)), secondY(secondX.size());
  for (int ky = 0; ky < py; ++ky)
    for (int kx = 0; kx < px; ++kx) {
      double mx = 0.0, my = 0.0;
      for (int c = 0; c < f.channels; ++c) {
        const double *p = f.Patch(c, kx, ky);
        // The grid is sized by the cruder sum |c_ij| i^2 (i^2 - 1) / 3 (as
        // before the derivative's coefficients bounded p_zz), so that the
        // tighter bound below shrinks the term between nodes, not the grid.
        double crudeX = 0.0, crudeY = 0.0;
        for (int j = 0; j < f.ny; ++j)
          for (int i = 0; i < f.nx; ++i) {
            const double a = std::abs(p[j * f.nx + i]);
            crudeX += a * i * i * (i * i - 1.0) / 3.0;
            crudeY += a * j * j * (j * j - 1.0) / 3.0;
          }
        secondX[static_cast<size_t>((c * py + ky) * px + kx)] =
            std::min(crudeX, DerivativeBound(p, f.nx, f.ny, true, 2));
        secondY[static_cast<size_t>((c * py + ky) * px + kx)] =
            f.dims == 2 ? std::min(crudeY, DerivativeBound(p, f.nx, f.ny, false, 2)) : 0.0;
        mx = std::max(mx, crudeX);
        my = std::max(my, crudeY);
      }
      const auto size = [&](double m) {
        return static_cast<int>(std::min(
            2048.0, std::max(8.0, std::ceil(gridScale * std::sqrt(3.0 * m / (0.67 * tolerance))))));
      };
      PatchGrid g{kx, ky, size(mx), f.dims == 2 ? size(my) : 0, points.size()};
      for (int j = 0; j <= g.gy; ++j)
        for (int i = 0; i <= g.gx; ++i) {
          const double x0 = f.breaksX[kx], x1 = f.breaksX[kx + 1];
          const double sx = x0 + (x1 - x0) * i / g.gx;
          double sy = f.breaksY[0];
          if (f.dims == 2) {
            const double y0 = f.breaksY[ky], y1 = f.breaksY[ky + 1];
            sy = y0 + (y1 - y0) * j / g.gy;
          }
          double x, y;
          f.Unmap(sx, sy, &x, &y);
          points.emplace_back(x, y);
        }
      grids.push_back(g);
    }
  const std::vector<FitExactValue> values = EvaluateAll(exact, points);
  cert.gridPoints = points.size();
  // The fit at the same nodes, in z (not re-mapped: the grid is the patch's).
  for (int c = 0; c < f.channels; ++c) {
    FitChannelBound &out = cert.channels[static_cast<size_t>(c)];
    for (const PatchGrid &g : grids) {
      const double *coef = f.Patch(c, g.kx, g.ky);
      const auto fitAt = [&](int i, int j) {
        const double zx = -1.0 + 2.0 * i / g.gx, zy = g.gy ? -1.0 + 2.0 * j / g.gy : 0.0;
        std::vector<double> rows(static_cast<size_t>(f.ny));
        for (int r = 0; r < f.ny; ++r)
          rows[static_cast<size_t>(r)] = Clenshaw<double>(coef + r * f.nx, f.nx, 1, zx);
        return f.ny == 1 ? rows[0] : ClenshawValues<double>(rows.data(), f.ny, zy);
      };
      const auto exactAt = [&](int i, int j) -> const FitExactValue & {
        return values[g.first + static_cast<size_t>(j * (g.gx + 1) + i)];
      };
      double worst = 0.0, fxx = 0.0, fyy = 0.0;
      std::pair<double, double> worstAt{0.0, 0.0};
      for (int j = 0; j <= g.gy; ++j)
        for (int i = 0; i <= g.gx; ++i) {
          const FitExactValue &e = exactAt(i, j);
          const double v = e.value[static_cast<size_t>(c)];
          if (!std::isfinite(v))
            throw std::domain_error("the exact value is not finite inside the fit's domain");
          const double d = std::abs(fitAt(i, j) - v);
          if (d > worst) {
            worst = d;
            worstAt = points[g.first + static_cast<size_t>(j * (g.gx + 1) + i)];
          }
          out.exactError = std::max(out.exactError, e.error[static_cast<size_t>(c)]);
          const double hx = 2.0 / g.gx;
          if (i > 0 && i < g.gx)
            fxx = std::max(fxx, std::abs(exactAt(i - 1, j).value[static_cast<size_t>(c)] - 2.0 * v +
                                         exactAt(i + 1, j).value[static_cast<size_t>(c)]) /
                                    (hx * hx));
          if (g.gy > 0 && j > 0 && j < g.gy) {
            const double hy = 2.0 / g.gy;
            fyy = std::max(fyy, std::abs(exactAt(i, j - 1).value[static_cast<size_t>(c)] - 2.0 * v +
                                         exactAt(i, j + 1).value[static_cast<size_t>(c)]) /
                                    (hy * hy));
          }
        }
      const size_t slot = static_cast<size_t>((c * py + g.ky) * px + g.kx);
      const double hx = 2.0 / g.gx, hy = g.gy ? 2.0 / g.gy : 0.0;
      const double between =
          hx * hx / 8.0 * (secondX[slot] + 2.0 * fxx) + hy * hy / 8.0 * (secondY[slot] + 2.0 * fyy);
      const double rounding = FitRoundingBound(f, c, g.kx, g.ky, FitPrecision::kIeee);
      const double shaderRounding = FitRoundingBound(f, c, g.kx, g.ky, FitPrecision::kShader);
      if (worst > out.gridError) {
        out.gridError = worst;
        out.worstX = worstAt.first;
        out.worstY = worstAt.second;
      }
      out.betweenNodes = std::max(out.betweenNodes, between);
      out.rounding = std::max(out.rounding, rounding);
      out.shaderRounding = std::max(out.shaderRounding, shaderRounding);
      out.bound = std::max(out.bound, worst + between + rounding);
      out.shaderBound = std::max(out.shaderBound, worst + between + shaderRounding);
    }
    out.bound += out.exactError;
    out.shaderBound += out.exactError;
    cert.maxError = std::max(cert.maxError, out.bound);
    cert.shaderMaxError = std::max(cert.shaderMaxError, out.shaderBound);
  }
  cert.method =
      "max |fit - exact| on a grid of " + std::to_string(cert.gridPoints) +
      " points (per patch uniform in z, edges included) + h^2/8 (|fit_zz| proved from the "
      "coefficients + 2 x the largest second difference of the exact values, an estimate) per "
      "axis + the exact values' error bounds + the float32 evaluation's rounding (a priori; IEEE "
      "binary32, correctly rounded / and sqrt, log within 3 ulp)";
  return cert;
}

FitResult FitPiecewiseChebyshev(const FitRequest &r) {
  if (!r.exact) throw std::invalid_argument("FitPiecewiseChebyshev: no exact function");
  if (r.channels < 1 || r.channels > kMaxFitChannels)
    throw std::invalid_argument("FitPiecewiseChebyshev: 1 to 4 channels");
  std::vector<FitMap> maps = r.maps;
  if (maps.empty())
    maps = r.dims == 1 ? std::vector<FitMap>{FitMap::kLinear, FitMap::kSqrtX}
                       : std::vector<FitMap>{FitMap::kSqrtX, FitMap::kCorner};
  if (r.maps.empty() && r.xLo > 0.0) maps.push_back(FitMap::kLogX);
  // The logarithmic maps need their arguments above 0 over the whole domain.
  for (FitMap m : maps)
    if ((m == FitMap::kLogX && !(r.xLo > 0.0)) ||
        (m == FitMap::kLogXY && !(r.xLo + r.xShift > 0.0 && r.yLo > 0.0)))
      throw std::invalid_argument(
          "FitPiecewiseChebyshev: a logarithmic map needs a domain above 0");
  uint64_t evaluations = 0;
  // The shapes, fewest coefficients first: per map and grading, patches
  // and degrees per axis (a tight budget: equal degrees only). Each is fitted
  // and measured by CheckError until a few are below the target; the
  // first of those has the fewest coefficients of all that reach it.
  struct Candidate {
    Shape shape;
    int coefficients;
    double error;
    bool reached;
  };
  std::vector<Candidate> shapes;
  const bool tight = r.maxCoefficients > 512;
  for (FitMap map : maps)
    for (double gradeX : {1.0, 2.0})
      for (double gradeY :
           r.dims == 1 ? std::vector<double>{1.0} : std::vector<double>{1.0, 2.0, 0.0})
        for (int px = 1; px <= 8; ++px)
          for (int py = 1; py <= (r.dims == 1 ? 1 : 6); ++py)
            for (int nx = 4; nx <= 24; nx += 2)
              for (int ny = r.dims == 1 ? 1 : 4; ny <= (r.dims == 1 ? 1 : 24); ny += 2) {
                if (map == FitMap::kCorner && (gradeX != 1.0 || px % 2 != 0)) continue;
                if (map != FitMap::kLinear && gradeX != 1.0) continue;
                // One patch in y: every grading is the same shape.
                if (py == 1 && gradeY != 1.0) continue;
                if (gradeY == 0.0 && (map != FitMap::kCorner || py < 2 || r.cornerExclusion <= 0.0))
                  continue;
                if (r.dims == 2 && tight && nx != ny) continue;
                if (r.dims == 2 && !tight && (px > 4 || py > 3)) continue;
                const int count = px * py * nx * ny;
                if (count <= r.maxCoefficients)
                  shapes.push_back({{map, gradeX, gradeY, px, py, nx, ny}, count, HUGE_VAL, false});
              }
  std::stable_sort(shapes.begin(), shapes.end(), [](const Candidate &a, const Candidate &b) {
    return a.coefficients < b.coefficients;
  });
  std::vector<Candidate> candidates;
  int reachedCount = 0;
  Candidate closest{};
  closest.error = HUGE_VAL;
  for (Candidate &c : shapes) {
    PiecewiseChebyshev f = Build(r, c.shape);
    FitCoefficients(&f, r.exact, &evaluations);
    c.error = CheckError(f, r.exact, &evaluations);
    // The float32 evaluation's rounding (a priori, as certified) takes its
    // share too: a tight tolerance is mostly rounding where the table is
    // steep in s (at 4.9e-4 it is a few percent and decides nothing).
    double rounding = 0.0;
    for (int ch = 0; ch < f.channels; ++ch)
      for (int ky = 0; ky < f.PatchesY(); ++ky)
        for (int kx = 0; kx < f.PatchesX(); ++kx)
          rounding = std::max(rounding, FitRoundingBound(f, ch, kx, ky, FitPrecision::kIeee));
    if (c.error < closest.error) closest = c;
    if (c.error <= 0.45 * r.tolerance && c.error + rounding <= 0.75 * r.tolerance) {
      c.reached = true;
      candidates.push_back(c);
      if (++reachedCount >= 3) break;
    }
  }
  if (candidates.empty() && closest.error < HUGE_VAL) candidates.push_back(closest);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate &a, const Candidate &b) {
                     if (a.reached != b.reached) return a.reached;
                     return a.coefficients != b.coefficients ? a.coefficients < b.coefficients
                                                             : a.error < b.error;
                   });
  FitResult best;
  bool haveBest = false;
  int certified = 0;
  for (const Candidate &c : candidates) {
    if (certified >= 4) break;
    PiecewiseChebyshev f = Build(r, c.shape);
    FitCoefficients(&f, r.exact, &evaluations);
    FitCertificate cert = CertifyFit(f, r.exact, r.tolerance, 1.0);
    ++certified;
    // Where the term between nodes alone breaks the bound, a grid twice as
    // fine in each axis quarters it.
    const FitChannelBound *over = nullptr;
    for (const FitChannelBound &b : cert.channels)
      if (b.bound > r.tolerance) over = &b;
    if (over && over->bound - over->betweenNodes < 0.8 * r.tolerance)
      cert = CertifyFit(f, r.exact, r.tolerance, 2.0);
    const bool met = cert.maxError <= r.tolerance;
    if (!haveBest || (met && !best.met) ||
        (!best.met && cert.maxError < best.certificate.maxError)) {
      best.fit = f;
      best.certificate = cert;
      best.met = met;
      haveBest = true;
    }
    if (met) break;
  }
  best.certificate.fitPoints = evaluations;
  return best;
}

}  // namespace lutbake
