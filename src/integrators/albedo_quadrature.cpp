#include "lutbake/integrators/albedo_quadrature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "integrators/albedo_kernel.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/gauss_legendre.h"

namespace lutbake {

namespace {

// Gauss nodes per outer panel (phi or mu), per inner panel of the core
// (and Beckmann's) and per panel of GGX's tail. The tail's panels are graded
// toward their singularities and converge ahead of the core's: at level 1
// seven nodes there leave every measured bound as it was with eight
// (albedo_quadrature.h).
struct Level {
  int outer, inner, tail;
};
constexpr Level kLevels[kQuadratureLevels] = {
    {6, 5, 5}, {9, 8, 7}, {13, 12, 12}, {18, 17, 17}, {24, 23, 23}};

// Width of the outer panels in u (phi = pi/2 -+ a sinh(u)): the singularities
// at Im(u) = +-pi/2 then sit at rho = pi/1.2 + sqrt((pi/1.2)^2 + 1) = 5.4
// from a panel's middle.
constexpr double kOuterPanelWidth = 1.2;
// At grazing view the outer scale a = asinh(mu_o / s_o) goes to 0; at
// mu_o = 0 itself the azimuths with cos(phi) < 0 see no light and the rest
// is smooth, so phi in [0, pi/2] is graded with this scale instead.
constexpr double kGrazingLimitScale = 0.25;
// a is capped here (mu_o within 4e-9 of 1, where the integrand hardly
// depends on phi and a = infinity at mu_o = 1).
constexpr double kMaxOuterScale = 10.0;
// Inner panels: graded by this ratio from the horizon, and no longer than
// these (in t or w; Beckmann's t), so that the factors with poles at
// x = +-i (the measure 2x / (1 + x^2)^2) stay far from every panel.
constexpr double kGradingRatio = 2.0;
constexpr double kMaxGgxPanel = 0.5;
// GgxInnerPanels splits only the last two pieces of a tail: with ratio 2 on
// a range no longer than 1 the others are shorter than 1/3.
static_assert(kGradingRatio == 2.0 && kMaxGgxPanel >= 1.0 / 3.0);
constexpr double kMaxBeckmannPanel = 1.0;
// Beckmann's measure 2 t exp(-t^2) dt beyond t = 6.5 has mass below 1e-18:
// the inner range is cut there.
constexpr double kBeckmannCut = 6.5;
// A graded panel at the horizon whose share of E is provably below this
// fraction of the tolerance need not resolve the boundary layer: grading
// starts no finer than that (see FirstPanel).
constexpr double kNegligibleShare = 1e-3;
// At most this many panels per geometric grading (2^60 ~ 1e18 in scale).
constexpr int kMaxGradedPanels = 60;
// The first panel of E_avg's mu rule is at most this long: the logarithmic
// singularity of E at mu = 0 (c mu log(mu), times the weight 2 mu) is then
// integrated by the Gauss rule of that panel alone to ~1e-13 (measured
// against tests/data at level 1: 9.7e-13 for GGX, where 0.1 gave 7.6e-10).
constexpr double kFirstAveragePanel = 0.01;
// Beckmann's Lambda has an essential singularity where the light reaches the
// normal (mu_i = 1, a = mu / (alpha sqrt(1 - mu^2)) infinite): inside the
// domain, at phi = 0. The rule converges there more slowly than
// geometrically, so Beckmann starts from a finer pair of levels.
constexpr int kBeckmannFirstLevel = 1;
// Unreal's Vis_SmithJointApprox (FittedVisibility::kSmithJointApprox) has
// its pole at mu_i ~ -mu_o, next to the horizon at grazing view, and from
// levels 0 and 1 the two values of B could agree by chance: on 68630 points
// (the texel centres of 32^2, 128^2 and 256^2 tables and 20000 random ones,
// a third of each) 12 values of B at mu_o < 0.012 were off by 3.3e-10 to
// 5.1e-10 against bounds of 1.4e-10 to 4.6e-10 (the rule at 1e-30 as
// reference). From levels 1 and 2: none, worst error / bound 0.074.
constexpr int kJointApproxFirstLevel = 1;

// What every evaluation of one texel shares.
struct Setup {
  Ndf ndf;
  SmithForm smith;
  double mu_o, s_o, L_o;
  // A fitted G2 (FittedVisibility) and its parameter; L_o above is then not
  // Smith's but the L with G2 / mu_o <= 1 / (mu_o + L) (the mass bound).
  FittedVisibility fitted = FittedVisibility::kNone;
  double fitParameter = 0.0;
  double d_mu;            // distance of G2/mu_o's nearest singularity from mu_i = 0
  double a;               // outer scale
  double negligibleMass;  // kNegligibleShare x tolerance
};

Setup MakeSetup(const Ndf &ndf, SmithForm smith, double mu_o, double tolerance) {
  Setup s{ndf,
          smith,
          mu_o,
          SafeSqrt((1.0 - mu_o) * (1.0 + mu_o)),
          ndf.MuLambda(mu_o),
          FittedVisibility::kNone,
          0,
          0,
          0,
          kNegligibleShare * tolerance};
  const double L_0 = ndf.MuLambda(0.0);  // alpha / 2 (GGX), alpha / (2 sqrt(pi)) (Beckmann)
  s.d_mu = smith == SmithForm::kCorrelated ? std::min(mu_o * L_0 / (mu_o + s.L_o), ndf.alpha)
                                           : std::min(L_0, ndf.alpha);
  s.a = s.s_o > 0.0 ? std::min(std::asinh(mu_o / s.s_o), kMaxOuterScale) : kMaxOuterScale;
  return s;
}

// The first graded panel at the horizon end: the singularity's distance in
// the variable, but no finer than the panel whose contribution is provably
// at most negligibleMass (`lengthForMass`, from the closed-form bound of the
// mass of the first l of the range). Such a panel may be left unresolved: its
// Gauss sum and its integral both lie in [0, 2 negligibleMass], and the
// bound adds that (IntegrateSplitSumQuadrature).
double FirstPanel(double distance, double lengthForMass) {
  if (!(distance > 0.0)) distance = 0.0;
  return std::max(distance, lengthForMass);
}

// Panels of one level, of one kind (core or tail): their range in x (t or w),
// sc = s_o cos(phi) of their azimuth, and scale = outer weight x width.
// Grown as needed, never shrunk: one set per thread.
struct PanelList {
  std::vector<double> from, width, sc, scale;
  size_t n = 0;
  void Clear() { n = 0; }
  // Room for `more` panels past n.
  void Reserve(size_t more) {
    if (n + more <= from.size()) return;
    const size_t size = 2 * (n + more) + 64;
    from.resize(size);
    width.resize(size);
    sc.resize(size);
    scale.resize(size);
  }
  void Push(double lo, double hi, double sci, double outerWeight) {
    Reserve(1);
    PushReserved(lo, hi, sci, outerWeight);
  }
  // Push after Reserve.
  void PushReserved(double lo, double hi, double sci, double outerWeight) {
    from[n] = lo;
    width[n] = hi - lo;
    sc[n] = sci;
    scale[n] = outerWeight * (hi - lo);
    ++n;
  }
  kernel::Panels View() const { return {from.data(), width.data(), sc.data(), scale.data(), n}; }
};

// What every texel of one column (one mu_o) shares at one level, whatever
// alpha: the outer nodes, cos(phi) and the weight dphi / pi, and the horizon
// at each: sc = s_o cos(phi), T_max (infinite at mu_o = 0 toward the view,
// <= 0 where no light is above the horizon), |dmu_i/dT| at T_max and
// |sc| T_max + mu_o (the numerator of InnerPanels' bound M).
struct ColumnNodes {
  double mu_o = -1.0;
  std::vector<double> cosPhi, weight;
  std::vector<double> sc, T_max, slope, boundNumerator;
};

// Each thread keeps the columns it met last in this many slots a level,
// placed by mu_o: a table's thread works down a column, and E_avg meets the
// same mu nodes again for every roughness of its graded rule.
constexpr size_t kColumnSlots = 256;

struct Scratch {
  PanelList core, tail;
  PanelList graded;  // Beckmann's horizon grading before its panels are cut
  std::vector<ColumnNodes> columns[kQuadratureLevels];
  // kernel::GgxAzimuthSetup's results for one texel and level.
  std::vector<int> kind;
  std::vector<double> first, end, g2, lengthForMass;
  // kernel::GradedCutsTowardLo's ranges and cuts, for the tails.
  std::vector<double> tailLo, tailFirst, cuts;
  std::vector<int> cutCount;
};

Scratch &ThreadScratch() {
  thread_local Scratch scratch;
  return scratch;
}

// dmu_i / dT at T: (2 sc (1 - T^2) - 4 mu_o T) / (1 + T^2)^2.
double HorizonSlope(double sc, double mu_o, double T) {
  const double d = 1.0 + T * T;
  return (2.0 * sc * (1.0 - T * T) - 4.0 * mu_o * T) / (d * d);
}

// The column of the setup's mu_o at `level`: from the thread's slots, or
// computed there.
const ColumnNodes &Column(const Setup &t, int level, Scratch *s) {
  std::vector<ColumnNodes> &slots = s->columns[level];
  if (slots.empty()) slots.resize(kColumnSlots);
  uint64_t bits;
  std::memcpy(&bits, &t.mu_o, sizeof bits);
  // The top 8 bits of a Fibonacci hash: one of the 256 slots.
  static_assert(kColumnSlots == 256);
  ColumnNodes &c = slots[(bits * 0x9e3779b97f4a7c15ull) >> 56];
  if (c.mu_o == t.mu_o) return c;
  c.mu_o = t.mu_o;
  c.cosPhi.clear();
  c.weight.clear();
  // At mu_o = 0 (grazing) phi in [0, pi/2] only.
  const bool grazing = t.mu_o == 0.0;
  const GaussLegendreRule &rule = GaussLegendre(kLevels[level].outer);
  const double scale = grazing ? kGrazingLimitScale : t.a;
  const double U = std::asinh(0.5 * kPi / scale);
  const int panels = std::max(1, static_cast<int>(std::ceil(U / kOuterPanelWidth)));
  const double width = U / panels;
  // side -1: phi < pi/2 (cos(phi) > 0, toward the view); +1: phi > pi/2.
  for (int side = -1; side <= (grazing ? -1 : 1); side += 2)
    for (int p = 0; p < panels; ++p)
      for (int j = 0; j < rule.n; ++j) {
        const double u = width * (p + rule.x[j]);
        // cos(phi) = sin(pi/2 - phi) = -side sin(a sinh(u)), accurate near pi/2.
        const double offset = std::min(scale * std::sinh(u), 0.5 * kPi);
        c.cosPhi.push_back(-side * std::sin(offset));
        // dphi / pi = a cosh(u) du / pi.
        c.weight.push_back(scale * std::cosh(u) * width * rule.w[j] * kInvPi);
      }
  const double mu_o = t.mu_o;
  const size_t n = c.cosPhi.size();
  // Padded to whole vectors of 8 for kernel::GgxAzimuthSetup: T_max = -1
  // there (no light).
  const size_t padded = (n + 7) / 8 * 8;
  c.sc.assign(padded, 0.0);
  c.T_max.assign(padded, -1.0);
  c.slope.assign(padded, 0.0);
  c.boundNumerator.assign(padded, 0.0);
  for (size_t j = 0; j < n; ++j) {
    const double sc = t.s_o * c.cosPhi[j];
    // T_max, the positive root of mu_o T^2 - 2 sc T - mu_o, in the form that
    // does not cancel: (sc + R) / mu_o for sc >= 0, mu_o / (R - sc) otherwise.
    const double R = std::sqrt(sc * sc + mu_o * mu_o);
    const double T_max =
        sc >= 0.0 ? (mu_o > 0.0 ? (sc + R) / mu_o : std::numeric_limits<double>::infinity())
                  : mu_o / (R - sc);
    c.sc[j] = sc;
    c.T_max[j] = T_max;
    c.slope[j] = std::isfinite(T_max) ? std::abs(HorizonSlope(sc, mu_o, T_max)) : 0.0;
    c.boundNumerator[j] = std::abs(sc) * T_max + mu_o;
  }
  return c;
}

// Pushes [from, to] split into equal parts no longer than maxLength, into
// room already reserved.
inline void PushSplit(double from, double to, double maxLength, double sc, double outerWeight,
                      PanelList *list) {
  if (!(to - from > maxLength)) {
    list->PushReserved(from, to, sc, outerWeight);
    return;
  }
  const int parts = static_cast<int>(std::ceil((to - from) / maxLength));
  for (int p = 1; p < parts; ++p) {
    const double at = from + (to - from) * p / parts;
    list->PushReserved(from + (to - from) * (p - 1) / parts, at, sc, outerWeight);
  }
  list->PushReserved(from + (to - from) * (parts - 1) / parts, to, sc, outerWeight);
}

// Pushes the panels of [lo, hi] graded toward hi (towardHi) or lo: lengths
// first, 2 first, 4 first, ... from that end, the last taking what is left
// (joined to the one before when under half its length), each then split
// into equal parts no longer than maxLength. first <= 0: no grading.
void PushGraded(double lo, double hi, double first, bool towardHi, double maxLength, double sc,
                double outerWeight, PanelList *list) {
  const double length = hi - lo;
  double cut[kMaxGradedPanels + 2];
  int cuts = 0;
  cut[cuts++] = 0.0;
  if (first > 0.0) first = std::max(first, length * 0x1p-60);
  if (first > 0.0 && first < length) {
    double size = first;
    while (cuts < kMaxGradedPanels && cut[cuts - 1] + size < length) {
      cut[cuts] = cut[cuts - 1] + size;
      ++cuts;
      size *= kGradingRatio;
    }
    if (cuts > 1 && length - cut[cuts - 1] < 0.5 * (cut[cuts - 1] - cut[cuts - 2])) --cuts;
  }
  cut[cuts++] = length;
  // Each of the cuts - 1 pieces is split into at most its length / maxLength
  // + 1 parts (+ 1 for the rounding of that quotient).
  list->Reserve(static_cast<size_t>(cuts) + static_cast<size_t>(std::ceil(length / maxLength)) + 2);
  double from = lo;
  for (int k = 1; k < cuts; ++k) {
    const double to = k == cuts - 1 ? hi : towardHi ? hi - cut[cuts - 1 - k] : lo + cut[k];
    PushSplit(from, to, maxLength, sc, outerWeight, list);
    from = to;
  }
}

// The inner panels of every azimuth of one texel and level (GGX). Per
// azimuth: T_max from the column, t_max = T_max / alpha, and
//   M = (|sc| T_max + mu_o) / (mu_o + L_o),
// a bound of the E integrand near the horizon in the measure dxi
// ((o.h / cos(theta)) G2 / mu_o <= M). The whole inner integral is at most
// M xi(T_max), xi(T_max) = t_max^2 / (1 + t_max^2) (the NDF's mass below the
// horizon times the bound above; the bound is largest at T_max). An azimuth
// where that is below the negligible mass is left out: the outer weights sum
// to 1, so all of them together leave out at most that much. (Far past pi/2
// at grazing view, where the horizon cuts the NDF to a sliver.)
//
// Where t_max <= 1 the horizon cuts the core: it is graded toward t_max,
// from FirstPanel(d_mu / (alpha |dmu_i/dT|), m / (2 t_max M)) (the mass of
// [t_max - l, t_max] is at most 2 t_max l M, dxi <= 2 t dt).
//
// Otherwise the core is two panels and the tail, w = alpha / T from
// w_min = alpha / T_max, is graded. Two singularities set the grading: G2's,
// at distance d_mu / (dmu_i/dw) beyond w_min (dmu_i/dw = dmu_i/dT T^2 /
// alpha), and 1 + T^2 = 0 at w = +-i alpha, where o.h and mu_i turn over from
// the NDF's core to its horizon: at a distance hypot(w_min, alpha) (>= alpha,
// so taken only where G2's distance is not below alpha). The mass of
// [w_min, w_min + l] is at most M ((w_min + l)^2 - w_min^2) (dxi <= 2 w dw),
// which is m at l = (m / M) / (w_min + sqrt(w_min^2 + m / M)). At mu_o = 0
// the tail reaches w = 0, where mu_i = 2 sc w / (w^2 + alpha^2) has slope
// 2 sc / alpha; with no mass bound (M is infinite) it is graded fully.
//
// The arithmetic of all azimuths at once (kernel::GgxAzimuthSetup, the same
// doubles as one at a time), then the panels one azimuth after the other.
void GgxInnerPanels(const Setup &t, const ColumnNodes &column, Scratch *s) {
  const double alpha = t.ndf.alpha;
  const size_t n = column.cosPhi.size(), padded = column.T_max.size();
  s->kind.resize(padded);
  s->first.resize(padded);
  s->end.resize(padded);
  s->g2.resize(padded);
  s->lengthForMass.resize(padded);
  const kernel::GgxAzimuthConstants constants{alpha, t.mu_o, t.mu_o + t.L_o, t.d_mu,
                                              t.negligibleMass};
  kernel::GgxAzimuthSetup(constants, padded, column.sc.data(), column.T_max.data(),
                          column.slope.data(), column.boundNumerator.data(), s->kind.data(),
                          s->first.data(), s->end.data(), s->g2.data(), s->lengthForMass.data());
  // The core: two panels, or graded toward t_max.
  for (size_t j = 0; j < n; ++j) {
    const double sc = column.sc[j], outerWeight = column.weight[j];
    const int kind = s->kind[j];
    if (kind == kernel::kAzimuthNone) continue;
    if (kind == kernel::kAzimuthCore) {
      PushGraded(0.0, s->end[j], s->first[j], true, kMaxGgxPanel, sc, outerWeight, &s->core);
      continue;
    }
    s->core.Push(0.0, 0.5, sc, outerWeight);
    s->core.Push(0.5, 1.0, sc, outerWeight);
  }
  // The tails, [w_min, 1] (from 0 at mu_o = 0) graded toward w_min: their
  // cuts all at once (kernel::GradedCutsTowardLo, PushGraded's doubles), then
  // their pieces, each split into parts no longer than kMaxGgxPanel.
  s->tailLo.assign(padded, 1.0);  // no tail: [1, 1], no cut
  s->tailFirst.assign(padded, 0.0);
  for (size_t j = 0; j < n; ++j) {
    const int kind = s->kind[j];
    if (kind == kernel::kAzimuthNone || kind == kernel::kAzimuthCore) continue;
    s->tailLo[j] = kind == kernel::kAzimuthTailAll ? 0.0 : s->end[j];
    s->tailFirst[j] =
        kind == kernel::kAzimuthTailHypot
            ? FirstPanel(std::min(s->g2[j], std::hypot(s->end[j], alpha)), s->lengthForMass[j])
            : s->first[j];
  }
  s->cuts.resize(padded * (kMaxGradedPanels - 1));
  s->cutCount.resize(padded);
  kernel::GradedCutsTowardLo(padded, s->tailLo.data(), s->tailFirst.data(), kGradingRatio,
                             kMaxGradedPanels, s->cuts.data(), s->cutCount.data());
  for (size_t j = 0; j < n; ++j) {
    const int kind = s->kind[j];
    if (kind == kernel::kAzimuthNone || kind == kernel::kAzimuthCore) continue;
    const double sc = column.sc[j], outerWeight = column.weight[j], lo = s->tailLo[j];
    const int cuts = s->cutCount[j];
    // Pieces no longer than 1: each splits into at most 2 parts, and at most
    // 2 of them are longer than kMaxGgxPanel.
    s->tail.Reserve(static_cast<size_t>(cuts) + 3);
    const double *cut = &s->cuts[j];  // c_k at cut[(k - 1) padded]
    double from = lo;
    // The pieces before the last two are shorter than 1/3, never split: the
    // piece [c_(k-1), c_k] is first 2^(k-1), and c_cuts = first (2^cuts - 1)
    // < 1 gives first 2^(cuts-2) < 1/3 for cuts >= 2 (ratio 2, length <= 1).
    for (int k = 1; k < cuts; ++k) {
      const double to = lo + cut[static_cast<size_t>(k - 1) * padded];
      s->tail.PushReserved(from, to, sc, outerWeight);
      from = to;
    }
    if (cuts >= 1) {
      const double to = lo + cut[static_cast<size_t>(cuts - 1) * padded];
      PushSplit(from, to, kMaxGgxPanel, sc, outerWeight, &s->tail);
      from = to;
    }
    PushSplit(from, 1.0, kMaxGgxPanel, sc, outerWeight, &s->tail);
  }
}

// The inner panels of azimuth j of the column `h` (Beckmann): as GGX's (M,
// the negligible azimuths), with xi(T_max) = 1 - exp(-t_max^2).
void BeckmannInnerPanels(const Setup &t, const ColumnNodes &h, size_t j, double outerWeight,
                         Scratch *s) {
  const double mu_o = t.mu_o, alpha = t.ndf.alpha;
  const double sc = h.sc[j], T_max = h.T_max[j];
  if (!(T_max > 0.0)) return;  // no light above the horizon
  const bool bounded = std::isfinite(T_max);
  const double M = h.boundNumerator[j] / (mu_o + t.L_o);
  const double slope = h.slope[j];
  const double tMax = T_max / alpha;
  const double xiMax = -std::expm1(-tMax * tMax);
  if (bounded && M * xiMax <= t.negligibleMass) return;
  // Beckmann: t = T / alpha up to min(t_max, the cut), in panels no longer
  // than BeckmannPanel allows where they start (graded toward t_max as GGX's
  // tail is). The factor 1 + T^2 vanishes at t = +-i / alpha, and
  // exp(-t^2) grows as exp(y^2) off the real axis: panels of 0.4 / alpha (at
  // most 1) keep rho near 5 where the mass is, longer ones past t = 3 and
  // 4.5, where exp(-t^2) has left less than 1e-4 and 2e-9 of it.
  const double end = std::min(tMax, kBeckmannCut);
  const double first = tMax < kBeckmannCut ? FirstPanel(t.d_mu / (alpha * slope),
                                                        t.negligibleMass / (2.0 * tMax * M))
                                           : 0.0;
  PanelList &graded = s->graded;
  graded.Clear();
  PushGraded(0.0, end, first, true, kBeckmannCut, sc, outerWeight, &graded);
  const double step = std::min(kMaxBeckmannPanel, 0.4 / alpha);
  for (size_t p = 0; p < graded.n; ++p) {
    const double from = graded.from[p], to = from + graded.width[p];
    const double local = step * (from < 3.0 ? 1.0 : from < 4.5 ? 2.0 : 4.0);
    const int parts = std::max(1, static_cast<int>(std::ceil((to - from) / local)));
    for (int k = 0; k < parts; ++k)
      s->core.Push(from + (to - from) * k / parts,
                   k + 1 == parts ? to : from + (to - from) * (k + 1) / parts, sc, outerWeight);
  }
}

// Beckmann's integrand one node at a time (erfc in Lambda has no vector
// form here): the measure 2 t exp(-t^2) dt, T = alpha t.
// With f82, sums[2] gets the F82 term C (weight (o.h) (1 - o.h)^6) besides.
void SumBeckmann(const Setup &t, const GaussLegendreRule &rule, const PanelList &panels, bool f82,
                 double sums[3]) {
  double A = 0.0, B = 0.0, C = 0.0;
  for (size_t p = 0; p < panels.n; ++p)
    for (int i = 0; i < rule.n; ++i) {
      const double x = panels.from[p] + panels.width[p] * rule.x[i], sc = panels.sc[p];
      const double T = t.ndf.alpha * x;
      const double q = sc * T + t.mu_o;
      const double inv = 1.0 / (1.0 + T * T);
      const double mu_i = (2.0 * T * sc + t.mu_o * (1.0 - T * T)) * inv;
      if (!(mu_i > 0.0 && q > 0.0)) continue;
      const double f = panels.scale[p] * rule.w[i] * 2.0 * x * std::exp(-x * x) * q *
                       SmithG2OverMuO(t.smith, t.mu_o, mu_i, t.L_o, t.ndf.MuLambda(mu_i));
      const double oh = q * std::sqrt(inv);
      const SchlickWeights fc = Schlick(oh);
      A += f * fc.complement;
      B += f * fc.fc;
      if (f82) C += f * (oh * (fc.fc * (1.0 - oh)));
    }
  sums[0] = A;
  sums[1] = B;
  sums[2] = C;
}

struct Sums {
  double A = 0, B = 0;
  double C = 0;  // the F82 term, with f82 only
  uint64_t evaluations = 0;
};

// The integrals at one level; with f82 also C.
Sums EvaluateLevel(const Setup &t, int level, bool f82 = false) {
  Scratch &s = ThreadScratch();
  s.core.Clear();
  s.tail.Clear();
  const ColumnNodes &column = Column(t, level, &s);
  if (t.ndf.kind == NdfKind::kGgx) {
    GgxInnerPanels(t, column, &s);
  } else {
    for (size_t j = 0; j < column.cosPhi.size(); ++j)
      BeckmannInnerPanels(t, column, j, column.weight[j], &s);
  }
  const GaussLegendreRule &inner = GaussLegendre(kLevels[level].inner);
  double core[3] = {0.0, 0.0, 0.0}, tail[3] = {0.0, 0.0, 0.0};
  if (t.ndf.kind == NdfKind::kGgx) {
    const kernel::GgxSplitSumConstants constants{t.ndf.alpha, t.mu_o,   t.L_o,
                                                 t.smith,     t.fitted, t.fitParameter};
    const auto sum = f82 ? kernel::SumGgxSplitSumF82 : kernel::SumGgxSplitSum;
    sum(constants, false, inner.n, inner.x, inner.w, s.core.View(), core);
    const GaussLegendreRule &tailRule = GaussLegendre(kLevels[level].tail);
    sum(constants, true, tailRule.n, tailRule.x, tailRule.w, s.tail.View(), tail);
  } else {
    SumBeckmann(t, inner, s.core, f82, core);
  }
  Sums sums;
  sums.A = core[0] + tail[0];
  sums.B = core[1] + tail[1];
  sums.C = core[2] + tail[2];
  sums.evaluations = s.core.n * static_cast<uint64_t>(inner.n) +
                     s.tail.n * static_cast<uint64_t>(kLevels[level].tail);
  return sums;
}

int FirstLevel(const Ndf &ndf, FittedVisibility fitted) {
  if (ndf.kind == NdfKind::kBeckmann) return kBeckmannFirstLevel;
  return fitted == FittedVisibility::kSmithJointApprox ? kJointApproxFirstLevel : 0;
}

}  // namespace

namespace {

SplitSumQuadrature SplitSumOn(const Setup &setup, double tolerance, bool split);

}  // namespace

SplitSumQuadrature IntegrateSplitSumQuadrature(const Ndf &ndf, SmithForm smith, double mu_o,
                                               double tolerance, bool split) {
  return SplitSumOn(MakeSetup(ndf, smith, mu_o, tolerance), tolerance, split);
}

SplitSumQuadrature IntegrateFittedSplitSumQuadrature(double alpha, FittedVisibility visibility,
                                                     double mu_o, double tolerance) {
  const Ndf ndf{NdfKind::kGgx, alpha};
  Setup setup = MakeSetup(ndf, SmithForm::kSeparable, mu_o, tolerance);
  setup.fitted = visibility;
  if (visibility == FittedVisibility::kSchlickGgx) {
    // G2 / mu_o <= G1(mu_o) / mu_o = 1 / (mu_o + k (1 - mu_o)); pole at
    // mu_i = -k / (1 - k).
    const double k = alpha / 2.0;
    setup.fitParameter = k;
    setup.L_o = k * (1.0 - mu_o);
    setup.d_mu = std::min(k / (1.0 - k), alpha);
  } else if (visibility == FittedVisibility::kSmithJointApprox) {
    // G2 / mu_o = 2 mu_i / (2 mu_o mu_i (1 - a) + a (mu_i + mu_o)) <=
    // min(1 / mu_o, 2 / (a + 2 mu_o (1 - a))) = 1 / (mu_o + L),
    // L = max(0, a (1/2 - mu_o)); pole at mu_i = -a mu_o / (2 mu_o (1 - a) + a).
    const double a = alpha;
    setup.fitParameter = a;
    setup.L_o = std::max(0.0, a * (0.5 - mu_o));
    setup.d_mu = std::min(a * mu_o / (2.0 * mu_o * (1.0 - a) + a), alpha);
  }
  return SplitSumOn(setup, tolerance, true);
}

namespace {

SplitSumQuadrature SplitSumOn(const Setup &setup, double tolerance, bool split) {
  SplitSumQuadrature result;
  const int first = FirstLevel(setup.ndf, setup.fitted);
  Sums previous = EvaluateLevel(setup, first);
  result.evaluations = previous.evaluations;
  for (int k = first + 1; k < kQuadratureLevels; ++k) {
    const Sums current = EvaluateLevel(setup, k);
    result.evaluations += current.evaluations;
    result.A = current.A;
    result.B = current.B;
    // The floor, and what the negligible parts may hold: the first horizon
    // panels (their sums and integrals both in [0, 2 m]) and the azimuths
    // left out (at most m).
    const double floor = kQuadratureBoundFloor + 3.0 * setup.negligibleMass;
    result.boundA = std::abs(current.A - previous.A) + floor;
    result.boundB = std::abs(current.B - previous.B) + floor;
    result.boundE = std::abs((current.A + current.B) - (previous.A + previous.B)) + floor;
    result.level = k;
    result.converged =
        split ? std::max(result.boundA, result.boundB) <= tolerance : result.boundE <= tolerance;
    if (result.converged) break;
    previous = current;
  }
  // The sums of ~3000 positive terms carry a rounding of ~1e-14: where a
  // mirror-like lobe makes E = 1 - O(alpha^2), A + B may come out a few ulps
  // above 1. The truth lies in {A, B >= 0, A + B <= 1}; bringing the values
  // back into it (A, B scaled by 1 / (A + B)) moves them by at most that
  // excess, far inside the 1e-10 floor of the bounds.
  result.A = std::max(result.A, 0.0);
  result.B = std::max(result.B, 0.0);
  if (const double E = result.A + result.B; E > 1.0) {
    result.A /= E;
    result.B /= E;
  }
  return result;
}

}  // namespace

F82Quadrature IntegrateF82Quadrature(const Ndf &ndf, SmithForm smith, double mu_o,
                                     double tolerance) {
  const Setup setup = MakeSetup(ndf, smith, mu_o, tolerance);
  F82Quadrature result;
  const int first = FirstLevel(setup.ndf, setup.fitted);
  Sums previous = EvaluateLevel(setup, first, true);
  result.evaluations = previous.evaluations;
  for (int k = first + 1; k < kQuadratureLevels; ++k) {
    const Sums current = EvaluateLevel(setup, k, true);
    result.evaluations += current.evaluations;
    result.C = current.C;
    // The same floor as E's: C's integrand is E's times (o.h) (1 - o.h)^6
    // <= 6^6 / 7^7 < 1, so the negligible parts of E bound those of C.
    result.bound =
        std::abs(current.C - previous.C) + kQuadratureBoundFloor + 3.0 * setup.negligibleMass;
    result.level = k;
    result.converged = result.bound <= tolerance;
    if (result.converged) break;
    previous = current;
  }
  // C >= 0 in exact arithmetic; a rounding below 0 is brought back (it is
  // far inside the floor).
  result.C = std::max(result.C, 0.0);
  return result;
}

namespace {

// E_avg's value at one level: Gauss panels in mu graded from 0.
Sums AverageAtLevel(const Ndf &ndf, SmithForm smith, double tolerance, int k,
                    const PanelList &panels) {
  const GaussLegendreRule &rule = GaussLegendre(kLevels[k].outer);
  Sums sums;
  for (size_t p = 0; p < panels.n; ++p)
    for (int i = 0; i < rule.n; ++i) {
      const double mu = panels.from[p] + panels.width[p] * rule.x[i];
      // E at mu enters with the weight 2 mu (the rule's weights sum to 1):
      // its negligible parts may be 1 / (2 mu) times larger, and add up to
      // at most 3 kNegligibleShare tolerance over the whole rule.
      const Sums e = EvaluateLevel(MakeSetup(ndf, smith, mu, tolerance / (2.0 * mu)), k);
      sums.A += panels.width[p] * rule.w[i] * 2.0 * mu * (e.A + e.B);
      sums.evaluations += e.evaluations;
    }
  return sums;
}

}  // namespace

AverageQuadrature IntegrateAverageQuadrature(const Ndf &ndf, SmithForm smith, double tolerance) {
  // E(mu) varies at grazing over a width alpha (mu Lambda(mu) has branch
  // points at mu = +-i alpha / sqrt(1 - alpha^2)), and correlated E(mu) =
  // 1 + c mu log(mu) + ... (c ~ 0.7 at alpha = 0.7): the panels are graded
  // toward 0 from min(alpha, kFirstAveragePanel).
  PanelList panels;
  PushGraded(0.0, 1.0, std::min(ndf.alpha, kFirstAveragePanel), false, 0.5, 0.0, 1.0, &panels);
  AverageQuadrature result;
  const int first = FirstLevel(ndf, FittedVisibility::kNone);
  Sums previous = AverageAtLevel(ndf, smith, tolerance, first, panels);
  result.evaluations = previous.evaluations;
  for (int k = first + 1; k < kQuadratureLevels; ++k) {
    const Sums current = AverageAtLevel(ndf, smith, tolerance, k, panels);
    result.evaluations += current.evaluations;
    result.value = current.A;
    // The floor, the first mu panel (at most m) and the negligible parts of
    // every E (3 m in all, see AverageAtLevel), m = kNegligibleShare tolerance.
    result.bound = std::abs(current.A - previous.A) + kQuadratureBoundFloor +
                   4.0 * kNegligibleShare * tolerance;
    result.level = k;
    result.converged = result.bound <= tolerance;
    if (result.converged) break;
    previous = current;
  }
  result.value = std::clamp(result.value, 0.0, 1.0);  // as for E above
  return result;
}

}  // namespace lutbake
