#include "lutbake/integrators/light_direction_rule.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/models/ltc.h"

namespace lutbake {

namespace {

// Gauss nodes per panel at levels 0, 1, 2 (the same in theta and phi), and
// the widest panels.
constexpr int kNodes[3] = {8, 12, 18};
constexpr double kMaxThetaPanel = 0.25 * kPi;
constexpr double kMaxPhiPanel = 0.25 * kPi;

Vec3 Cross(const Vec3 &a, const Vec3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Sorted breaks of [lo, hi] at `cuts` inside it, every panel at most
// `widest` wide (split evenly).
std::vector<double> Panels(double lo, double hi, std::vector<double> cuts, double widest) {
  std::vector<double> ends{lo};
  std::sort(cuts.begin(), cuts.end());
  for (double c : cuts)
    if (c > lo && c < hi) ends.push_back(c);
  ends.push_back(hi);
  std::vector<double> out{lo};
  for (size_t k = 0; k + 1 < ends.size(); ++k) {
    const double a = ends[k], b = ends[k + 1];
    if (!(b > a)) continue;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / widest)));
    for (int i = 1; i < n; ++i) out.push_back(a + (b - a) * i / n);
    out.push_back(b);
  }
  return out;
}

// Emits the nodes of theta in [theta0, theta1] along azimuth phi (weight
// wPhi), cut at theta_o.
void Meridian(const Vec3 &o, double thetaO, double theta0, double theta1, double phi, double wPhi,
              int level, std::vector<LtcNode> *nodes) {
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  const double cp = std::cos(phi), sp = std::sin(phi);
  const std::vector<double> ends = Panels(theta0, theta1, {thetaO}, kMaxThetaPanel);
  for (size_t p = 0; p + 1 < ends.size(); ++p) {
    const double a = ends[p], b = ends[p + 1];
    for (int k = 0; k < rule.n; ++k) {
      const double theta = a + (b - a) * rule.x[k];
      const double st = std::sin(theta), ct = std::cos(theta);
      const Vec3 l{st * cp, st * sp, ct};
      const Vec3 sum{o.x + l.x, o.y + l.y, o.z + l.z};
      const Vec3 h = Dot(sum, sum) > 0.0 ? Normalize(sum) : Vec3{0.0, 0.0, 1.0};
      nodes->push_back(LtcNode{l, h, wPhi * rule.w[k] * (b - a) * st});
    }
  }
}

// Calls emit(phi, weight) for the azimuth nodes of [0, pi] (halfCircle,
// weights doubled) or [0, 2 pi], cut at the quarters and at `cuts`.
template <typename Emit>
void Azimuths(int level, bool halfCircle, std::vector<double> cuts, Emit &&emit) {
  const GaussLegendreRule &rule = GaussLegendre(kNodes[level]);
  const double end = halfCircle ? kPi : 2.0 * kPi;
  for (double q : {0.5 * kPi, kPi, 1.5 * kPi}) cuts.push_back(q);
  const std::vector<double> ends = Panels(0.0, end, cuts, kMaxPhiPanel);
  for (size_t p = 0; p + 1 < ends.size(); ++p) {
    const double a = ends[p], b = ends[p + 1];
    for (int k = 0; k < rule.n; ++k)
      emit(a + (b - a) * rule.x[k], rule.w[k] * (b - a) * (halfCircle ? 2.0 : 1.0));
  }
}

}  // namespace

std::vector<LtcNode> LightDirectionRule(double mu_o, int level, bool halfCircle) {
  assert(level >= 0 && level <= 2);
  const Vec3 o = ViewDirection(mu_o);
  const double thetaO = std::acos(Clamp(mu_o, 0.0, 1.0));
  std::vector<LtcNode> nodes;
  Azimuths(level, halfCircle, {}, [&](double phi, double w) {
    Meridian(o, thetaO, 0.0, 0.5 * kPi, phi, w, level, &nodes);
  });
  return nodes;
}

std::vector<LtcNode> LightDirectionPolygonRule(double mu_o, int level, const Vec3 *vertices,
                                               int count) {
  assert(count >= 3 && count <= 8 && level >= 0 && level <= 2);
  const Vec3 o = ViewDirection(mu_o);
  const double thetaO = std::acos(Clamp(mu_o, 0.0, 1.0));
  // Inward edge normals: toward the polygon's centroid direction.
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
  Vec3 clipped[9];
  const int m = ClipPolygonToUpperHalfSpace(vertices, count, clipped);
  std::vector<LtcNode> nodes;
  if (m == 0) return nodes;
  std::vector<double> cuts;
  for (int i = 0; i < m; ++i) {
    const Vec3 &v = clipped[i];
    if (std::hypot(v.x, v.y) <= 1e-14 * std::sqrt(Dot(v, v))) continue;  // at the pole
    double phi = std::atan2(v.y, v.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    cuts.push_back(phi);
  }
  Azimuths(level, false, cuts, [&](double phi, double w) {
    const double cp = std::cos(phi), sp = std::sin(phi);
    double lo = 0.0, hi = 0.5 * kPi;
    for (const Vec3 &n : normals) {
      // n . l = a sin(theta) + b cos(theta) >= 0 on [0, pi/2].
      const double a = n.x * cp + n.y * sp, b = n.z;
      if (a >= 0.0 && b >= 0.0) continue;
      if (a < 0.0 && b < 0.0) return;  // the meridian misses P
      const double root = std::atan2(std::fabs(b), std::fabs(a));
      if (b >= 0.0)
        hi = std::min(hi, root);  // a < 0: from the normal up to the root
      else
        lo = std::max(lo, root);  // a >= 0: from the root to the horizon
    }
    if (hi > lo) Meridian(o, thetaO, lo, hi, phi, w, level, &nodes);
  });
  return nodes;
}

}  // namespace lutbake
