// The fitted closed forms of --format fit (tests/data/fits) beside the
// analytic split-sum approximations engines ship, all measured alike on one
// grid against lutbake's dfg (the panel quadrature, bound ~1e-8):
//   - lutbake's dfg fit (dfg_fit.h, evaluated in float32 as emitted);
//   - Karis's EnvBRDFApprox (UE4 mobile, also three.js's DFGApprox before
//     its LUT), a function of perceptual roughness r;
//   - MaterialX's mx_ggx_dir_albedo_analytic (a rational quadratic fit to
//     Monte Carlo data, height-correlated Smith like dfg), a function of
//     alpha = r^2 (MaterialX passes the average alpha).
// The engines' constants are facts of their public shaders; the code here is
// ours.
//
//   lutbake_measure_fits [FIT_DIR]   (default: tests/data/fits)
//
// Grid: 101 x 101 cell centres of (mu, r) in [0, 1]^2, less the fit's corner
// box (sqrt(mu) < 0.01 and r < 0.01, where dfg has no limit). Prints, per
// method and channel (A, B) and for E = A + B, the max, mean and RMS
// |error| and where the max is.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "lutbake/formats/fit_format.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/table_definition.h"

namespace {

struct AB {
  double a, b;
};

// Karis 2014, "Physically Based Shading on Mobile": EnvBRDFApprox.
AB Karis(double mu, double r) {
  const double c0[4] = {-1.0, -0.0275, -0.572, 0.022}, c1[4] = {1.0, 0.0425, 1.04, -0.04};
  double v[4];
  for (int i = 0; i < 4; ++i) v[i] = r * c0[i] + c1[i];
  const double a004 = std::min(v[0] * v[0], std::exp2(-9.28 * mu)) * v[0] + v[1];
  return {a004 * -1.04 + v[2], a004 * 1.04 + v[3]};
}

// MaterialX mx_ggx_dir_albedo_analytic (x = NdotV, y = alpha).
AB MaterialX(double mu, double alpha) {
  const double x = mu, y = alpha, x2 = x * x, y2 = y * y;
  const double k[9][4] = {{0.10031, 0.93450, 1.0, 1.0},
                          {-0.63301, -2.32352, -1.76427, 0.22797},
                          {9.74995, 2.22823, 8.26501, 15.93688},
                          {-2.02075, -3.74584, 11.54840, -55.82466},
                          {29.38247, 1.42450, 28.99991, 13.07919},
                          {-8.24713, -0.76829, -7.50867, 41.25882},
                          {-26.51510, 1.43366, -36.16186, 54.86775},
                          {19.98406, 0.29060, 15.85408, 300.10923},
                          {-5.41717, 0.62933, 33.41550, -284.73288}};
  const double m[9] = {1.0, x, y, x * y, x2, y2, x2 * y, x * y2, x2 * y2};
  double r[4] = {0, 0, 0, 0};
  for (int t = 0; t < 9; ++t)
    for (int i = 0; i < 4; ++i) r[i] += k[t][i] * m[t];
  return {r[0] / r[2], r[1] / r[3]};
}

struct Stat {
  double max = 0, sum = 0, sum2 = 0, mu = 0, r = 0;
  int n = 0;
  void Add(double e, double atMu, double atR) {
    e = std::abs(e);
    if (e > max) max = e, mu = atMu, r = atR;
    sum += e;
    sum2 += e * e;
    ++n;
  }
};

}  // namespace

int main(int argc, char **argv) {
  using namespace lutbake;
  const std::string dir = argc > 1 ? argv[1] : "tests/data/fits";
  const FitSource fit = ReadFitSource(dir + "/dfg_fit.h");
  const TableDefinition &dfg = TableNamed("dfg");
  BakeSettings s;
  s.estimator = Estimator::kQuadrature;
  const char *names[3] = {"lutbake dfg_fit.h", "Karis EnvBRDFApprox", "MaterialX analytic"};
  Stat stats[3][3];  // method, {A, B, E}
  const int g = 101;
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const double mu = (i + 0.5) / g, r = (j + 0.5) / g;
      if (std::sqrt(mu) < 0.01 && r < 0.01) continue;
      const PointValue exact = dfg.Evaluate(s, mu, r);
      const AB got[3] = {{fit.fit.EvaluateFloat(0, mu, r), fit.fit.EvaluateFloat(1, mu, r)},
                         Karis(mu, r),
                         MaterialX(mu, r * r)};
      for (int m = 0; m < 3; ++m) {
        stats[m][0].Add(got[m].a - exact.value[0], mu, r);
        stats[m][1].Add(got[m].b - exact.value[1], mu, r);
        stats[m][2].Add(got[m].a + got[m].b - exact.value[0] - exact.value[1], mu, r);
      }
    }
  std::printf("%d x %d cell centres, corner box left out; against dfg (panel quadrature)\n", g, g);
  const char *channel[3] = {"A", "B", "E = A + B"};
  for (int m = 0; m < 3; ++m)
    for (int c = 0; c < 3; ++c) {
      const Stat &t = stats[m][c];
      std::printf("%-22s %-10s max %.3g at (mu %.3f, r %.3f)  mean %.3g  rms %.3g\n", names[m],
                  channel[c], t.max, t.mu, t.r, t.sum / t.n, std::sqrt(t.sum2 / t.n));
    }
  return 0;
}
