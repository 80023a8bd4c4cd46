#include "lutbake/integrators/ltc_fit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/integrators/sheen_quadrature.h"

namespace lutbake {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Nodes per panel: {azimuth, core, tail} at levels 0 (the fit), 1 (errors)
// and 2 (the check of level 1).
constexpr int kAzimuthNodes[3] = {8, 12, 18};
constexpr int kCoreNodes[3] = {8, 12, 18};
constexpr int kTailNodes[3] = {5, 8, 12};
// Tail panels shrink by this ratio toward the horizon (w = w_min) until
// narrower than max(alpha w_min, kTailSmallest) / 2: G2 falls to 0 at the
// horizon through a boundary layer of width ~alpha in mu_i, ~alpha w_min in w
// (mu_i ~ T_max - T there, dw = -w^2 / alpha dT).
constexpr double kTailRatio = 1.0 / 3.0;
constexpr double kTailSmallest = 1e-9;
// Azimuth panels are at most this wide in u (phi = phi_c -+ a sinh(u)).
constexpr double kAzimuthPanel = 1.2;

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The view's geometry and one azimuth.
struct Azimuth {
  double cosPhi, sinPhi, weight;  // weight: the outer rule's, times dphi/du
};

// T_max(phi) of the horizon, +inf when the whole meridian stays above it
// (mu = 0 and sc > 0). Stable forms of (sc + sqrt(sc^2 + mu^2)) / mu.
double HorizonT(double mu, double sc) {
  const double root = std::sqrt(sc * sc + mu * mu);
  if (sc > 0.0) return mu > 0.0 ? (sc + root) / mu : kInf;
  return root - sc > 0.0 ? mu / (root - sc) : 0.0;
}

// (n_e . l)(1 + T^2) along one azimuth, as the coefficients of a quadratic in T.
struct Quadratic {
  double a, b, c;
  double operator()(double T) const { return (a * T + b) * T + c; }
};
Quadratic EdgeQuadratic(const Vec3 &o, const Vec3 &ne, double cosPhi, double sinPhi) {
  const double a1 = o.x * cosPhi + o.y * sinPhi, a0 = o.z;  // o . h~ = a1 T + a0
  const double b1 = ne.x * cosPhi + ne.y * sinPhi, b0 = ne.z;
  const double k = Dot(ne, o);
  return {2.0 * a1 * b1 - k, 2.0 * (a1 * b0 + a0 * b1), 2.0 * a0 * b0 - k};
}

// Appends the roots of q in (lo, hi).
void AppendRoots(const Quadratic &q, double lo, double hi, std::vector<double> *roots) {
  auto add = [&](double r) {
    if (r > lo && r < hi && std::isfinite(r)) roots->push_back(r);
  };
  const double scale = std::max({std::fabs(q.a), std::fabs(q.b), std::fabs(q.c)});
  if (scale == 0.0) return;
  if (std::fabs(q.a) <= 1e-15 * scale) {
    if (q.b != 0.0) add(-q.c / q.b);
    return;
  }
  const double disc = q.b * q.b - 4.0 * q.a * q.c;
  if (disc < 0.0) return;
  // Citardauq: no cancellation between -b and the root of the discriminant.
  const double s = -0.5 * (q.b + std::copysign(std::sqrt(disc), q.b));
  add(s / q.a);
  if (s != 0.0) add(q.c / s);
}

// Emits the nodes of the T-interval [T0, T1] (T1 may be +inf) along one
// azimuth, cut at the core and tail panels.
class InnerRule {
 public:
  InnerRule(const Vec3 &o, double alpha, int level) : o_(o), alpha_(alpha), level_(level) {}

  // The panel breaks in T for the horizon tMax.
  void SetHorizon(double tMax) {
    breaks_.clear();
    kinds_.clear();
    // Core: t = T / alpha in [0, 1/2], [1/2, 1].
    breaks_.push_back(0.0);
    for (double t : {0.5, 1.0}) {
      breaks_.push_back(std::min(alpha_ * t, tMax));
      kinds_.push_back(0);
      if (alpha_ * t >= tMax) return;
    }
    // Tail: w = alpha / T from 1 down to wMin, graded.
    const double wMin = std::isfinite(tMax) ? alpha_ / tMax : 0.0;
    const double smallest = 0.5 * std::max(alpha_ * wMin, kTailSmallest);
    double width = (1.0 - wMin) * kTailRatio;
    while (width > smallest) {
      breaks_.push_back(alpha_ / (wMin + width));
      kinds_.push_back(1);
      width *= kTailRatio;
    }
    breaks_.push_back(tMax);
    kinds_.push_back(1);
  }

  template <typename Emit>
  void Interval(double T0, double T1, const Azimuth &az, Emit &&emit) const {
    for (size_t p = 0; p + 1 < breaks_.size(); ++p) {
      const double lo = std::max(T0, breaks_[p]), hi = std::min(T1, breaks_[p + 1]);
      if (!(hi > lo)) continue;
      if (kinds_[p] == 0) {
        Panel(lo / alpha_, hi / alpha_, false, az, emit);
      } else {
        Panel(alpha_ / hi, alpha_ / lo, true, az, emit);  // hi = inf gives w = 0
      }
    }
  }

 private:
  // Gauss nodes in v in [v0, v1]: v = t (core) or w (tail).
  template <typename Emit>
  void Panel(double v0, double v1, bool tail, const Azimuth &az, Emit &&emit) const {
    const GaussLegendreRule &rule = GaussLegendre(tail ? kTailNodes[level_] : kCoreNodes[level_]);
    const double a = alpha_;
    for (int k = 0; k < rule.n; ++k) {
      const double v = v0 + (v1 - v0) * rule.x[k];
      // h~ = (T cos, T sin, 1) up to scale, and the Jacobian
      // |dT/dv| T / (1 + T^2)^(3/2): core T = a t gives a^2 t / (1 + a^2 t^2)^(3/2),
      // tail T = a / w gives a^2 / (w^2 + a^2)^(3/2), written so that w -> 0 (T -> inf)
      // stays finite.
      double hx, hz, jac;
      if (!tail) {
        const double T = a * v;
        const double inv = 1.0 / std::sqrt(1.0 + T * T);
        hx = T * inv;
        hz = inv;
        jac = a * a * v * inv * inv * inv;
      } else {
        const double r = std::sqrt(v * v + a * a);
        hx = a / r;
        hz = v / r;
        jac = a * a / (r * r * r);
      }
      const Vec3 h{hx * az.cosPhi, hx * az.sinPhi, hz};
      const double oh = Dot(o_, h);
      if (oh <= 0.0) continue;  // not reached inside the horizon (l.z > 0 implies o.h > 0)
      const Vec3 l = Reflect(o_, h);
      emit(LtcNode{l, h, az.weight * rule.w[k] * (v1 - v0) * jac * 4.0 * oh});
    }
  }

  Vec3 o_;
  double alpha_;
  int level_;
  std::vector<double> breaks_;
  std::vector<int> kinds_;  // 0 core, 1 tail, per panel
};

// The azimuths: quarters [0, pi/2], [pi/2, pi], [pi, 3pi/2], [3pi/2, 2pi],
// each phi = phi_c -+ a sinh(u), phi_c = pi/2 or 3pi/2, u in [0, U], cut at
// the azimuths in `cuts`.
//
// With `smooth` each panel's Gauss variable x is mapped by x -> 3x^2 - 2x^3
// (dphi/dx = 6 x (1 - x) at the ends): an integrand that behaves like
// sqrt(phi - phi_c) next to a cut (where a polygon's edge is tangent to the
// meridian's curve) becomes smooth in x.
std::vector<Azimuth> AzimuthRule(double mu, int level, bool halfCircle,
                                 const std::vector<double> &cuts, bool smooth) {
  const double s = SafeSqrt(1.0 - mu * mu);
  // a is capped where the horizon does not depend on phi (mu = 1: s = 0) and
  // floored at grazing: at mu = 0 T_max jumps from +inf to 0 at phi = pi/2,
  // where the integrand falls to 0 like cos(phi) (o.h ~ T cos(phi)); panels
  // graded to a width ~1e-3 there resolve that kink.
  const double a = s > 0.0 ? Clamp(std::asinh(mu / s), 1e-3, 50.0) : 50.0;
  const double U = std::asinh(0.5 * kPi / a);
  const GaussLegendreRule &rule = GaussLegendre(kAzimuthNodes[level]);
  std::vector<Azimuth> out;
  const int quarters = halfCircle ? 2 : 4;
  for (int q = 0; q < quarters; ++q) {
    const double center = (q < 2) ? 0.5 * kPi : 1.5 * kPi;
    const double dir = (q % 2 == 0) ? -1.0 : 1.0;
    std::vector<double> ub;
    const int panels = std::max(1, static_cast<int>(std::ceil(U / kAzimuthPanel)));
    for (int p = 0; p <= panels; ++p) ub.push_back(U * p / panels);
    for (double phi : cuts) {
      const double d = dir * (phi - center);  // in (0, pi/2) inside this quarter
      if (d > 0.0 && d < 0.5 * kPi) ub.push_back(std::asinh(d / a));
    }
    std::sort(ub.begin(), ub.end());
    for (size_t p = 0; p + 1 < ub.size(); ++p) {
      const double u0 = ub[p], u1 = ub[p + 1];
      if (!(u1 > u0)) continue;
      for (int k = 0; k < rule.n; ++k) {
        const double x = rule.x[k];
        const double t = smooth ? x * x * (3.0 - 2.0 * x) : x;
        const double dt = smooth ? 6.0 * x * (1.0 - x) : 1.0;
        const double u = u0 + (u1 - u0) * t;
        const double phi = center + dir * a * std::sinh(u);
        const double w = rule.w[k] * dt * (u1 - u0) * a * std::cosh(u) * (halfCircle ? 2.0 : 1.0);
        out.push_back({std::cos(phi), std::sin(phi), w});
      }
    }
  }
  return out;
}

}  // namespace

std::vector<LtcNode> HalfVectorRule(double mu_o, double quadratureAlpha, int level,
                                    bool halfCircle) {
  assert(level >= 0 && level <= 2);
  const Vec3 o = ViewDirection(mu_o);
  InnerRule inner(o, quadratureAlpha, level);
  std::vector<LtcNode> nodes;
  for (const Azimuth &az : AzimuthRule(mu_o, level, halfCircle, {}, false)) {
    const double tMax = HorizonT(mu_o, o.x * az.cosPhi);
    if (!(tMax > 0.0)) continue;
    inner.SetHorizon(tMax);
    inner.Interval(0.0, tMax, az, [&](const LtcNode &n) { nodes.push_back(n); });
  }
  return nodes;
}

std::vector<LtcNode> HalfVectorPolygonRule(double mu_o, double quadratureAlpha, int level,
                                           const Vec3 *vertices, int count) {
  assert(count >= 3 && count <= 8);
  const Vec3 o = ViewDirection(mu_o);
  // Inward edge normals: oriented toward the polygon's centroid direction.
  Vec3 centre{0, 0, 0};
  for (int i = 0; i < count; ++i) {
    const Vec3 v = Normalize(vertices[i]);
    centre = {centre.x + v.x, centre.y + v.y, centre.z + v.z};
  }
  std::vector<Vec3> normals;
  for (int i = 0; i < count; ++i) {
    Vec3 n = Cross(vertices[i], vertices[(i + 1) % count]);
    if (Dot(n, centre) < 0.0) n = {-n.x, -n.y, -n.z};
    normals.push_back(n);
  }
  // Azimuth cuts: the half vectors of the vertices of P clipped at the horizon.
  Vec3 clipped[9];
  const int m = ClipPolygonToUpperHalfSpace(vertices, count, clipped);
  std::vector<double> cuts;
  for (int i = 0; i < m; ++i) {
    const Vec3 v = Normalize(clipped[i]);
    const Vec3 h{o.x + v.x, o.y + v.y, o.z + v.z};
    if (std::hypot(h.x, h.y) <= 1e-14 * std::sqrt(Dot(h, h))) continue;
    double phi = std::atan2(h.y, h.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    cuts.push_back(phi);
  }
  // And the azimuths where an edge's quadratic has a double root (the
  // meridian's curve touches the edge's great circle): the zeros of its
  // discriminant, a trigonometric polynomial of degree 2 in phi, found by
  // sign changes on 720 azimuths (a table of their cosines and sines, made
  // once) and bisection.
  constexpr int kSamples = 720;
  static const std::vector<std::array<double, 2>> circle = [] {
    std::vector<std::array<double, 2>> c(kSamples + 1);
    for (int k = 0; k <= kSamples; ++k) {
      const double phi = 2.0 * kPi * k / kSamples;
      c[k] = {std::cos(phi), std::sin(phi)};
    }
    return c;
  }();
  for (const Vec3 &n : normals) {
    auto disc = [&](double cosPhi, double sinPhi) {
      const Quadratic q = EdgeQuadratic(o, n, cosPhi, sinPhi);
      return q.b * q.b - 4.0 * q.a * q.c;
    };
    double prev = disc(circle[0][0], circle[0][1]);
    for (int k = 1; k <= kSamples; ++k) {
      const double cur = disc(circle[k][0], circle[k][1]);
      if ((prev < 0.0) != (cur < 0.0)) {
        double lo = 2.0 * kPi * (k - 1) / kSamples, hi = 2.0 * kPi * k / kSamples;
        const bool loNegative = prev < 0.0;
        for (int it = 0; it < 50; ++it) {
          const double mid = 0.5 * (lo + hi);
          ((disc(std::cos(mid), std::sin(mid)) < 0.0) == loNegative ? lo : hi) = mid;
        }
        cuts.push_back(0.5 * (lo + hi));
      }
      prev = cur;
    }
  }
  InnerRule inner(o, quadratureAlpha, level);
  std::vector<LtcNode> nodes;
  if (m == 0) return nodes;
  std::vector<Quadratic> quads;
  std::vector<double> roots;
  for (const Azimuth &az : AzimuthRule(mu_o, level, false, cuts, true)) {
    const double tMax = HorizonT(mu_o, o.x * az.cosPhi);
    if (!(tMax > 0.0)) continue;
    quads.clear();
    roots.assign(1, 0.0);
    for (const Vec3 &n : normals) {
      quads.push_back(EdgeQuadratic(o, n, az.cosPhi, az.sinPhi));
      AppendRoots(quads.back(), 0.0, tMax, &roots);
    }
    std::sort(roots.begin(), roots.end());
    roots.push_back(tMax);
    inner.SetHorizon(tMax);
    for (size_t k = 0; k + 1 < roots.size(); ++k) {
      const double T0 = roots[k], T1 = roots[k + 1];
      if (!(T1 > T0)) continue;
      const double mid = std::isfinite(T1) ? 0.5 * (T0 + T1) : 2.0 * T0 + 1.0;
      bool inside = true;
      for (const Quadratic &q : quads) inside = inside && q(mid) >= 0.0;
      if (inside) inner.Interval(T0, T1, az, [&](const LtcNode &n) { nodes.push_back(n); });
    }
  }
  return nodes;
}

void IntegrateLobeMoments(const LtcLobe &lobe, double mu_o, int level, double *magnitude,
                          double *fresnel) {
  const Vec3 o = ViewDirection(mu_o);
  double m = 0.0, f = 0.0;
  for (const LtcNode &n : HalfVectorRule(mu_o, lobe.quadratureAlpha, level, true)) {
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
    for (const LtcNode &n : HalfVectorPolygonRule(mu_o, lobe.quadratureAlpha, level, r.vertices, 4))
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
  const std::vector<LtcNode> nodes = HalfVectorRule(mu_o, lobe.quadratureAlpha, level, true);
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

Params ToParams(const LtcMatrix &m) {
  const double rho = std::hypot(m.m00, m.m02);
  const double det = m.Determinant();
  if (!(det > 0.0) || !(rho > 0.0)) return {0.0, 0.0, 0.0, 0.0};  // the cosine
  const double theta = std::atan2(-m.m02, m.m00);
  const double c = std::cos(theta), s = std::sin(theta);
  const double B = m.m20 * c - m.m22 * s;
  return {theta, std::log(det / rho), std::log(rho), B / rho};
}

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
    // Stop when the values agree to 1e-10 and the simplex is 1e-7 small.
    double size = 0.0;
    for (int i = 1; i <= n; ++i)
      for (int k = 0; k < n; ++k) size = std::max(size, std::fabs(x[i][k] - x[0][k]));
    if (fx[n] - fx[0] <= 1e-10 * (1.0 + std::fabs(fx[0])) && size < 1e-7) break;
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

LtcTexel FitLtcTexel(const LtcLobe &lobe, double mu_o, const LtcMatrix &start,
                     const LtcFitSettings &settings) {
  LtcTexel out;
  if (lobe.moments) {
    lobe.moments(mu_o, &out.magnitude, &out.fresnel);
  } else {
    IntegrateLobeMoments(lobe, mu_o, 1, &out.magnitude, &out.fresnel);
  }
  const std::vector<LtcNode> nodes = HalfVectorRule(mu_o, lobe.quadratureAlpha, 0, true);
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
  // The row r = 1, sequentially in mu.
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
