#include "lutbake/integrators/ltc_fit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/integrators/light_direction_rule.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/models/burley.h"

namespace lutbake {

namespace {

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace

std::vector<LtcNode> LtcLobeRule(const LtcLobe &lobe, double mu_o, int level, bool halfCircle) {
  return lobe.quadrature == LtcQuadrature::kLightDirection
             ? LightDirectionRule(mu_o, level, halfCircle)
             : HalfVectorRule(mu_o, lobe.quadratureAlpha, level, halfCircle);
}

std::vector<LtcNode> LtcLobePolygonRule(const LtcLobe &lobe, double mu_o, int level,
                                        const Vec3 *vertices, int count) {
  return lobe.quadrature == LtcQuadrature::kLightDirection
             ? LightDirectionPolygonRule(mu_o, level, vertices, count)
             : HalfVectorPolygonRule(mu_o, lobe.quadratureAlpha, level, vertices, count);
}

void IntegrateLobeMoments(const LtcLobe &lobe, double mu_o, int level, double *magnitude,
                          double *fresnel) {
  const Vec3 o = ViewDirection(mu_o);
  double m = 0.0, f = 0.0;
  for (const LtcNode &n : LtcLobeRule(lobe, mu_o, level, true)) {
    const double value = n.weight * lobe.cosineWeighted(mu_o, n.l);
    m += value;
    f += value * Pow5(1.0 - Dot(o, n.h));
  }
  *magnitude = m;
  *fresnel = f;
}

LtcLobe MicrofacetLtcLobe(const Ndf &ndf, SmithForm smith) {
  LtcLobe lobe;
  // A mirror has no lobe to fit: the fit takes the narrowest one ltc_code does.
  const Ndf fitted{ndf.kind, std::max(ndf.alpha, kLtcMinimumAlpha)};
  lobe.quadratureAlpha = fitted.alpha;
  lobe.cosineWeighted = [fitted, smith](double mu_o, const Vec3 &l) {
    if (l.z <= 0.0) return 0.0;
    const Vec3 o = ViewDirection(mu_o);
    const Vec3 sum{o.x + l.x, o.y + l.y, o.z + l.z};
    const double len2 = Dot(sum, sum);
    if (len2 == 0.0) return 0.0;
    const Vec3 h = Normalize(sum);
    // f mu_i = D G2 / (4 mu_o), with G2 / mu_o finite at mu_o = 0.
    return 0.25 * fitted.D(h) *
           SmithG2OverMuO(smith, mu_o, l.z, fitted.MuLambda(mu_o), fitted.MuLambda(l.z));
  };
  lobe.moments = [ndf, smith](double mu_o, double *magnitude, double *fresnel) {
    if (ndf.alpha == 0.0) {
      *magnitude = 1.0;
      *fresnel = Pow5(1.0 - mu_o);
      return;
    }
    const SplitSumQuadrature q = IntegrateSplitSumQuadrature(ndf, smith, mu_o, 1e-10, true);
    *magnitude = q.A + q.B;
    *fresnel = q.B;
  };
  return lobe;
}

LtcLobe SheenLtcLobe(SheenVisibility visibility, double alpha) {
  LtcLobe lobe;
  // alpha = 0 has no lobe (E = 0): the shape of the narrowest one fitted
  // stands in for it, with magnitude 0.
  const double shape = alpha > 0.0 ? alpha : kLtcMinimumSheenAlpha;
  lobe.quadratureAlpha = std::max(alpha, kLtcMinimumSheenAlpha);
  lobe.cosineWeighted = [visibility, shape](double mu_o, const Vec3 &l) {
    if (l.z <= 0.0) return 0.0;
    const Vec3 o = ViewDirection(mu_o);
    const Vec3 sum{o.x + l.x, o.y + l.y, o.z + l.z};
    if (Dot(sum, sum) == 0.0) return 0.0;
    const Vec3 h = Normalize(sum);
    return CharlieDFromCos(shape, h.z) * SheenCosineVisibility(visibility, shape, mu_o, l.z);
  };
  lobe.moments = [visibility, alpha, lobe](double mu_o, double *magnitude, double *fresnel) {
    *magnitude = IntegrateSheenAlbedo(visibility, alpha, mu_o, 1e-10).value;
    if (alpha == 0.0) {
      *fresnel = 0.0;
      return;
    }
    double ruleMagnitude = 0.0;
    IntegrateLobeMoments(lobe, mu_o, 2, &ruleMagnitude, fresnel);
  };
  return lobe;
}

LtcLobe BurleyLtcLobe(double perceptualRoughness) {
  LtcLobe lobe;
  lobe.quadrature = LtcQuadrature::kLightDirection;
  lobe.cosineWeighted = [perceptualRoughness](double mu_o, const Vec3 &l) {
    if (l.z <= 0.0) return 0.0;
    return BurleyDiffuseBrdf(perceptualRoughness, ViewDirection(mu_o), l) * l.z;
  };
  return lobe;
}

LtcLobe OrenNayarLtcLobe(OrenNayarVariant variant, double sigma) {
  LtcLobe lobe;
  lobe.quadrature = LtcQuadrature::kLightDirection;
  lobe.cosineWeighted = [variant, sigma](double mu_o, const Vec3 &l) {
    if (l.z <= 0.0) return 0.0;
    return OrenNayarBrdf(variant, sigma, ViewDirection(mu_o), l) * l.z;
  };
  return lobe;
}

LtcMomentsReference IntegrateLobeMomentsAdaptive(const LtcLobe &lobe, double mu_o,
                                                 double tolerance) {
  const Vec3 o = ViewDirection(mu_o);
  const double thetaO = std::acos(Clamp(mu_o, 0.0, 1.0));
  std::vector<double> outer = {0.0, 0.5 * kPi};
  if (thetaO > 0.0 && thetaO < 0.5 * kPi) outer = {0.0, thetaO, 0.5 * kPi};
  int inner = 0;
  // Channels: magnitude, fresnel, and the inner estimates of both.
  const QuadratureResultN<4> q = IntegrateAdaptiveN<4>(
      [&](double theta) {
        const double st = std::sin(theta), ct = std::cos(theta);
        const QuadratureResultN<2> ring = IntegrateAdaptiveN<2>(
            [&](double phi) {
              const Vec3 l{st * std::cos(phi), st * std::sin(phi), ct};
              const Vec3 sum{o.x + l.x, o.y + l.y, o.z + l.z};
              const double vh = Dot(sum, sum) > 0.0 ? Dot(o, Normalize(sum)) : 0.0;
              const double f = lobe.cosineWeighted(mu_o, l);
              return std::array<double, 2>{f, f * Pow5(1.0 - vh)};
            },
            {0.0, 0.5 * kPi, kPi}, 0.1 * tolerance);
        inner += ring.evaluations;
        const double w = 2.0 * st;
        return std::array<double, 4>{w * ring.value[0], w * ring.value[1], w * ring.error[0],
                                     w * ring.error[1]};
      },
      outer, tolerance);
  LtcMomentsReference r;
  r.magnitude = q.value[0];
  r.fresnel = q.value[1];
  constexpr double kFactor = 16.0;  // the house factor over the Gauss-Kronrod estimate
  r.magnitudeBound = kFactor * (q.error[0] + q.value[2]) + 1e-13;
  r.fresnelBound = kFactor * (q.error[1] + q.value[3]) + 1e-13;
  r.evaluations = static_cast<uint64_t>(inner);
  return r;
}

const std::vector<LtcRectangle> &LtcTestRectangles() {
  // {polar angle of the centre, its azimuth (0: the view's side, 180: the
  //  mirror direction's), half-width, half-height, roll}, degrees.
  static const double kSpec[12][5] = {
      {0, 0, 10, 10, 0},     {30, 180, 20, 10, 15}, {45, 160, 40, 25, 30}, {60, 200, 15, 15, 45},
      {75, 175, 30, 10, 10}, {85, 190, 20, 40, 0},  {20, 90, 35, 35, 20},  {50, 30, 25, 15, 60},
      {80, 0, 30, 30, 0},    {10, 200, 60, 60, 5},  {40, 250, 10, 30, 70}, {88, 140, 45, 20, 25},
  };
  static const std::vector<LtcRectangle> rectangles = [] {
    std::vector<LtcRectangle> out;
    const double deg = kPi / 180.0;
    for (const auto &s : kSpec) {
      const double th = s[0] * deg, ph = s[1] * deg, roll = s[4] * deg;
      const Vec3 c{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      // e1, e2: an orthonormal pair orthogonal to c (e1 horizontal).
      Vec3 e1 = s[0] == 0 ? Vec3{1, 0, 0} : Normalize(Cross({0, 0, 1}, c));
      Vec3 e2 = Cross(c, e1);
      const Vec3 a1{std::cos(roll) * e1.x + std::sin(roll) * e2.x,
                    std::cos(roll) * e1.y + std::sin(roll) * e2.y,
                    std::cos(roll) * e1.z + std::sin(roll) * e2.z};
      const Vec3 a2 = Cross(c, a1);
      const double hw = std::tan(s[2] * deg), hh = std::tan(s[3] * deg);
      LtcRectangle r;
      const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
      for (int k = 0; k < 4; ++k) {
        r.vertices[k] = {c.x + signs[k][0] * hw * a1.x + signs[k][1] * hh * a2.x,
                         c.y + signs[k][0] * hw * a1.y + signs[k][1] * hh * a2.y,
                         c.z + signs[k][0] * hw * a1.z + signs[k][1] * hh * a2.z};
      }
      out.push_back(r);
    }
    return out;
  }();
  return rectangles;
}

std::vector<double> RectangleLobeIntegrals(const LtcLobe &lobe, double mu_o, int level) {
  std::vector<double> out;
  for (const LtcRectangle &r : LtcTestRectangles()) {
    double sum = 0.0;
    for (const LtcNode &n : LtcLobePolygonRule(lobe, mu_o, level, r.vertices, 4))
      sum += n.weight * lobe.cosineWeighted(mu_o, n.l);
    out.push_back(sum);
  }
  return out;
}

namespace {

// D(l) for a unit l: w.z det / (pi |w|^4).
inline double UnitLtcDensity(const LtcMatrix &minv, double det, const Vec3 &l) {
  const Vec3 w = minv.Apply(l);
  if (w.z <= 0.0) return 0.0;
  const double len2 = Dot(w, w);
  return kInvPi * w.z * det / (len2 * len2);
}

// The lobe error with D scaled by ltcScale = (LTC magnitude) / m:
//   int_{l.z>0} |f (n.l) / m - c D| dl = Q[f] / m + c (1 - leakage) - 2 Q[min(f (n.l) / m, c D)].
double LobeError(const std::vector<LtcNode> &nodes, const std::vector<double> &lobeValues,
                 double magnitude, double ltcScale, const LtcMatrix &minv) {
  const double det = minv.Determinant();
  double lobeSum = 0.0, minSum = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const double a = lobeValues[k] / magnitude;
    const double b = ltcScale * UnitLtcDensity(minv, det, nodes[k].l);
    lobeSum += nodes[k].weight * a;
    minSum += nodes[k].weight * std::min(a, b);
  }
  return lobeSum + ltcScale * (1.0 - LtcLeakage(minv)) - 2.0 * minSum;
}

}  // namespace

LtcErrors MeasureLtcErrors(const LtcLobe &lobe, double mu_o, double magnitude,
                           const LtcMatrix &minv, const std::vector<double> &references) {
  return MeasureLtcErrors(lobe, mu_o, magnitude, magnitude, minv, references);
}

double LtcLobeError(const LtcLobe &lobe, double mu_o, double magnitude, double ltcMagnitude,
                    const LtcMatrix &minv, int level) {
  const std::vector<LtcNode> nodes = LtcLobeRule(lobe, mu_o, level, true);
  std::vector<double> values(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) values[k] = lobe.cosineWeighted(mu_o, nodes[k].l);
  return LobeError(nodes, values, magnitude, ltcMagnitude / magnitude, minv);
}

LtcErrors MeasureLtcErrors(const LtcLobe &lobe, double mu_o, double magnitude, double ltcMagnitude,
                           const LtcMatrix &minv, const std::vector<double> &references) {
  LtcErrors e;
  e.leakage = LtcLeakage(minv);
  // No lobe (magnitude 0): magnitude D = 0 = f (n.l) is exact.
  if (!(magnitude > 0.0)) return e;
  e.lobe = LtcLobeError(lobe, mu_o, magnitude, ltcMagnitude, minv, 1);
  e.leakage = LtcLeakage(minv);
  const std::vector<LtcRectangle> &rects = LtcTestRectangles();
  for (size_t k = 0; k < references.size() && k < rects.size(); ++k) {
    if (!(references[k] >= kLtcPolygonMinimumShare * magnitude)) continue;
    const double ltc = ltcMagnitude * LtcPolygonIntegral(minv, rects[k].vertices, 4, true);
    e.polygon = std::max(e.polygon, std::fabs(ltc - references[k]) / references[k]);
  }
  return e;
}

namespace {

// The parameters (theta*, log A, log rho, beta) of ltc_fit.h and back.
using Params = std::array<double, 4>;

LtcMatrix FromParams(const Params &p) {
  const double c = std::cos(p[0]), s = std::sin(p[0]);
  const double A = std::exp(p[1]), rho = std::exp(p[2]), B = p[3] * rho;
  return {rho * c, A * s + B * c, -rho * s, A * c - B * s};
}

Params ToParams(const LtcMatrix &m) { return LtcParameters(m); }

// Nelder-Mead on the first n parameters (the others fixed), deterministic.
template <typename F>
Params NelderMead(const Params &start, const Params &step, int n, int maxEvaluations, F &&f,
                  double *best, int *evaluations) {
  std::array<Params, 5> x;
  std::array<double, 5> fx{};
  int evals = 0;
  for (int i = 0; i <= n; ++i) {
    x[i] = start;
    if (i > 0) x[i][i - 1] += step[i - 1];
    fx[i] = f(x[i]);
    ++evals;
  }
  auto blend = [&](const Params &a, const Params &b, double t) {  // a + t (b - a)
    Params r = a;
    for (int k = 0; k < n; ++k) r[k] = a[k] + t * (b[k] - a[k]);
    return r;
  };
  while (evals < maxEvaluations) {
    // Order the simplex (stable: ties keep their order).
    std::array<int, 5> idx{0, 1, 2, 3, 4};
    std::stable_sort(idx.begin(), idx.begin() + n + 1, [&](int a, int b) { return fx[a] < fx[b]; });
    std::array<Params, 5> xs;
    std::array<double, 5> fs;
    for (int i = 0; i <= n; ++i) {
      xs[i] = x[idx[i]];
      fs[i] = fx[idx[i]];
    }
    x = xs;
    fx = fs;
    // Stop when the values agree to 1e-9 and the simplex is 1e-5 small (in
    // theta* and the logarithms: far below what changes the errors).
    double size = 0.0;
    for (int i = 1; i <= n; ++i)
      for (int k = 0; k < n; ++k) size = std::max(size, std::fabs(x[i][k] - x[0][k]));
    if (fx[n] - fx[0] <= 1e-9 * (1.0 + std::fabs(fx[0])) && size < 1e-5) break;
    if (fx[n] - fx[0] <= 1e-13 && size < 1e-4) break;
    Params centroid = x[0];
    for (int k = 0; k < n; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += x[i][k];
      centroid[k] = sum / n;
    }
    const Params xr = blend(centroid, x[n], -1.0);
    const double fr = f(xr);
    ++evals;
    if (fr < fx[0]) {
      const Params xe = blend(centroid, x[n], -2.0);
      const double fe = f(xe);
      ++evals;
      if (fe < fr) {
        x[n] = xe;
        fx[n] = fe;
      } else {
        x[n] = xr;
        fx[n] = fr;
      }
    } else if (fr < fx[n - 1]) {
      x[n] = xr;
      fx[n] = fr;
    } else {
      const bool outside = fr < fx[n];
      const Params xc = outside ? blend(centroid, xr, 0.5) : blend(centroid, x[n], 0.5);
      const double fc = f(xc);
      ++evals;
      if (fc < (outside ? fr : fx[n])) {
        x[n] = xc;
        fx[n] = fc;
      } else {
        for (int i = 1; i <= n; ++i) {
          x[i] = blend(x[0], x[i], 0.5);
          fx[i] = f(x[i]);
          ++evals;
        }
      }
    }
  }
  int bestIndex = 0;
  for (int i = 1; i <= n; ++i)
    if (fx[i] < fx[bestIndex]) bestIndex = i;
  *best = fx[bestIndex];
  *evaluations = evals;
  return x[bestIndex];
}

}  // namespace

std::array<double, 4> LtcParameters(const LtcMatrix &m) {
  const double rho = std::hypot(m.m00, m.m02);
  const double det = m.Determinant();
  if (!(det > 0.0) || !(rho > 0.0)) return {0.0, 0.0, 0.0, 0.0};  // the cosine
  const double theta = std::atan2(-m.m02, m.m00);
  const double c = std::cos(theta), s = std::sin(theta);
  const double B = m.m20 * c - m.m22 * s;
  return {theta, std::log(det / rho), std::log(rho), B / rho};
}

LtcTexel FitLtcTexel(const LtcLobe &lobe, double mu_o, const LtcMatrix &start,
                     const LtcFitSettings &settings) {
  LtcTexel out;
  if (!settings.moments) {
    // The caller integrates them.
  } else if (lobe.moments) {
    lobe.moments(mu_o, &out.magnitude, &out.fresnel);
  } else {
    IntegrateLobeMoments(lobe, mu_o, 1, &out.magnitude, &out.fresnel);
  }
  const std::vector<LtcNode> nodes = LtcLobeRule(lobe, mu_o, 0, true);
  // The lobe normalised by the rule's own integral, so that Q[f / m] = 1 and
  // the objective is the rule's L1 error of two unit densities.
  std::vector<LtcNode> used;
  std::vector<double> values;
  double total = 0.0;
  for (const LtcNode &n : nodes) total += n.weight * lobe.cosineWeighted(mu_o, n.l);
  // A lobe that vanishes (sheen at alpha = 0, or below double's range) has
  // nothing to fit: the start stands.
  if (!(total > 0.0) || !std::isfinite(total)) {
    out.minv = start;
    return out;
  }
  for (const LtcNode &n : nodes) {
    const double v = lobe.cosineWeighted(mu_o, n.l) / total;
    // Nodes that hold less than 1e-12 of the lobe can change min(f / m, D)
    // by no more than that: left out.
    if (n.weight * v < 1e-12) continue;
    used.push_back(n);
    values.push_back(v * n.weight);
  }
  const double weight = settings.leakageWeight;
  auto objective = [&](const Params &p) {
    const LtcMatrix m = FromParams(p);
    const double det = m.Determinant();
    double minSum = 0.0;
    for (size_t k = 0; k < used.size(); ++k)
      minSum += std::min(values[k], used[k].weight * UnitLtcDensity(m, det, used[k].l));
    const double leakage = LtcLeakage(m);
    return 2.0 - leakage - 2.0 * minSum + weight * leakage;
  };
  const bool axisymmetric = mu_o == 1.0;
  Params p0 = ToParams(start);
  int n = 4;
  if (axisymmetric) {
    // Only log A varies: theta* = 0, rho = 1, beta = 0.
    p0 = {p0[1], 0.0, 0.0, 0.0};
    n = 1;
  }
  auto wrapped = [&](const Params &q) {
    return objective(axisymmetric ? Params{0.0, q[0], 0.0, 0.0} : q);
  };
  // Steps: relative in A and rho; in theta* a quarter of the start's width
  // within the view plane, A / rho (a narrow lobe is missed by a wider step,
  // and where the LTC misses the lobe J is flat).
  const double width = std::exp(p0[1] - p0[2]);
  const Params step =
      axisymmetric ? Params{0.1, 0, 0, 0} : Params{std::min(0.05, 0.25 * width), 0.1, 0.1, 0.05};
  double best = 0.0;
  int evals = 0;
  Params p = NelderMead(p0, step, n, settings.maxEvaluations, wrapped, &best, &evals);
  // A restart from the result escapes a collapsed simplex.
  double best2 = 0.0;
  int evals2 = 0;
  Params halfStep = step;
  for (double &s : halfStep) s *= 0.5;
  p = NelderMead(p, halfStep, n, settings.maxEvaluations, wrapped, &best2, &evals2);
  if (axisymmetric) p = {0.0, p[0], 0.0, 0.0};
  out.minv = FromParams(p);
  out.objective = best2;
  out.evaluations = evals + evals2;
  return out;
}

double LtcTableMu(int i, int size) {
  const double x = static_cast<double>(i) / (size - 1);
  return 1.0 - x * x;
}

double LtcTableRoughness(int j, int size) { return static_cast<double>(j) / (size - 1); }

LtcTable FitLtcTable(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt, int size,
                     const LtcFitSettings &settings, bool errors, double muFloor) {
  assert(size >= 2);
  LtcTable t;
  t.size = size;
  for (int i = 0; i < size; ++i) t.mu.push_back(std::max(LtcTableMu(i, size), muFloor));
  for (int j = 0; j < size; ++j) t.roughness.push_back(LtcTableRoughness(j, size));
  const size_t count = static_cast<size_t>(size) * size;
  for (auto *v : {&t.m00, &t.m20, &t.m02, &t.m22, &t.magnitude, &t.fresnel}) v->assign(count, 0.0);
  if (errors)
    for (auto *v : {&t.lobeError, &t.polygonError, &t.leakage}) v->assign(count, 0.0);
  std::vector<int> evaluations(count, 0);
  std::vector<LtcLobe> lobes;
  for (int j = 0; j < size; ++j) lobes.push_back(lobeAt(LtcTableRoughness(j, size)));

  auto store = [&](int i, int j, const LtcTexel &x) {
    const size_t k = static_cast<size_t>(i) * size + j;
    t.m00[k] = x.minv.m00;
    t.m20[k] = x.minv.m20;
    t.m02[k] = x.minv.m02;
    t.m22[k] = x.minv.m22;
    t.magnitude[k] = x.magnitude;
    t.fresnel[k] = x.fresnel;
    evaluations[k] = x.evaluations;
    if (errors) {
      const double mu = t.mu[i];
      const LtcErrors e = MeasureLtcErrors(lobes[j], mu, x.magnitude, x.minv,
                                           RectangleLobeIntegrals(lobes[j], mu, 0));
      t.lobeError[k] = e.lobe;
      t.polygonError[k] = e.polygon;
      t.leakage[k] = e.leakage;
    }
  };
  // The column r = 1, sequentially in mu.
  std::vector<LtcTexel> first(size);
  LtcMatrix start;
  for (int i = 0; i < size; ++i) {
    first[i] = FitLtcTexel(lobes[size - 1], t.mu[i], start, settings);
    start = first[i].minv;
  }
  // Each mu in parallel, r from 1 down to 0.
  tbb::parallel_for(0, size, [&](int i) {
    const double mu = t.mu[i];
    store(i, size - 1, first[i]);
    LtcMatrix s = first[i].minv;
    for (int j = size - 2; j >= 0; --j) {
      const LtcTexel x = FitLtcTexel(lobes[j], mu, s, settings);
      store(i, j, x);
      s = x.minv;
    }
  });
  for (int e : evaluations) t.evaluations += e;
  return t;
}

namespace {

// The nodes of `values` above `from` (strictly), largest first.
std::vector<double> NodesAbove(const std::vector<double> &values, double from) {
  std::vector<double> out;
  for (double v : values)
    if (v > from) out.push_back(v);
  std::sort(out.begin(), out.end(), std::greater<double>());
  return out;
}

}  // namespace

std::vector<LtcTexel> FitLtcGrid(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt,
                                 const std::vector<double> &mu,
                                 const std::vector<double> &roughness,
                                 const LtcFitSettings &settings) {
  const size_t rows = mu.size(), columns = roughness.size();
  std::vector<LtcTexel> out(rows * columns);
  if (rows == 0 || columns == 0) return out;
  // Indices in decreasing order of their values.
  const auto decreasing = [](const std::vector<double> &v) {
    std::vector<size_t> order(v.size());
    for (size_t k = 0; k < v.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] > v[b]; });
    return order;
  };
  const std::vector<size_t> muOrder = decreasing(mu), rOrder = decreasing(roughness);
  std::vector<LtcLobe> lobes(columns);
  for (size_t j = 0; j < columns; ++j) lobes[j] = lobeAt(roughness[j]);
  // The top roughness, sequentially in mu.
  const size_t top = rOrder[0];
  LtcMatrix start;
  for (size_t i : muOrder) {
    out[i * columns + top] = FitLtcTexel(lobes[top], mu[i], start, settings);
    start = out[i * columns + top].minv;
  }
  // Each mu in parallel, down in roughness.
  tbb::parallel_for(size_t{0}, rows, [&](size_t i) {
    LtcMatrix s = out[i * columns + top].minv;
    for (size_t k = 1; k < columns; ++k) {
      const size_t j = rOrder[k];
      out[i * columns + j] = FitLtcTexel(lobes[j], mu[i], s, settings);
      s = out[i * columns + j].minv;
    }
  });
  return out;
}

LtcTexel FitLtcPoint(const std::function<LtcLobe(double perceptualRoughness)> &lobeAt, double mu,
                     double perceptualRoughness, const std::vector<double> &gridMu,
                     const std::vector<double> &gridRoughness, const LtcFitSettings &settings) {
  double top = perceptualRoughness;
  for (double r : gridRoughness) top = std::max(top, r);
  const bool above =
      std::none_of(gridRoughness.begin(), gridRoughness.end(), [&](double r) { return r == top; });
  // Above every node: the path of the top node, then one step up.
  const double columnR = above && !gridRoughness.empty()
                             ? *std::max_element(gridRoughness.begin(), gridRoughness.end())
                             : top;
  const LtcLobe column = lobeAt(columnR);
  LtcMatrix start;
  for (double m : NodesAbove(gridMu, mu)) start = FitLtcTexel(column, m, start, settings).minv;
  LtcTexel fit = FitLtcTexel(column, mu, start, settings);
  if (columnR == perceptualRoughness) return fit;
  if (columnR < perceptualRoughness)
    return FitLtcTexel(lobeAt(perceptualRoughness), mu, fit.minv, settings);
  std::vector<double> between;
  for (double r : NodesAbove(gridRoughness, perceptualRoughness))
    if (r < columnR) between.push_back(r);
  for (double r : between) fit = FitLtcTexel(lobeAt(r), mu, fit.minv, settings);
  return FitLtcTexel(lobeAt(perceptualRoughness), mu, fit.minv, settings);
}

LtcTable FitSheenLtcTable(SheenVisibility visibility, bool alphaIsRoughnessSquared, int size,
                          const LtcFitSettings &settings, bool errors) {
  return FitLtcTable(
      [visibility, alphaIsRoughnessSquared](double r) {
        return SheenLtcLobe(visibility, alphaIsRoughnessSquared ? r * r : r);
      },
      size, settings, errors, std::cos(1.57));
}

LtcTable FitGgxLtcTable(NdfKind ndf, SmithForm smith, int size, const LtcFitSettings &settings,
                        bool errors) {
  return FitLtcTable(
      [ndf, smith](double r) {
        return MicrofacetLtcLobe(Ndf{ndf, r * r}, smith);
      },
      size, settings, errors);
}

}  // namespace lutbake
