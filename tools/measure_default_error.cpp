#include <cstdio>
// Real error of a bake against the quadrature reference: every texel of E,
// and the grazing columns, smoothest rows, edges and a lattice of dfg.
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdlib>

#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/tables/bake.h"
using namespace lutbake;
static int Measure(int argc, char **argv) {
  BakeSettings s;
  s.samples = atoll(argv[1]);
  int which = atoi(argv[2]);  // 0 E, 1 dfg
  s.ndf = argc > 3 && atoi(argv[3]) ? NdfKind::kBeckmann : NdfKind::kGgx;
  s.estimator = argc > 4 && atoi(argv[4]) ? Estimator::kNdf : Estimator::kVisibleNormal;
  const TableDefinition *k = which ? &TableNamed("dfg") : &TableNamed("E");
  auto t0 = std::chrono::steady_clock::now();
  Table t = BakeTable(*k, s);
  double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int W = t.width(), H = t.height();
  const bool all = which == 0;
  std::vector<std::pair<int, int>> pts;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (all || x < 2 || y < 2 || x == W - 1 || y == H - 1 || (x % 7 == 3 && y % 7 == 3))
        pts.push_back({x, y});
  std::vector<double> err(pts.size()), bound(pts.size());
  tbb::parallel_for(size_t(0), pts.size(), [&](size_t i) {
    auto [x, y] = pts[i];
    double r = t.y.TexelCenter(y);
    ReferenceAlbedo ref = IntegrateReferenceAlbedo(Ndf{s.ndf, r * r}, s.smith, t.x.TexelCenter(x));
    double e = 0, b = 0;
    for (int c = 0; c < t.channels; ++c) {
      double v = which ? (c ? ref.B : ref.A) : ref.E;
      e = std::max(e, std::abs((double)(float)t.value(x, y, c) - v));
      b = std::max(b, t.errors[t.index(x, y, c)]);
    }
    err[i] = e;
    bound[i] = b;
  });
  double maxe = 0, maxb = 0;
  int worst = 0, over = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (err[i] > maxe) {
      maxe = err[i];
      worst = i;
    }
    maxb = std::max(maxb, bound[i]);
    if (err[i] > bound[i] + 1e-7) over++;
  }
  for (size_t i = 0; i < pts.size() && getenv("SHOW"); ++i)
    if (err[i] > bound[i] + 1e-7)
      printf("  (%d,%d) err %.2e bound %.2e\n", pts[i].first, pts[i].second, err[i], bound[i]);
  double maxcol0 = 0, maxrow0 = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].first == 0) maxcol0 = std::max(maxcol0, err[i]);
    if (pts[i].second == 0) maxrow0 = std::max(maxrow0, err[i]);
  }
  printf(
      "N=%llu table=%s bake %.2fs  checked %zu: max err %.3e at (%d,%d) (grazing col %.3e, smooth "
      "row %.3e); max bound %.3e; err>bound: %d (%.2f%%)\n",
      (unsigned long long)s.samples, k->Name(), dt, pts.size(), maxe, pts[worst].first,
      pts[worst].second, maxcol0, maxrow0, maxb, over, 100.0 * over / pts.size());
  return 0;
}
int main(int argc, char **argv) {
  const char *samples = argc > 1 ? argv[1] : "65536";
  for (const char *table : {"0", "1"}) {
    const char *args[] = {argv[0], samples, table};
    Measure(3, const_cast<char **>(args));
  }
}
