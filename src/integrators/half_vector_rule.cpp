#include "lutbake/integrators/half_vector_rule.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/models/ltc.h"

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

}  // namespace lutbake
