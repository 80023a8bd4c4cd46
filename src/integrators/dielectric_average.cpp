// The rough-dielectric average albedo E_avg over the half vector first
// (dielectric_quadrature.h gives the integral, the breaks and the bound).
//
// With o at c = o.h from the facet h (h.z = cos(theta) = h_z, sin(theta) =
// h_s) and azimuth psi about h, d(omega_o) = dc d(psi), and
//   mu_o = c h_z + u,  mu_r = c h_z - u,  |mu_t| = (W h_z + u) / eta,
//   u = sqrt(1 - c^2) h_s cos(psi),  W = sqrt(eta^2 - 1 + c^2)
// (dielectric.h: mu_t = ((c - W) h_z - mu_o) / eta). Swapping the view and
// the facet in E_avg = (1/pi) int d(omega_o) mu_o E(o), and D cos(theta)
// d(omega_h) = d(xi) d(phi_h) / (2 pi) (xi the NDF's CDF in theta):
//   E_avg = (2/pi) int d(xi) / h_z int_0^1 c dc [F(c) A_r + (1 - F(c)) A_t],
//   A_r = int_0^pi d(psi) G2(mu_o, mu_r) [mu_o > 0, mu_r > 0],
//   A_t = int_0^pi d(psi) G2(mu_o, |mu_t|) [mu_o > 0, mu_t < 0].
// F depends on c alone, so the critical cosine is a coordinate line, and the
// horizons are closed-form ends of the psi ranges.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "integrators/dielectric_kernel.h"
#include "integrators/graded_panels.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/integrators/gauss_legendre.h"

namespace lutbake {

namespace {

using graded::AppendPanel;
using graded::AppendPoint;
using graded::BuildPanels;
using graded::GradeToward;
using graded::MapNode;
using graded::Panel;
using graded::Point;

constexpr int kLevels = 6;
// Gauss nodes per panel at each level, in all three variables (a level
// costs n^3 a panel). Smaller steps past the first pair (5, 7, 9, 12, 16,
// 21) took 9% fewer G2 values on the default glass_Eavg grid at tolerance
// 1e-8, but 31% more at check's 2.4e-9 (panels reached the last level,
// split, and 7 of 368 texels fell back on the rule over the albedos), which
// put `check` of a default glass set past twice its bake; a seventh level
// (28) fixed that but cost 18% more at eta = 0.1 (the cycles preset's
// range). Kept as it was.
constexpr int kNodes[kLevels] = {5, 7, 10, 14, 19, 25};
constexpr double kBoundFloor = 1e-10;
constexpr double kDifferenceFactor = 2.0;
constexpr double kToleranceShare = 0.2;
// The share of the tolerance the outer panels' doubled differences may take
// (with kToleranceShare and the floor, the bound stays below the tolerance).
constexpr double kPanelShare = 0.7;
// Grading toward the breaks in c and psi: each panel keeps this share of
// what is left (ratio 4).
constexpr double kKeep = 0.25;
constexpr double kBeckmannCut = 7.0;
// Where the panels keep splitting (the differences stop shrinking: a few
// (r, eta) pairs, e.g. eta < 0.15 at r ~ 0.5, where the azimuth panels'
// layout jumps between neighbouring facets) or the values run past this
// budget, the rule over the albedos answers instead (the smaller bound).
constexpr int kMaxOuterPanels = 24;
constexpr uint64_t kEvaluationBudget = 40000000;
constexpr double kMaxPanel = 0.5;          // in c, x and w
constexpr double kBeckmannMaxPanel = 1.0;  // in t

struct Setup {
  Ndf ndf;
  SmithForm smith;
  bool glass;
  double eta;
  double cc;       // c_crit = sqrt(1 - eta^2) for eta < 1, else 0
  double grazing;  // F's singularities near c = 0 (eta > 1): half their distance
  double layer;    // G2's layer in a cosine: alpha / 2 (Lambda's branch points at mu ~ +-i alpha)
  uint64_t *evaluations;  // G2 values taken
  double alpha2;          // alpha^2
};

// GGX's mu Lambda(mu) (ggx.h's form: alpha^2 sin^2 / (2 (root + mu))).
inline double GgxMuLambda(double alpha2, double mu) {
  const double a2s2 = alpha2 * std::max(0.0, (1.0 - mu) * (1.0 + mu));
  const double root = std::sqrt(mu * mu + a2s2);
  return root + mu > 0.0 ? a2s2 / (2.0 * (root + mu)) : 0.0;
}

// G2 (smith.h's forms), 0 unless both cosines are positive.
inline double G2(const Setup &s, double mu_o, double mu_i) {
  mu_o = std::min(mu_o, 1.0);
  mu_i = std::min(mu_i, 1.0);
  if (!(mu_o > 0.0 && mu_i > 0.0)) return 0.0;
  const bool ggx = s.ndf.kind == NdfKind::kGgx;
  const double L_o = ggx ? GgxMuLambda(s.alpha2, mu_o) : s.ndf.MuLambda(mu_o);
  const double L_i = ggx ? GgxMuLambda(s.alpha2, mu_i) : s.ndf.MuLambda(mu_i);
  if (s.smith == SmithForm::kCorrelated) {
    const double denom = mu_o * mu_i + mu_i * L_o + mu_o * L_i;
    return denom > 0.0 ? mu_o * mu_i / denom : 0.0;
  }
  return (mu_o / (mu_o + L_o)) * (mu_i / (mu_i + L_i));
}

// How close to a horizon G2 is singular, in that cosine: correlated, its
// denominator mu_o mu_i + mu_i L_o + mu_o L_i vanishes at mu ~ -other L /
// (other + L), L ~ alpha / 2, `other` the other cosine there (and Lambda's
// branch points sit at ~ +-i alpha): min(alpha / 2, other), at least 1e-14.
double LayerBeside(const Setup &s, double other) {
  return std::max(std::min(s.layer, other), graded::kSmallestScale);
}

// The two cosines along an azimuth range, affine in cos(psi): mu_o = a +
// ka cos(psi), mu_i = (b + kb cos(psi)) / divisor.
struct CosineLine {
  double a, ka, b, kb, divisor;
};

// The azimuth integrals run in v = tan(psi / 2) (or of pi - psi): cos(psi)
// = (1 - v^2) / (1 + v^2), d(psi) = 2 dv / (1 + v^2), no trigonometry at the
// nodes. v = 0 is psi = 0, v = 1 psi = pi/2; a horizon at cos(psi_k) = k / S
// (|k| < S) sits at v_k = sqrt((S - k) / (S + k)); where none is crossed, the
// smallest cosine delta >= 0 is at v = 0 (of the far side). Panels [from,
// to], graded toward `from` (towardFrom) or `to` down to `scalePsi` (in psi;
// dv/d(psi) = (1 + v^2) / 2 there), and the sum of G2 d(psi) over them.
double HalfAngleArc(double from, double to, double scalePsi, bool towardFrom,
                    const GaussLegendreRule &rule, const Setup &s, const CosineLine &line) {
  thread_local std::vector<Panel> panels;
  thread_local std::vector<double> nodes, ruleW, terms;
  panels.clear();
  if (!(from < to)) return 0.0;
  const double end = towardFrom ? from : to;
  const double scale = 0.5 * scalePsi * (1.0 + end * end);
  if (scale > 0.0 && scale < 0.5 * (to - from))
    GradeToward(from, to, scale, towardFrom, &panels, kKeep);
  else
    AppendPanel(&panels, from, to);
  const size_t n = static_cast<size_t>(rule.n), total = panels.size() * n;
  *s.evaluations += total;
  // Padded to whole vectors of 8 with v = 0 and weight 0 (terms 0, not
  // summed): the kernel then never takes its path for a last partial vector.
  const size_t padded = (total + 7) / 8 * 8;
  if (nodes.size() < padded) {
    nodes.resize(padded);
    ruleW.resize(padded);
    terms.resize(padded);
  }
  for (size_t k = total; k < padded; ++k) nodes[k] = ruleW[k] = 0.0;
  size_t k = 0;
  for (const Panel &p : panels) {
    const double len = p.b - p.a;
    for (size_t j = 0; j < n; ++j, ++k) {
      nodes[k] = p.a + len * rule.x[j];
      ruleW[k] = rule.w[j];
    }
  }
  if (s.ndf.kind == NdfKind::kGgx) {
    // q, the cosines and G2 by the vector kernel (dielectric_kernel.h).
    const kernel::ArcConstants constants{s.alpha2, s.smith,           line.a, line.ka, line.b,
                                         line.kb,  1.0 / line.divisor};
    kernel::ArcTerms(constants, nodes.data(), ruleW.data(), padded, terms.data());
  } else {
    for (k = 0; k < total; ++k) {
      const double v = nodes[k], q = 1.0 / (1.0 + v * v);
      const double cosPsi = (1.0 - v * v) * q;
      terms[k] = ruleW[k] * q *
                 G2(s, line.a + line.ka * cosPsi, (line.b + line.kb * cosPsi) / line.divisor);
    }
  }
  double sum = 0.0;
  k = 0;
  for (const Panel &p : panels) {
    double part = 0.0;
    for (size_t j = 0; j < n; ++j, ++k) part += terms[k];
    sum += part * (p.b - p.a);
  }
  return 2.0 * sum;
}

// The grading scale in psi toward a horizon at psi_k (the cosine reaching 0
// at rate S sin(psi_k) per unit psi, its layer `layer` wide): layer / (S
// max(sin(psi_k), sqrt(layer / S))), the second form where psi_k sits near 0
// and the cosine is quadratic in psi.
double HorizonScale(double sinPsi, double S, double layer) {
  return layer / (S * std::max(sinPsi, std::sqrt(layer / S)));
}

// Where no horizon is crossed, the smallest cosine delta >= 0 sits at psi =
// 0 (or pi); G2's singularities at that cosine +-i layer are sqrt(max(delta,
// layer) / S) away in psi.
double EndScale(double delta, double S, double layer) {
  return std::sqrt(std::max(delta, layer) / S);
}

// A_r at a = c h_z, S = sqrt(1 - c^2) h_s: mu_o and mu_r trade places
// under psi -> pi - psi, so A_r = 2 int_{psi_lo}^{pi/2}, psi_lo the mirror's
// horizon (u = a) or 0.
double ReflectionArc(const Setup &s, double a, double S, const GaussLegendreRule &rule) {
  if (!(a > 0.0)) return 0.0;
  if (!(S > 0.0)) return kPi * G2(s, a, a);
  const CosineLine g{a, S, a, -S, 1.0};
  if (S > a) {
    const double sinPsi = std::sqrt((S - a) * (S + a)) / S;
    return 2.0 * HalfAngleArc(std::sqrt((S - a) / (S + a)), 1.0,
                              HorizonScale(sinPsi, S, LayerBeside(s, 2.0 * a)), true, rule, s, g);
  }
  return 2.0 * HalfAngleArc(0.0, 1.0, EndScale(a - S, S, LayerBeside(s, a + S)), true, rule, s, g);
}

// A_t at a = c h_z, b = W h_z: mu_o = a + u and |mu_t| = (b + u) / eta are
// positive for u > -m, m = min(a, b): psi from 0 to the horizon (cos(psi_t) =
// -m / S) or to pi.
double TransmissionArc(const Setup &s, double a, double b, double S,
                       const GaussLegendreRule &rule) {
  const double m = std::min(a, b);
  if (!(m > 0.0)) return 0.0;
  if (!(S > 0.0)) return kPi * G2(s, a, b / s.eta);
  // The binding cosine's layer in u: mu_o's beside mu_t = (b - a) / eta, or
  // mu_t's (eta times narrower in u) beside mu_o = a - b, at that horizon.
  const double layer = b < a ? s.eta * LayerBeside(s, a - b) : LayerBeside(s, (b - a) / s.eta);
  const CosineLine near{a, S, b, S, s.eta}, far{a, -S, b, -S, s.eta};
  if (S > m) {
    const double sinPsi = std::sqrt((S - m) * (S + m)) / S;
    const double scale = HorizonScale(sinPsi, S, layer);
    // The horizon at v_t = sqrt((S + m) / (S - m)): up to v_t = 2 (psi_t =
    // 127 degrees) one range graded toward it (split at pi/2, the layer of a
    // horizon just past pi/2 would reach the ungraded side); beyond, the
    // quarter turn to pi/2 and the far side from the horizon.
    const double vt = std::sqrt((S + m) / (S - m));
    if (vt <= 2.0) return HalfAngleArc(0.0, vt, scale, false, rule, s, near);
    return HalfAngleArc(0.0, 1.0, 0.0, true, rule, s, near) +
           HalfAngleArc(1.0 / vt, 1.0, scale, true, rule, s, far);
  }
  return HalfAngleArc(0.0, 1.0, 0.0, true, rule, s, near) +
         HalfAngleArc(0.0, 1.0, EndScale(m - S, S, layer), true, rule, s, far);
}

// int_0^1 c dc [F A_r + (1 - F) A_t] at the facet (h_z, h_s). Its breaks in
// c: c_crit (eta < 1: 1 - F ~ sqrt(c - c_crit), the refracting side mapped
// quadratically and graded down to c_crit / 2, F's other singularities being
// -c_crit and 0); c = h_s, where the mirror's (and for eta >= 1 the view's)
// horizon enters the psi range at psi = 0 (a (c - h_s)^(3/2) point: the
// panel below mapped quadratically, both sides graded to G2's layer,
// alpha h_z / 2 in c); for glass with eta < 1 c_t = sqrt(1 - eta^2 h_z^2),
// where the refracted horizon enters (layer eta alpha / 2 in u, rate c_t /
// (eta h_s h_z) in c); and c = 0, graded to F's branch points for eta > 1.
double OverFacetCosine(const Setup &s, double hz, double hs, const GaussLegendreRule &rule) {
  thread_local std::vector<Point> points;
  thread_local std::vector<Panel> panels;
  points.clear();
  panels.clear();
  AppendPoint(&points, 0.0, 0.0, s.grazing);
  AppendPoint(&points, 1.0, 0.0, 0.0);
  if (s.cc > 0.0) AppendPoint(&points, s.cc, 0.0, 0.5 * s.cc, false, true);
  if (hs > 0.0 && hs < 1.0) {
    // The other cosine there: mu_o = 2 h_s h_z; |d(c h_z - S)/dc| = 1 / h_z.
    const double scale = LayerBeside(s, 2.0 * hs * hz) * hz;
    AppendPoint(&points, hs, scale, scale, true, false, kKeep);
  }
  if (s.glass && s.cc > 0.0 && hs > 0.0) {
    const double ct = std::sqrt((1.0 - s.eta * hz) * (1.0 + s.eta * hz));
    if (ct > s.cc && ct < 1.0) {
      // W = eta h_s there, mu_o = (c_t - eta h_s) h_z; rate c_t / (eta h_s h_z).
      const double scale = s.eta * LayerBeside(s, (ct - s.eta * hs) * hz) * s.eta * hs * hz / ct;
      AppendPoint(&points, ct, scale, scale, true, false, kKeep);
    }
  }
  std::sort(points.begin(), points.end(), [](const Point &x, const Point &y) { return x.v < y.v; });
  // A break's grading reaches no further than its nearest neighbour: where
  // c = h_s comes close to c_crit (theta near theta_b), F's branch point is
  // the singularity beside it.
  for (size_t k = 1; k + 1 < points.size(); ++k) {
    const double gap = std::min(points[k].v - points[k - 1].v, points[k + 1].v - points[k].v);
    if (points[k].below > 0.0) points[k].below = std::min(points[k].below, gap);
    if (points[k].above > 0.0) points[k].above = std::min(points[k].above, gap);
  }
  BuildPanels(points, kMaxPanel, 0.0, &panels);
  double sum = 0.0;
  for (const Panel &p : panels) {
    double part = 0.0;
    for (int j = 0; j < rule.n; ++j) {
      double c = 0.0;
      const double jac = MapNode(p, rule.x[j], &c);
      const double sinC = std::sqrt((1.0 - c) * (1.0 + c));
      const double a = c * hz, S = sinC * hs;
      const DielectricFresnelTerms f = DielectricFresnel(s.eta, c);
      double v = 0.0;
      if (f.F > 0.0) v += f.F * ReflectionArc(s, a, S, rule);
      if (s.glass && f.T > 0.0) v += f.T * TransmissionArc(s, a, f.W * hz, S, rule);
      part += rule.w[j] * jac * c * v;
    }
    sum += part;
  }
  return sum;
}

enum class Variable { kCore, kTail, kBeckmann };

struct OuterPanel {
  Panel p;
  Variable variable;
  int level = 0;
  double value = 0.0, difference = 0.0;
};

// One outer panel at one level: int d(xi) / h_z [...] over it, the same
// level's rule in c and psi.
double OuterAt(const Setup &s, const OuterPanel &o, int level) {
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  const double alpha = s.ndf.alpha;
  double part = 0.0;
  for (int j = 0; j < rule.n; ++j) {
    double v = 0.0;
    const double jac = MapNode(o.p, rule.x[j], &v);
    double hz = 1.0, hs = 0.0, measure = 0.0;
    if (o.variable == Variable::kTail) {
      // w = alpha / T: h_z = w / r, h_s = alpha / r, r = sqrt(w^2 + alpha^2);
      // d(xi)/dw / h_z = (2 w / (1 + w^2)^2) (r / w).
      const double r = std::sqrt(v * v + alpha * alpha), q = 1.0 + v * v;
      hz = v / r;
      hs = alpha / r;
      measure = 2.0 * r / (q * q);
    } else {
      const double T = alpha * v, q = std::sqrt(1.0 + T * T);
      hz = 1.0 / q;
      hs = T / q;
      if (o.variable == Variable::kCore) {
        const double q2 = 1.0 + v * v;
        measure = 2.0 * v / (q2 * q2) * q;  // d(xi)/dx = 2 x / (1 + x^2)^2
      } else {
        measure = 2.0 * v * std::exp(-v * v) * q;  // d(xi)/dt = 2 t exp(-t^2)
      }
    }
    part += rule.w[j] * jac * measure * OverFacetCosine(s, hz, hs, rule);
  }
  return 2.0 * kInvPi * part;
}

// The outer panels. For eta < 1 the breaks in c = h_s and c = c_crit cross
// at sin(theta_b) = c_crit, T_b = c_crit / eta: a break in theta, mapped
// quadratically on both sides and graded toward to the scale on which
// those layers cross (alpha / (4 h_z^2) in T).
void LayOuterPanels(const Setup &s, std::vector<OuterPanel> *out) {
  const double alpha = s.ndf.alpha;
  const bool hasBreak = s.cc > 0.0;
  const double Tb = hasBreak ? s.cc / s.eta : 0.0;
  const double hzB = hasBreak ? 1.0 / std::sqrt(1.0 + Tb * Tb) : 1.0;
  const double scaleT = 0.25 * alpha / (hzB * hzB);
  std::vector<Point> points;
  std::vector<Panel> panels;
  const auto add = [&](Variable variable) {
    for (const Panel &p : panels) out->push_back({p, variable});
    panels.clear();
    points.clear();
  };
  if (s.ndf.kind == NdfKind::kBeckmann) {
    AppendPoint(&points, 0.0, 0.0, 0.0);
    if (hasBreak && Tb / alpha < kBeckmannCut)
      AppendPoint(&points, Tb / alpha, scaleT / alpha, scaleT / alpha, true, true);
    AppendPoint(&points, kBeckmannCut, 0.0, 0.0);
    BuildPanels(points, kBeckmannMaxPanel, 0.0, &panels);
    add(Variable::kBeckmann);
    return;
  }
  // Core x = T / alpha in [0, 1].
  AppendPoint(&points, 0.0, 0.0, 0.0);
  if (hasBreak && Tb < alpha)
    AppendPoint(&points, Tb / alpha, scaleT / alpha, scaleT / alpha, true, true);
  AppendPoint(&points, 1.0, 0.0, 0.0);
  BuildPanels(points, kMaxPanel, 0.0, &panels);
  add(Variable::kCore);
  // Tail w = alpha / T in [0, 1] (|dw/dT| = w^2 / alpha), graded toward w =
  // 0 (theta = pi/2, where the breaks in c reach c = 1) from alpha / 4.
  AppendPoint(&points, 0.0, 0.0, 0.25 * alpha, false, false, kKeep);
  if (hasBreak && Tb > alpha) {
    const double wb = alpha / Tb, scaleW = scaleT * wb * wb / alpha;
    AppendPoint(&points, wb, scaleW, scaleW, true, true);
  }
  AppendPoint(&points, 1.0, 0.0, 0.0);
  BuildPanels(points, kMaxPanel, alpha, &panels);
  add(Variable::kTail);
}

}  // namespace

namespace {

// The rule over the half vector (the header), for 0 < alpha <= 1.
DielectricIntegral AverageOverHalfVector(NdfKind ndf, SmithForm smith, DielectricLobes lobes,
                                         double alpha, double eta, double tolerance) {
  DielectricIntegral out;
  const bool glass = lobes == DielectricLobes::kReflectionAndTransmission;
  Setup s;
  s.ndf = Ndf{ndf, alpha};
  s.smith = smith;
  s.glass = glass;
  s.eta = eta;
  s.cc = eta < 1.0 ? std::sqrt((1.0 - eta) * (1.0 + eta)) : 0.0;
  // F's singularities nearest c = 0 for eta > 1: W = 0 at c = +-i sqrt(eta^2
  // - 1), and r_p's pole eta^2 c + W = 0 at c = -1 / sqrt(eta^2 + 1) (within
  // 1/eta of the range at high indices).
  s.grazing = eta > 1.0 ? 0.5 * std::min(std::sqrt((eta - 1.0) * (eta + 1.0)),
                                         1.0 / std::sqrt(eta * eta + 1.0))
                        : 0.0;
  s.layer = 0.5 * alpha;
  s.alpha2 = alpha * alpha;
  uint64_t evaluations = 0;
  s.evaluations = &evaluations;
  std::vector<OuterPanel> panels;
  LayOuterPanels(s, &panels);
  double differences = 0.0;
  const auto start = [&](OuterPanel &o) {
    const double v0 = OuterAt(s, o, 0);
    o.value = OuterAt(s, o, 1);
    o.difference = std::abs(o.value - v0);
    o.level = 1;
  };
  for (OuterPanel &o : panels) {
    start(o);
    differences += o.difference;
  }
  // The panel with the largest difference a level further (at the last
  // level split in two) until twice the differences are within the share.
  while (kDifferenceFactor * differences > kPanelShare * tolerance &&
         evaluations <= kEvaluationBudget) {
    size_t worst = 0;
    for (size_t k = 1; k < panels.size(); ++k)
      if (panels[k].difference > panels[worst].difference) worst = k;
    OuterPanel &w = panels[worst];
    if (w.level + 1 < kLevels) {
      const double v = OuterAt(s, w, w.level + 1);
      differences -= w.difference;
      w.difference = std::abs(v - w.value);
      differences += w.difference;
      w.value = v;
      ++w.level;
      continue;
    }
    const double mid = 0.5 * (w.p.a + w.p.b);
    if (static_cast<int>(panels.size()) >= kMaxOuterPanels || !(mid > w.p.a && mid < w.p.b)) break;
    // The half away from a mapped end is linear.
    OuterPanel left{{w.p.a, mid, w.p.square > 0 ? 1 : 0}, w.variable};
    OuterPanel right{{mid, w.p.b, w.p.square < 0 ? -1 : 0}, w.variable};
    differences -= w.difference;
    start(left);
    start(right);
    differences += left.difference + right.difference;
    panels[worst] = left;
    panels.insert(panels.begin() + static_cast<std::ptrdiff_t>(worst) + 1, right);
  }
  // Summed afresh in panel order (the running sum may have drifted).
  double value = 0.0;
  differences = 0.0;
  for (const OuterPanel &o : panels) {
    value += o.value;
    differences += o.difference;
  }
  const double cut = ndf == NdfKind::kBeckmann
                         ? std::exp(-kBeckmannCut * kBeckmannCut) * (1.0 + 8.0 * alpha)
                         : 0.0;
  out.value = value;
  out.bound = kDifferenceFactor * differences + kBoundFloor + kToleranceShare * tolerance + cut;
  out.converged = out.bound <= tolerance * std::max(1.0, std::abs(value));
  out.evaluations = evaluations;
  if (!out.converged) {
    const DielectricIntegral before =
        IntegrateDielectricAverageOverAlbedo(ndf, smith, lobes, alpha, eta, tolerance);
    if (before.bound < out.bound) out = before;
    out.evaluations = evaluations + before.evaluations;
  }
  return out;
}

}  // namespace

DielectricIntegral IntegrateDielectricAverage(NdfKind ndf, SmithForm smith, DielectricLobes lobes,
                                              double alpha, double eta, double tolerance) {
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw std::invalid_argument("dielectric average: alpha must lie in [0, 1]");
  if (!(eta >= kMinRelativeIor && eta <= kMaxRelativeIor))
    throw std::invalid_argument("dielectric average: eta must lie in [1/128, 128]");
  if (!(tolerance > 0.0))
    throw std::invalid_argument("dielectric average: tolerance must be positive");
  DielectricIntegral out;
  const bool glass = lobes == DielectricLobes::kReflectionAndTransmission;
  if (alpha == 0.0 && glass) {
    out.value = 1.0;  // the smooth interface scatters everything
    out.exact = out.converged = true;
    return out;
  }
  if (alpha == 0.0)  // the smooth interface: F_avg, from the rule that knows its kinks
    return IntegrateDielectricAverageOverAlbedo(ndf, smith, lobes, alpha, eta, tolerance);
  if (glass && eta < 1.0) {
    // Reciprocity (the header): the reflection inside, and glass and its
    // reflection entering at 1 / eta (in [1, 128] for eta in [1/128, 1)).
    // Measured on the default glass_Eavg grid's eta < 1 slices (32 x 11
    // texels, tolerance 1e-8): within 0.057 of the summed bounds of the
    // direct rule, at 0.76 of its time.
    const double eta2 = eta * eta, share = tolerance / (1.0 + 2.0 * eta2);
    const DielectricIntegral inside =
        AverageOverHalfVector(ndf, smith, DielectricLobes::kReflection, alpha, eta, share);
    const DielectricIntegral entering =
        AverageOverHalfVector(ndf, smith, lobes, alpha, 1.0 / eta, share);
    const DielectricIntegral enteringReflected =
        AverageOverHalfVector(ndf, smith, DielectricLobes::kReflection, alpha, 1.0 / eta, share);
    out.value = inside.value + eta2 * (entering.value - enteringReflected.value);
    out.bound = inside.bound + eta2 * (entering.bound + enteringReflected.bound);
    out.converged = inside.converged && entering.converged && enteringReflected.converged &&
                    out.bound <= tolerance * std::max(1.0, std::abs(out.value));
    out.evaluations = inside.evaluations + entering.evaluations + enteringReflected.evaluations;
    if (out.converged) return out;
    // Not converged: the direct rule as well, keeping the smaller bound.
    DielectricIntegral direct = AverageOverHalfVector(ndf, smith, lobes, alpha, eta, tolerance);
    direct.evaluations += out.evaluations;
    if (direct.bound < out.bound) return direct;
    out.evaluations = direct.evaluations;
    return out;
  }
  return AverageOverHalfVector(ndf, smith, lobes, alpha, eta, tolerance);
}

}  // namespace lutbake
