// The sheen albedo by a Gauss-Legendre product rule over the light direction.
//
// The integral. With o = (s_o, 0, mu_o), the light i at (mu_i, phi) and
// t = pi - phi, D depends on phi only through
//   T = (s_o - s_i)^2 + 4 s_o s_i sin^2(t / 2)   (= |o + i|^2 sin^2(theta_h)),
// and W = V mu_i only on mu_i, so
//   E = 2 int_0^1 dmu_i W(mu_i) int_0^pi dt D,
//   D = K dhat,  dhat = exp(-p log1p(m^2 / T)),  K = (2 + q) / (2 pi),
// with m = mu_o + mu_i, q = 1 / alpha, p = q / 2. Writing W = W_max what,
//   E = S J,  S = 2 K W_max,  J = int dmu_i what(mu_i) int_0^pi dhat dt,
// what and dhat in [0, 1]; S is applied last (in logarithms where S alone
// would overflow: K = 1.6e23 at alpha = 1e-24, W_max = 1 / (4 mu_o (1 +
// Lambda(mu_o))) = 8e291 at mu_o = 1e-300). W_max = 1/4 for ashikhmin.
//
// Two monotonicities give closed-form upper bounds: what increases with mu_i
// (Lambda decreases; mu_i / (mu_i + mu_o (1 - mu_i)) has derivative
// mu_o / (...)^2), and dhat is largest at t = pi (phi = 0, T = (s_o + s_i)^2)
// where it decreases with mu_i; so on mu_i in [a, b]
//   int_a^b what int dhat <= pi (b - a) what(b) dhatmax(a),
//   dhatmax(a) = exp(-p log1p((mu_o + a)^2 / (s_o + s_a)^2)).
// They give U, an upper bound of E, and the end of the lobe mu_end, beyond
// which the rest of J is below the negligible mass (pi (1 - mu) dhatmax(mu)).
// When U itself is below 1e-3 tolerance the value is 0 with bound U (small
// alpha, mu_o >> sqrt(alpha): E is exponentially small).
//
// The panels in mu_i (on [0, mu_end]), from the integrand's features:
//  - mu_i = 0. Charlie: Lambda(mu_i) = exp(a / (1 + b mu_i^c) + ...) has a
//    branch point of order c ~ 0.2 there, which makes W vary by orders of
//    magnitude over every dyadic scale of mu_i down to ~1e-10. On [0, h] the
//    variable is y = mu_i^c (mu_i = y^(1/c), dmu_i = y^(1/c - 1) dy / c):
//    Lambda is analytic in y, the Jacobian is flat at y = 0, and uniform
//    panels of at most 0.2 in y (l changes by at most a b 0.2 ~ 16 over one,
//    less where the mass is) reach mu_i = 0 itself. (A power map
//    mu_i = h u^k with one Gauss panel was tried first: it squeezes the
//    whole variation of W into u near 1, and converged 1000x slower.)
//    Ashikhmin: W has a pole at mu_i = -mu_o / (1 - mu_o), a plain panel.
//    Both: D has features of scale m ~ mu_o (the light's grazing band near
//    phi = pi, and h = n below). h = min(mu_o / 2, 2 sqrt(alpha) / 4, 1/8),
//    then panels grow by 2. Where that is finer than needed (tiny mu_o), h
//    is raised while the panel's mass bound pi h what(h) dhatmax(0) stays
//    negligible; such a first panel is not resolved, and its mass bound is
//    added to the bound.
//  - mu_i = mu_o: h = n at phi = pi, where D ~ |distance|^q (a branch point
//    unless q is even). Panels graded by 2 from both sides, first length
//    sigma min(1, (1e5 m_neg)^(1 / (q + 2))), sigma = min(mu_o, 2 s_o) / 2
//    the scale of the cone (where |s_o - s_i| ~ m), m_neg the negligible mass.
//  - mu_i = 0.5 (Charlie): Lambda is C1 but not C2 there; a panel break.
//  - mu_i = 1: s_i = sqrt(1 - mu_i^2) has a square-root branch point and
//    Charlie's Lambda a (1 - mu_i)^c one. Charlie: y = (1 - mu_i)^c panels as
//    at 0 (s_i ~ y^(1/(2c)) under the y^(1/c - 1) Jacobian); ashikhmin: the
//    last panel [1 - h, 1] mapped by mu_i = 1 - h u^2 (s_i analytic in u).
//    h = min(1/8, 2 sqrt(alpha), (1 - mu_o) / 2) (ashikhmin: a quarter of it),
//    then panels grow by 2.
//  - Nowhere longer than min(1/4, 2 sqrt(alpha)): in m, D is a Gaussian of
//    standard deviation sqrt(alpha T) <= 2 sqrt(alpha).

// The panels in t = pi - phi, per mu_i node, graded toward t = 0 (phi = pi):
// as a function of phi, dhat is analytic except at T = 0 (if q is not even)
// and T + m^2 = 0, at imaginary distances y0 = 2 asinh(|s_o - s_i| / (2 r))
// and y1 = 2 asinh(sqrt((s_o - s_i)^2 + m^2) / (2 r)) from t = 0, r =
// sqrt(s_o s_i). The first panel is pi 2^-J <= min(y0, y1), raised while its
// mass bound (length x dhat at its far end, dhat increasing in t) is below
// 1e5 negligible masses (it is still integrated: dhat ~ t^(2p) there, and
// the level difference measures it), then dyadic panels up to pi 2^-Jm and uniform ones of that
// length; pi 2^-Jm <= 2.5 sqrt(T0 / (B max(z, 1))), the width of dhat's
// peak at phi = 0 (T0 = (s_o + s_i)^2, B = 2 s_o s_i, z = p m^2 / T0). Being
// dyadic, the node sets (and their sin^2(t / 2)) are computed once per
// (J, Jm, level) and kept; the sums over them are the kernel's
// (sheen_kernel.h: SIMD, 5 to 8x the scalar loop).
//
// The bound. Level k uses n(k) Gauss nodes per panel in mu_i and in t:
// 5, 7, 10, 14, 19, 25. The value is level k's and the bound
//   sum over mu_i panels of |V_k - V_{k-1}| + 1e-12 max(1, |V_k|)
//   + S (the negligible masses),
// levels added until the bound is at most tolerance max(1, |V_k|).
#include "lutbake/integrators/sheen_quadrature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "integrators/sheen_kernel.h"
#include "lutbake/core/math.h"
#include "lutbake/integrators/gauss_kronrod.h"
#include "lutbake/integrators/gauss_legendre.h"

namespace lutbake {

namespace {

constexpr int kLevels = 6;
constexpr int kNodes[kLevels] = {5, 7, 10, 14, 19, 25};
constexpr double kNegligibleShare = 1e-3;
constexpr double kBoundFloor = 1e-12;
constexpr double kMaxMuPanel = 0.25;
constexpr int kMaxDyadic = 50;
// The first panels at h = n (in mu_i and in t) are raised while their mass
// bound is below this many negligible masses: unlike the negligible parts,
// they are still integrated, and the level difference measures their error
// (dhat ~ distance^q there, a mild singularity). Measured over 576 points
// against the adaptive rule (worst real error / bound, mean evaluations at
// tolerance 1e-8): 1e3: 0.16, 10500; 1e5: 0.16, 9100; 1e7: 0.16, 7700 (and
// 3.3 with the bound from the totals' difference instead of the panels').
constexpr double kConeShare = 1e5;

void CheckArguments(double alpha, double mu_o, double tolerance) {
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw std::invalid_argument("sheen albedo: alpha must lie in [0, 1]");
  if (!(mu_o >= 0.0 && mu_o <= 1.0))
    throw std::invalid_argument("sheen albedo: mu_o must lie in [0, 1]");
  if (!(tolerance > 0.0)) throw std::invalid_argument("sheen albedo: tolerance must be positive");
}

// Throws where E is infinite (see the header).
void CheckFinite(SheenVisibility visibility, double alpha, double mu_o) {
  if (mu_o > 0.0) return;
  if (UsesCharlieLambda(visibility))
    throw std::domain_error(
        "sheen albedo: E is infinite at mu_o = 0 with the Charlie visibility (its 1 / (4 mu_o "
        "mu_i) keeps a factor 1 / mu_o that Lambda(mu_o), finite at 0, does not cancel)");
  if (alpha == 0.0)
    throw std::domain_error(
        "sheen albedo: E is infinite at mu_o = 0 and alpha = 0 with the Ashikhmin visibility (E "
        "grows as alpha^(-1/2) at grazing view)");
}

// S J, through logarithms where S alone overflows; domain_error if the value
// itself does.
double Scaled(double J, double logS) {
  if (J == 0.0) return 0.0;
  const double S = std::exp(logS);
  double value = std::isfinite(S) ? S * J : std::exp(logS + std::log(J));
  if (!std::isfinite(value))
    throw std::domain_error(
        "sheen albedo: the value exceeds the range of double (mu_o too small for this alpha)");
  return value;
}

// Everything one E evaluation shares.
struct Problem {
  SheenVisibility visibility;
  double alpha = 1.0, mu_o = 0.0, s_o = 1.0;
  double p = 0.5;          // q / 2 = 1 / (2 alpha)
  bool evenPower = false;  // p an integer: dhat analytic at h = n
  double onePlusLambda_o = 1.0;
  double c = 0.2;     // Lambda's exponent
  double logS = 0.0;  // log(2 K W_max)
  double muEnd = 1.0;
  double negligible = 0.0;  // in units of J

  double What(double mu_i) const {
    if (UsesCharlieLambda(visibility))
      return onePlusLambda_o / (onePlusLambda_o + SheenLightLambda(visibility, mu_i, alpha));
    const double denom = mu_i + mu_o * (1.0 - mu_i);
    return denom > 0.0 ? mu_i / denom : 1.0;  // mu_o = mu_i = 0: the limit 1 along mu_i > 0
  }
  double DhatPower(double x) const {  // (1 + x)^(-p)
    if (p == 0.5) return 1.0 / std::sqrt(1.0 + x);
    if (p == 1.0) return 1.0 / (1.0 + x);
    if (p == 2.0) return 1.0 / Sqr(1.0 + x);
    return std::exp(-p * std::log1p(x));
  }
  double DhatMax(double mu) const {
    const double s = SafeSqrt((1.0 - mu) * (1.0 + mu));
    const double sum = s_o + s, m = mu_o + mu;
    if (!(sum > 0.0)) return m > 0.0 ? 0.0 : 1.0;
    return DhatPower(m * m / (sum * sum));
  }
};

Problem MakeProblem(SheenVisibility visibility, double alpha, double mu_o) {
  Problem t;
  t.visibility = visibility;
  t.alpha = alpha;
  t.mu_o = mu_o;
  t.s_o = SafeSqrt((1.0 - mu_o) * (1.0 + mu_o));
  t.p = 0.5 / alpha;
  t.evenPower = t.p == std::floor(t.p) && t.p < 1e15;
  t.c = CharlieLambdaExponent(alpha);
  const double logTwoK = std::log(2.0 * CharlieNormalization(alpha));
  if (UsesCharlieLambda(visibility)) {
    t.onePlusLambda_o = 1.0 + CharlieLambda(mu_o, alpha);
    t.logS = logTwoK - std::log(4.0 * mu_o) - std::log(t.onePlusLambda_o);
  } else {
    t.logS = logTwoK - std::log(4.0);
  }
  return t;
}

// Upper bound of J over mu_i in [lo, hi] from cells (see the top).
double MassBound(const Problem &t, double lo, double hi) {
  if (!(hi > lo)) return 0.0;
  constexpr int kUniform = 16, kGeometric = 40;
  const double width = (hi - lo) / kUniform;
  double sum = 0.0;
  for (int k = 1; k < kUniform; ++k) {
    const double a = lo + width * k, b = k + 1 == kUniform ? hi : lo + width * (k + 1);
    sum += (b - a) * t.What(b) * t.DhatMax(a);
  }
  // The first cell, geometrically toward lo.
  double b = lo + width;
  for (int k = 0; k < kGeometric; ++k) {
    const double a = lo + 0.5 * (b - lo);
    sum += (b - a) * t.What(b) * t.DhatMax(a);
    b = a;
  }
  sum += (b - lo) * t.What(b) * t.DhatMax(lo);
  return kPi * sum * (1.0 + 1e-12);
}

// The smallest mu with pi (1 - mu) dhatmax(mu) <= mass (what <= 1), by
// bisection (the left side decreases in mu).
double LobeEnd(const Problem &t, double mass) {
  const auto tail = [&](double mu) { return kPi * (1.0 - mu) * t.DhatMax(mu); };
  if (tail(0.0) <= mass) return 0.0;
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 80 && hi - lo > 1e-3 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (tail(mid) <= mass ? hi : lo) = mid;
  }
  return hi;
}

// A panel in mu_i: mu = a + (b - a) x (map 0), a + (b - a) u^k (map 1, toward
// a) or b - (b - a) u^k (map 2, toward b).
struct MuPanel {
  double a, b;
  int map;
  double k;
};

// Panels of [a, b] graded by 2 from a (first length hl > 0) and from b
// (hr > 0), none longer than maxLength.
void PushGraded(double a, double b, double hl, double hr, double maxLength,
                std::vector<MuPanel> *out) {
  if (!(b > a)) return;
  std::vector<double> left{a}, right{b};
  const double mid = 0.5 * (a + b);
  if (hl > 0.0)
    for (double size = hl; left.back() + size < mid && left.size() < 200; size *= 2.0)
      left.push_back(left.back() + size);
  if (hr > 0.0)
    for (double size = hr; right.back() - size > mid && right.size() < 200; size *= 2.0)
      right.push_back(right.back() - size);
  std::vector<double> cuts = left;
  // The gap between the two gradings, in parts no longer than the last ones.
  const double from = left.back(), to = right.back();
  const double lastLeft = left.size() > 1 ? left.back() - left[left.size() - 2] : to - from;
  const double lastRight = right.size() > 1 ? right[right.size() - 2] - right.back() : to - from;
  const double gapPart = std::min({maxLength, std::max(lastLeft, lastRight), to - from});
  if (to > from) {
    const int parts = std::max(1, static_cast<int>(std::ceil((to - from) / gapPart - 1e-9)));
    for (int k = 1; k < parts; ++k) cuts.push_back(from + (to - from) * k / parts);
  }
  for (size_t k = right.size(); k-- > 0;) cuts.push_back(right[k]);
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    if (!(hi > lo)) continue;
    const int parts = std::max(1, static_cast<int>(std::ceil((hi - lo) / maxLength - 1e-9)));
    for (int j = 0; j < parts; ++j)
      out->push_back({lo + (hi - lo) * j / parts,
                      j + 1 == parts ? hi : lo + (hi - lo) * (j + 1) / parts, 0, 1.0});
  }
}

// Charlie's Lambda at mu_i = 0 (and 1): with y = |mu_i - end|^c, Lambda is
// analytic in y (a / (1 + b y) + ...), and the x^c branch point, which makes
// W vary by orders of magnitude over every dyadic scale of mu_i, becomes the
// Jacobian (1/c) y^(1/c - 1) dy, smooth and flat at y = 0. Uniform panels in
// y no longer than kMaxYPanel cover [end, end +- h] to the end itself.
// Measured over 576 points (tests/data/sheen and table centres, both
// visibilities) against the adaptive rule: 0.1 and 0.2 both hold every bound
// (worst real error / bound 0.37 and 0.16 with the per-panel bound), 0.34
// comes within 0.95 of one.
constexpr double kMaxYPanel = 0.2;
void PushPowerPanels(double end, double other, double c, std::vector<MuPanel> *out) {
  const double Y = std::pow(std::abs(other - end), c);
  const int parts = std::max(1, static_cast<int>(std::ceil(Y / kMaxYPanel)));
  for (int k = 0; k < parts; ++k) {
    // map 3: mu = end + sign (y)^(1/c), y in [a, b]; k holds the sign.
    out->push_back(
        {Y * k / parts, k + 1 == parts ? Y : Y * (k + 1) / parts, 3, other > end ? 1.0 : -1.0});
  }
}

struct Layout {
  std::vector<MuPanel> panels;
  double neglected = 0.0;  // J-mass bound of the unresolved first panel
};

Layout MuLayout(const Problem &t) {
  Layout layout;
  const double alpha = t.alpha, mu_o = t.mu_o, end = t.muEnd;
  const bool charlie = UsesCharlieLambda(t.visibility);
  const double lobe = 2.0 * std::sqrt(alpha);
  const double maxLength = std::min(kMaxMuPanel, lobe);
  // The first panel at mu_i = 0.
  double h0 = std::min({0.125, 0.25 * lobe, 0.5 * end});
  if (mu_o > 0.0) h0 = std::min(h0, 0.5 * mu_o);

  // Raised while its mass bound stays negligible.
  const double dmax0 = t.DhatMax(0.0);
  const auto mass0 = [&](double h) { return kPi * h * t.What(h) * dmax0; };
  bool raised = false;
  while (2.0 * h0 <= 0.5 * end && mass0(2.0 * h0) <= t.negligible) {
    h0 *= 2.0;
    raised = true;
  }
  if (raised || mass0(h0) <= t.negligible) {
    raised = true;
    layout.neglected += mass0(h0);
  }
  if (charlie)
    PushPowerPanels(0.0, h0, t.c, &layout.panels);
  else
    layout.panels.push_back({0.0, h0, 1, mu_o > 0.0 ? 1.0 : 2.0});
  // Break points after h0.
  std::vector<double> points{h0};
  const bool cone = mu_o > 1.5 * h0 && mu_o < end;
  if (cone) points.push_back(mu_o);
  if (charlie && 0.5 > h0 && 0.5 < end && std::abs(0.5 - mu_o) > 1e-12) points.push_back(0.5);
  std::sort(points.begin(), points.end());
  const bool toOne = end >= 1.0;
  double h1 = 0.0;
  if (toOne) {
    h1 = std::min(0.125, lobe);
    if (cone) h1 = std::min(h1, 0.5 * (1.0 - mu_o));
    h1 = std::min(h1, 0.5 * (1.0 - points.back()));
    if (!charlie) h1 *= 0.25;
  }
  const double last = toOne ? 1.0 - h1 : end;
  points.push_back(last);
  // The cone's first panel.
  double hc = 0.0;
  if (cone) {
    const double sigma = 0.5 * std::min(mu_o, 2.0 * t.s_o);
    hc = t.evenPower ? sigma
                     : sigma * std::min(1.0, std::pow(std::max(kConeShare * t.negligible, 1e-300),
                                                      1.0 / (2.0 * t.p + 2.0)));
  }
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const double a = points[k], b = points[k + 1];
    double hl = 0.0, hr = 0.0;
    if (k == 0) hl = h0;  // continue the grading from mu_i = 0
    if (cone && a == mu_o) hl = hc;
    if (cone && b == mu_o) hr = hc;
    if (toOne && b == last) hr = h1;
    PushGraded(a, b, hl, hr, maxLength, &layout.panels);
  }
  if (toOne) {
    if (charlie)
      PushPowerPanels(1.0, 1.0 - h1, t.c, &layout.panels);
    else
      layout.panels.push_back({1.0 - h1, 1.0, 2, 2.0});
  }
  (void)raised;
  return layout;
}

// pi 2^-j, its logarithm and sin^2(pi 2^-j / 2), j = 0 .. kMaxDyadic.
struct Dyadic {
  double length[kMaxDyadic + 1], logLength[kMaxDyadic + 1], halfSin2[kMaxDyadic + 1];
};
const Dyadic &Dyadics() {
  static const Dyadic table = [] {
    Dyadic d;
    for (int j = 0; j <= kMaxDyadic; ++j) {
      d.length[j] = std::ldexp(kPi, -j);
      d.logLength[j] = std::log(d.length[j]);
      d.halfSin2[j] = Sqr(std::sin(0.5 * d.length[j]));
    }
    return d;
  }();
  return table;
}

// Dyadic node sets in t = pi - phi: edges 0, pi 2^-J, ..., pi 2^-Jm, then
// steps of pi 2^-Jm up to pi. Entries: sin^2(t / 2) and the weight dt.
struct PhiNodes {
  std::vector<double> c2, w;
  size_t nodes = 0;  // before the padding
};

const PhiNodes &PhiSet(int level, int J, int Jm) {
  thread_local std::unordered_map<int, PhiNodes> cache;
  const int key = (level * 64 + J) * 64 + Jm;
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  PhiNodes &set = cache[key];
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  std::vector<double> edges{0.0};
  for (int j = J; j > Jm; --j) edges.push_back(std::ldexp(kPi, -j));
  const double step = std::ldexp(kPi, -Jm);
  const int steps = 1 << Jm;
  for (int s = 1; s <= steps; ++s) {
    const double e = step * s;
    if (e > edges.back()) edges.push_back(s == steps ? kPi : e);
  }
  for (size_t k = 0; k + 1 < edges.size(); ++k) {
    const double lo = edges[k], width = edges[k + 1] - lo;
    for (int j = 0; j < rule.n; ++j) {
      const double half = std::sin(0.5 * (lo + width * rule.x[j]));
      set.c2.push_back(half * half);
      set.w.push_back(width * rule.w[j]);
    }
  }
  set.nodes = set.c2.size();
  // Padded for the kernel: weight 0 at a harmless T.
  while (set.c2.size() % kernel::kAzimuthPadding != 0) {
    set.c2.push_back(1.0);
    set.w.push_back(0.0);
  }
  return set;
}

struct LevelSums {
  double J = 0.0;
  std::vector<double> panels;  // each mu_i panel's share of J
  double neglected = 0.0;      // J-mass bound of the unresolved first t panels
  uint64_t evaluations = 0;
};

// int_0^pi dhat dt at one mu_i node.
double PhiIntegral(const Problem &t, int level, double mu_i, double s_i, double negligiblePhi,
                   double logNegligiblePhi, double *neglected, uint64_t *evaluations) {
  const double s_o = t.s_o, m = t.mu_o + mu_i, m2 = m * m;
  const double sum = s_o + s_i;
  const double ds = sum > 0.0 ? (mu_i - t.mu_o) * (mu_i + t.mu_o) / sum : 0.0;
  const double ds2 = ds * ds, B4 = 4.0 * s_o * s_i;
  if (!(B4 > 0.0)) {
    // D does not depend on phi (view or light at the normal).
    *evaluations += 1;
    if (!(ds2 > 0.0)) return m > 0.0 ? 0.0 : kPi;
    return kPi * t.DhatPower(m2 / ds2);
  }
  // y0 and y1 from below (their only use is to choose the first panel, so
  // smaller is safe): asinh(z) >= 2 z / (2 + z) for z >= 0 (equal slope at
  // 0, below 2 everywhere while asinh passes 2 at z = 3.63), 4x cheaper.
  const double r2 = 2.0 * std::sqrt(s_o * s_i);
  const auto twoAsinhBelow = [](double z) { return 4.0 * z / (2.0 + z); };
  double y = twoAsinhBelow(std::sqrt(ds2 + m2) / r2);
  if (!t.evenPower) y = std::min(y, twoAsinhBelow(std::abs(ds) / r2));
  // The peak at phi = 0.
  const double T0 = sum * sum, B = 0.5 * B4;
  const double z = t.p * m2 / T0;
  const double width = 2.5 * std::sqrt(T0 / (B * std::max(z, 1.0)));
  const Dyadic &dyadic = Dyadics();
  int Jm = 0;
  while (Jm < 6 && dyadic.length[Jm] > width) ++Jm;
  int J = Jm;
  while (J < kMaxDyadic && dyadic.length[J] > y) ++J;
  // Raise the first panel while its whole mass, length x dhat at its far
  // end, is small: it is still integrated by the rule (dhat ~ |t|^(2p)
  // there, a mild singularity whose error the two levels measure), so this
  // costs accuracy only in proportion. dhat = exp(-p log1p(x)) >= exp(-p x),
  // so where p x < log(length / negligiblePhi) the mass is above it and no
  // logarithm is needed to say so.
  while (J > Jm) {
    const double T = ds2 + B4 * dyadic.halfSin2[J - 1];
    const double x = T > 0.0 ? m2 / T : std::numeric_limits<double>::infinity();
    if (t.p * x < dyadic.logLength[J - 1] - logNegligiblePhi) break;
    if (dyadic.length[J - 1] * (T > 0.0 ? t.DhatPower(x) : 0.0) > negligiblePhi) break;
    --J;
  }
  (void)neglected;
  const PhiNodes &set = PhiSet(level, J, Jm);
  *evaluations += set.nodes;
  return kernel::SumCharlieAzimuth({t.p, m2, ds2, B4}, set.c2.data(), set.w.data(), set.c2.size());
}

LevelSums EvaluateLevel(const Problem &t, const Layout &layout, int level) {
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  LevelSums sums;
  // The t-panels' negligible masses add up to at most mu_end x this.
  const double negligiblePhi = kConeShare * t.negligible / std::max(t.muEnd, 1e-300);
  const double logNegligiblePhi = std::log(negligiblePhi);
  for (const MuPanel &panel : layout.panels) {
    const double L = panel.b - panel.a;
    double panelSum = 0.0, panelNeglected = 0.0;
    for (int j = 0; j < rule.n; ++j) {
      double mu_i, oneMinus, weight;
      if (panel.map == 3) {
        // y = |mu_i - end|^c; end is 0 (k = 1) or 1 (k = -1).
        const double y = panel.a + L * rule.x[j];
        const double x = std::pow(y, 1.0 / t.c);
        weight = L * rule.w[j] * x / (t.c * y);
        mu_i = panel.k > 0.0 ? x : 1.0 - x;
        oneMinus = panel.k > 0.0 ? 1.0 - x : x;
      } else if (panel.map == 0) {
        mu_i = panel.a + L * rule.x[j];
        oneMinus = 1.0 - mu_i;
        weight = L * rule.w[j];
      } else {
        const double uk = std::pow(rule.x[j], panel.k);
        const double jac = panel.k * uk / rule.x[j];
        weight = L * jac * rule.w[j];
        if (panel.map == 1) {
          mu_i = panel.a + L * uk;
          oneMinus = 1.0 - mu_i;
        } else {
          oneMinus = (1.0 - panel.b) + L * uk;
          mu_i = panel.b - L * uk;
        }
      }
      const double s_i = SafeSqrt(oneMinus * (1.0 + mu_i));
      const double what = t.What(mu_i);
      double neglected = 0.0;
      const double G = PhiIntegral(t, level, mu_i, s_i, negligiblePhi, logNegligiblePhi, &neglected,
                                   &sums.evaluations);
      panelSum += weight * what * G;
      panelNeglected += weight * what * neglected;
    }
    sums.J += panelSum;
    sums.panels.push_back(panelSum);
    sums.neglected += panelNeglected;
  }
  return sums;
}

// sum over panels of |V_k - V_(k-1)|: the panels' errors may have either
// sign, and the difference of the totals can cancel where the finer level's
// errors do not (measured: 4e-9 errors of 5-node panels summing to 7e-12,
// beside 7-node errors of one sign summing to 6e-11).
double PanelDifference(const LevelSums &a, const LevelSums &b) {
  double sum = 0.0;
  for (size_t p = 0; p < a.panels.size() && p < b.panels.size(); ++p)
    sum += std::abs(a.panels[p] - b.panels[p]);
  return sum;
}

// The integral and its bound in units of J: levels until the bound is at most
// tolerance max(1, E) (in J units: tolerance max(1/S, J)).
struct JResult {
  double J = 0.0, bound = 0.0, neglected = 0.0;
  uint64_t evaluations = 0;
};

JResult IntegrateJ(Problem t, double negligibleJ, double tolerance) {
  JResult out;
  t.negligible = negligibleJ;
  t.muEnd = LobeEnd(t, t.negligible);
  const double tail = t.muEnd < 1.0 ? kPi * (1.0 - t.muEnd) * t.DhatMax(t.muEnd) : 0.0;
  const Layout layout = MuLayout(t);
  const double invS = std::exp(-t.logS);  // may be 0: then only the J part counts
  LevelSums previous = EvaluateLevel(t, layout, 0);
  out.evaluations = previous.evaluations;
  for (int k = 1; k < kLevels; ++k) {
    const LevelSums current = EvaluateLevel(t, layout, k);
    out.evaluations += current.evaluations;
    out.J = current.J;
    out.neglected = tail + layout.neglected + std::max(current.neglected, previous.neglected);
    out.bound = PanelDifference(current, previous) + out.neglected +
                kBoundFloor * std::max(invS, std::abs(out.J));
    if (out.bound <= tolerance * std::max(invS, std::abs(out.J))) break;
    previous = current;
  }
  return out;
}

}  // namespace

SheenIntegral IntegrateSheenAlbedo(SheenVisibility visibility, double alpha, double mu_o,
                                   double tolerance) {
  CheckArguments(alpha, mu_o, tolerance);
  CheckFinite(visibility, alpha, mu_o);
  SheenIntegral result;
  if (alpha == 0.0) {
    result.exact = true;  // E = 0 for mu_o > 0 (see the header)
    return result;
  }
  const Problem t = MakeProblem(visibility, alpha, mu_o);
  // An upper bound of E: if negligible, E is 0 within it.
  const double upperJ = MassBound(t, 0.0, 1.0);
  const double upper = Scaled(upperJ, t.logS);
  if (upper <= kNegligibleShare * tolerance) {
    result.bound = std::max(upper, std::numeric_limits<double>::denorm_min());
    return result;
  }
  // The negligible mass, 1e-3 tolerance max(1, E) in J units, with E first
  // taken as its upper bound; where that was far above E and the neglected
  // parts then weigh in the bound, once more with E's value.
  double estimate = std::max(1.0, upper);
  JResult j;
  for (int pass = 0; pass < 2; ++pass) {
    const double negligibleJ = std::exp(std::log(kNegligibleShare * tolerance * estimate) - t.logS);
    j = IntegrateJ(t, negligibleJ, tolerance);
    result.evaluations += j.evaluations;
    const double value = Scaled(j.J, t.logS);
    const double bound = Scaled(j.bound, t.logS);
    if (bound <= tolerance * std::max(1.0, value) || estimate <= 2.0 * std::max(1.0, value)) break;
    estimate = std::max(1.0, value);
  }
  result.value = Scaled(j.J, t.logS);
  result.bound = Scaled(j.bound, t.logS);
  return result;
}

// ---------------------------------------------------------------------------
// E_avg = 2 int_0^1 E(mu) mu dmu by Gauss panels in mu, E at each node by the
// rule above at the same level (the level difference of E_avg then measures
// both rules' errors). The panels, from E's features as a function of mu_o:
// Charlie's Lambda(mu_o) (with its branch points at 0 and 1, and C1 only at
// 0.5) enters through W_max = 1 / (4 mu_o (1 + Lambda(mu_o))), so 2 mu E is
// finite at 0 and the same y = mu^c panels as above are used at both ends;
// ashikhmin: panels graded by 2 toward 0 from the lobe scale (E has the pole
// of W at mu_i = -mu_o / (1 - mu_o) approaching its range) down to where
// h^2 U(0) is 1e5 negligible masses (AverageLayout), and u^2-mapped at 1
// (s_o). None longer than min(1/4, 2 sqrt(alpha)), and none past the end of
// the lobe, where the rest of E_avg is at most
//   int_mu^1 2 mu E <= pi K (1 - mu) (1 + mu^2 / (1 + s)^2)^(-p)
// (mu W_max <= 1/4 for both; the J integral at most pi dhatmax(mu_o, 0)).
// The negligible masses of the nodes' E are budgeted so that they add up to
// 1e-3 tolerance over the rule: node j (weight w_j) gets
// 1e-3 tolerance / (2 mu_j w_j N), N the number of nodes. The bound is the
// sum over mu panels of |V_k - V_(k-1)|, plus the tail, the nodes'
// neglected masses (weighted) and 1e-12 max(1, V). Measured against
// tests/data/sheen: within every bound at 1e-8 and 1e-10, 3 to 16 ms a value
// (2.4 to 10 ms at 1e-8 for the ten tabulated alphas; 32 texels of r^2: mean
// 3.8 ms charlie, 4.3 ms ashikhmin).

namespace {

struct NodeValue {
  double E = 0.0, neglected = 0.0;  // E at one level and its neglected mass, E units
  uint64_t evaluations = 0;
};

NodeValue NodeAlbedo(SheenVisibility visibility, double alpha, double mu_o, double negligibleE,
                     int level) {
  NodeValue out;
  Problem t = MakeProblem(visibility, alpha, mu_o);
  const double upper = Scaled(MassBound(t, 0.0, 1.0), t.logS);
  if (upper <= negligibleE) {
    out.neglected = upper;
    return out;
  }
  t.negligible = std::exp(std::log(negligibleE) - t.logS);
  t.muEnd = LobeEnd(t, t.negligible);
  const double tail = t.muEnd < 1.0 ? kPi * (1.0 - t.muEnd) * t.DhatMax(t.muEnd) : 0.0;
  const Layout layout = MuLayout(t);
  const LevelSums sums = EvaluateLevel(t, layout, level);
  out.E = Scaled(sums.J, t.logS);
  out.neglected = Scaled(tail + layout.neglected + sums.neglected, t.logS);
  out.evaluations = sums.evaluations;
  return out;
}

double AverageTail(double alpha, double mu) {
  const double s = SafeSqrt((1.0 - mu) * (1.0 + mu));
  return kPi * CharlieNormalization(alpha) * (1.0 - mu) *
         std::exp(-0.5 / alpha * std::log1p(mu * mu / Sqr(1.0 + s)));
}

std::vector<MuPanel> AverageLayout(SheenVisibility visibility, double alpha, double end,
                                   double negligible, double *neglected) {
  std::vector<MuPanel> panels;
  const bool charlie = UsesCharlieLambda(visibility);
  const double c = CharlieLambdaExponent(alpha);
  const double lobe = 2.0 * std::sqrt(alpha);
  const double maxLength = std::min(kMaxMuPanel, lobe);
  double h0 = std::min({0.125, 0.25 * lobe, 0.5 * end});
  if (charlie) {
    PushPowerPanels(0.0, h0, c, &panels);
  } else {
    // E near grazing view is of the size of U(0), its bound there; E's
    // singular terms at mu = 0 (the pole of W reaching mu_i = 0, h = n
    // reaching the horizon) are O(mu log mu), so the first panel [0, h],
    // integrated like the others, is graded down only until it holds
    // ~h^2 U <= kConeShare negligible masses of E_avg (the level difference
    // measures its error).
    (void)neglected;
    Problem t = MakeProblem(visibility, alpha, 0.0);
    const double U = Scaled(MassBound(t, 0.0, 1.0), t.logS);
    const double hNeg = std::sqrt(kConeShare * negligible / std::max(U, 1e-300));
    double h = h0;
    while (0.5 * h > hNeg && h > 1e-300) h *= 0.5;
    if (h < h0) {
      panels.push_back({0.0, h, 0, 1.0});
      PushGraded(h, h0, h, 0.0, maxLength, &panels);
    } else {
      panels.push_back({0.0, h0, 0, 1.0});
    }
  }
  std::vector<double> points{h0};
  if (charlie && 0.5 > h0 && 0.5 < end) points.push_back(0.5);
  const bool toOne = end >= 1.0;
  double h1 = 0.0;
  if (toOne) h1 = std::min({0.125, lobe, 0.5 * (1.0 - points.back())});
  const double last = toOne ? 1.0 - h1 : end;
  points.push_back(last);
  for (size_t k = 0; k + 1 < points.size(); ++k)
    PushGraded(points[k], points[k + 1], k == 0 ? h0 : 0.0,
               toOne && k + 2 == points.size() ? h1 : 0.0, maxLength, &panels);
  if (toOne) {
    if (charlie)
      PushPowerPanels(1.0, 1.0 - h1, c, &panels);
    else
      panels.push_back({1.0 - h1, 1.0, 2, 2.0});
  }
  return panels;
}

// One level of E_avg.
struct AverageSums {
  double value = 0.0, neglected = 0.0;
  std::vector<double> panels;  // each mu panel's share
  uint64_t evaluations = 0;
};

AverageSums AverageAtLevel(SheenVisibility visibility, double alpha, double tolerance,
                           const std::vector<MuPanel> &panels, int level) {
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  const double c = CharlieLambdaExponent(alpha);
  const double nodes = static_cast<double>(panels.size() * rule.n);
  AverageSums sums;
  for (const MuPanel &panel : panels) {
    const double L = panel.b - panel.a;
    double panelSum = 0.0;
    for (int j = 0; j < rule.n; ++j) {
      double mu, weight;
      if (panel.map == 3) {
        const double y = panel.a + L * rule.x[j];
        const double x = std::pow(y, 1.0 / c);
        weight = L * rule.w[j] * x / (c * y);
        mu = panel.k > 0.0 ? x : 1.0 - x;
      } else if (panel.map == 2) {
        const double uk = std::pow(rule.x[j], panel.k);
        weight = L * rule.w[j] * panel.k * uk / rule.x[j];
        mu = panel.b - L * uk;
      } else {
        mu = panel.a + L * rule.x[j];
        weight = L * rule.w[j];
      }
      if (!(mu > 0.0) || !(weight > 0.0)) continue;
      const double share = 2.0 * mu * weight;
      const double negligibleE = kNegligibleShare * tolerance / (share * nodes);
      const NodeValue e = NodeAlbedo(visibility, alpha, std::min(mu, 1.0), negligibleE, level);
      panelSum += share * e.E;
      sums.neglected += share * e.neglected;
      sums.evaluations += e.evaluations;
    }
    sums.value += panelSum;
    sums.panels.push_back(panelSum);
  }
  return sums;
}

}  // namespace

SheenIntegral IntegrateSheenAlbedoAverage(SheenVisibility visibility, double alpha,
                                          double tolerance) {
  CheckArguments(alpha, 0.5, tolerance);
  SheenIntegral result;
  if (alpha == 0.0) {
    result.exact = true;  // E_avg -> 0 as alpha -> 0 (E_avg = O(sqrt(alpha)), see the header)
    return result;
  }
  // E_avg <= 1 for Charlie and ~ a few for ashikhmin: the target is
  // tolerance max(1, E_avg) with E_avg's first estimate 1, refined below.
  double negligible = kNegligibleShare * tolerance;
  // The end of the lobe: bisection on the tail bound (decreasing in mu).
  double end = 1.0;
  if (AverageTail(alpha, 0.0) <= negligible) {
    result.bound = AverageTail(alpha, 0.0);
    return result;
  }
  {
    double lo = 0.0, hi = 1.0;
    if (AverageTail(alpha, 1.0 - 1e-16) > negligible) hi = 1.0;
    for (int k = 0; k < 80 && hi - lo > 1e-3 * hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      (AverageTail(alpha, mid) <= negligible ? hi : lo) = mid;
    }
    end = hi;
  }
  const double tail = end < 1.0 ? AverageTail(alpha, end) : 0.0;
  double neglectedFirst = 0.0;
  const std::vector<MuPanel> panels =
      AverageLayout(visibility, alpha, end, negligible, &neglectedFirst);
  AverageSums previous = AverageAtLevel(visibility, alpha, tolerance, panels, 0);
  result.evaluations = previous.evaluations;
  for (int k = 1; k < kLevels; ++k) {
    const AverageSums current = AverageAtLevel(visibility, alpha, tolerance, panels, k);
    result.evaluations += current.evaluations;
    result.value = current.value;
    double difference = 0.0;
    for (size_t p = 0; p < current.panels.size(); ++p)
      difference += std::abs(current.panels[p] - previous.panels[p]);
    result.bound = difference + tail + neglectedFirst +
                   std::max(current.neglected, previous.neglected) +
                   kBoundFloor * std::max(1.0, std::abs(current.value));
    if (result.bound <= tolerance * std::max(1.0, std::abs(result.value))) break;
    previous = current;
  }
  return result;
}

// ---------------------------------------------------------------------------
// The adaptive reference (see the header): over the half vector,
//   E = (4 / pi) (1 + 2 alpha) int_{v_min}^inf exp(-(1 + 2 alpha) v) dv
//       int_0^{phi_max(v)} (o.h) W(mu_i) / cos(theta_h) dphi_h,
// from D cos(theta_h) d(omega_h) = (1 + 2 alpha) exp(-(1 + 2 alpha) v) dv dphi /
// (2 pi), v = -(q / 2) log(sin^2(theta_h)), d(omega_i) = 4 (o.h) d(omega_h),
// phi_h in [0, 2 pi] folded onto [0, pi]. With c = cos(theta_h), s = sin:
//   c^2 = -expm1(-2 alpha v),  s = exp(-alpha v),
//   o.h = s_o s cos(phi) + mu_o c,  mu_i = 2 (o.h) c - mu_o,
// the light is above the horizon for cos(phi) > mu_o (1 - 2 c^2) / (2 c s_o s),
// and v >= v_min = -(q / 2) log((1 + s_o) / 2) (theta_h <= (theta_o + pi/2) / 2).
// Factored out: W_max, exp(-(1 + 2 alpha) v_min) and, for mu_o > 0, 1 / mu_o
// (mu_o (o.h) / c <= 1 + s_o).

namespace {

struct HalfVectorProblem {
  Problem base;
  double vMin = 0.0;
  double logP = 0.0;  // log of the factor in front of the double integral
  double muScale = 1.0;
  bool schlickWeight = false;  // weigh by (1 - o.h)^5 (the sheen's B)
};

HalfVectorProblem MakeHalfVectorProblem(SheenVisibility visibility, double alpha, double mu_o) {
  HalfVectorProblem h;
  h.base = MakeProblem(visibility, alpha, mu_o);
  const double s_o = h.base.s_o;
  h.vMin = mu_o > 0.0 ? -0.5 / alpha * std::log1p(-0.5 * mu_o * mu_o / (1.0 + s_o)) : 0.0;
  h.muScale = mu_o > 0.0 ? mu_o : 1.0;
  // log((4 / pi) (1 + 2 alpha) W_max / muScale) - (1 + 2 alpha) v_min, with
  // W_max = S / (2 K).
  const double logWmax = h.base.logS - std::log(2.0 * CharlieNormalization(alpha));
  h.logP = std::log(4.0 / kPi * (1.0 + 2.0 * alpha)) + logWmax - std::log(h.muScale) -
           (1.0 + 2.0 * alpha) * h.vMin;
  return h;
}

// theta_h -> v - v_min, for the outer breaks.
double OffsetOfTheta(const HalfVectorProblem &h, double theta) {
  const double s = std::sin(theta);
  return -0.5 / h.base.alpha * std::log(s * s) - h.vMin;
}

struct Inner {
  double value = 0.0, error = 0.0;
  int evaluations = 0;
};

Inner InnerIntegral(const HalfVectorProblem &h, double w, double absTolerance,
                    double relTolerance) {
  const Problem &t = h.base;
  const double alpha = t.alpha, v = h.vMin + w;
  const double c = std::sqrt(std::max(0.0, -std::expm1(-2.0 * alpha * v)));
  const double s = std::exp(-alpha * v);
  const double mu_o = t.mu_o, s_o = t.s_o;
  if (!(c > 0.0)) return {};
  const auto muAt = [&](double cosPhi) {
    return 2.0 * c * s_o * s * cosPhi - mu_o * (1.0 - 2.0 * c * c);
  };
  double phiMax = kPi;
  const double denom = 2.0 * c * s_o * s;
  if (denom > 0.0) {
    const double cStar = mu_o * (1.0 - 2.0 * c * c) / denom;
    if (cStar >= 1.0) return {};
    if (cStar > -1.0) phiMax = std::acos(cStar);
  } else if (muAt(1.0) <= 0.0) {
    return {};
  }
  const auto f = [&](double phi) {
    const double cosPhi = std::cos(phi);
    const double mu_i = muAt(cosPhi);
    if (!(mu_i > 0.0)) return 0.0;
    const double oh = s_o * s * cosPhi + mu_o * c;
    const double value = h.muScale * oh / c * t.What(std::min(mu_i, 1.0));
    if (!h.schlickWeight) return value;
    const double y = 1.0 - std::min(oh, 1.0), y2 = y * y;
    return value * (y2 * y2 * y);
  };
  std::vector<double> breaks{0.0};
  for (int k = 8; k >= 1; --k) breaks.push_back(std::ldexp(phiMax, -k) * 0.5);
  // mu_i = 0.5 inside the range.
  if (denom > 0.0) {
    const double cHalf = (0.5 + mu_o * (1.0 - 2.0 * c * c)) / denom;
    if (cHalf > -1.0 && cHalf < 1.0) {
      const double phiHalf = std::acos(cHalf);
      if (phiHalf > breaks.back() && phiHalf < phiMax) breaks.push_back(phiHalf);
    }
  }
  std::vector<double> upper;
  for (int k = 1; k <= 16; ++k) upper.push_back(phiMax - std::ldexp(phiMax, -k) * 0.5);
  for (double b : upper)
    if (b > breaks.back()) breaks.push_back(b);
  breaks.push_back(phiMax);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const QuadratureResultN<1> r =
      IntegrateAdaptiveN<1>([&](double phi) { return std::array<double, 1>{f(phi)}; }, breaks,
                            absTolerance, relTolerance, 8000);
  return {r.value[0], r.error[0], r.evaluations};
}

}  // namespace

namespace {

SheenIntegral SheenAdaptive(SheenVisibility visibility, double alpha, double mu_o, double tolerance,
                            bool schlickWeight) {
  CheckArguments(alpha, mu_o, tolerance);
  CheckFinite(visibility, alpha, mu_o);
  SheenIntegral result;
  if (alpha == 0.0) {
    result.exact = true;
    return result;
  }
  HalfVectorProblem h = MakeHalfVectorProblem(visibility, alpha, mu_o);
  h.schlickWeight = schlickWeight;
  const double decay = 1.0 + 2.0 * alpha;
  // The double integral is at most pi (1 + s_o) / muScale' ... : with the
  // factors taken out, its integrand is at most (1 + s_o) (mu_o > 0) and
  // int exp(-decay w) dw = 1 / decay; for mu_o = 0, s_o tan(theta) is not
  // bounded and no shortcut is taken.
  if (mu_o > 0.0) {
    const double logUpper = h.logP + std::log(kPi * (1.0 + h.base.s_o) / decay);
    if (logUpper < std::log(kNegligibleShare * tolerance)) {
      result.bound = std::max(std::exp(logUpper), std::numeric_limits<double>::denorm_min());
      return result;
    }
  }
  // Requested: 1/32 of the tolerance from each level (the bound is 16 x
  // their sum); absolute part tolerance / P (E's scale 1), relative part
  // tolerance.
  const double absJ = std::exp(std::log(tolerance / 32.0) - h.logP);
  const double relJ = tolerance / 32.0;
  double innerErrors = 0.0;
  const auto outer = [&](double w) {
    const Inner in = InnerIntegral(h, w, absJ, relJ);
    result.evaluations += static_cast<uint64_t>(in.evaluations);
    const double weight = std::exp(-decay * w);
    return std::array<double, 2>{weight * in.value, weight * in.error};
  };
  std::vector<double> breaks{0.0};
  for (int k = -40; k <= 9; k += 2) breaks.push_back(std::ldexp(1.0, k));
  const double thetaO = std::acos(mu_o);
  for (double theta : {0.25 * kPi - 0.5 * thetaO, 0.5 * thetaO, 0.5 * (thetaO + kPi / 3.0),
                       0.5 * (thetaO - kPi / 3.0), 0.5 * (kPi / 3.0 - thetaO)}) {
    if (!(theta > 0.0)) continue;
    const double w = OffsetOfTheta(h, theta);
    if (w > 0.0 && w < 512.0) breaks.push_back(w);
  }
  breaks.push_back(745.0 / decay);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const QuadratureResultN<2> r = IntegrateAdaptiveN<2>(outer, breaks, absJ, relJ, 8000);
  innerErrors = r.value[1];
  const double J = r.value[0];
  const double errorJ = 16.0 * (r.error[0] + innerErrors);
  result.value = Scaled(J, h.logP);
  result.bound = Scaled(errorJ, h.logP) + kBoundFloor * std::max(1.0, result.value);
  return result;
}

}  // namespace

SheenIntegral IntegrateSheenAlbedoAdaptive(SheenVisibility visibility, double alpha, double mu_o,
                                           double tolerance) {
  return SheenAdaptive(visibility, alpha, mu_o, tolerance, false);
}

SheenIntegral IntegrateSheenSchlickWeightedAdaptive(SheenVisibility visibility, double alpha,
                                                    double mu_o, double tolerance) {
  return SheenAdaptive(visibility, alpha, mu_o, tolerance, true);
}

// E_avg by adaptive Gauss-Kronrod over mu, E at each node by the adaptive
// reference above (its bound integrated as a second channel); breaks graded
// toward 0 and 1 by powers of 2 (Charlie's Lambda(mu_o)) and at 0.5. The
// range stops where the tail bound of IntegrateSheenAlbedoAverage is below
// 1e-3 tolerance (added to the bound).
SheenIntegral IntegrateSheenAlbedoAverageAdaptive(SheenVisibility visibility, double alpha,
                                                  double tolerance) {
  CheckArguments(alpha, 0.5, tolerance);
  SheenIntegral result;
  if (alpha == 0.0) {
    result.exact = true;
    return result;
  }
  const double negligible = kNegligibleShare * tolerance;
  double end = 1.0;
  if (AverageTail(alpha, 0.0) <= negligible) {
    result.bound = AverageTail(alpha, 0.0);
    return result;
  }
  {
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 80 && hi - lo > 1e-3 * hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      (AverageTail(alpha, mid) <= negligible ? hi : lo) = mid;
    }
    end = hi;
  }
  const double tail = end < 1.0 ? AverageTail(alpha, end) : 0.0;
  const double inner = tolerance / 8.0;
  const auto f = [&](double mu) {
    const SheenIntegral e = IntegrateSheenAlbedoAdaptive(visibility, alpha, mu, inner);
    result.evaluations += e.evaluations;
    return std::array<double, 2>{2.0 * mu * e.value, 2.0 * mu * e.bound};
  };
  std::vector<double> breaks{0.0};
  for (int k = 30; k >= 1; k -= 2) breaks.push_back(std::ldexp(end, -k));
  if (end > 0.5) breaks.push_back(0.5);
  for (int k = 2; k <= 20 && end >= 1.0; k += 2) breaks.push_back(1.0 - std::ldexp(1.0, -k));
  breaks.push_back(end);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const QuadratureResultN<2> r =
      IntegrateAdaptiveN<2>(f, breaks, tolerance / 32.0, tolerance / 32.0, 4000);
  result.value = r.value[0];
  result.bound = 16.0 * r.error[0] + r.value[1] + tail + kBoundFloor * std::max(1.0, result.value);
  return result;
}

}  // namespace lutbake
