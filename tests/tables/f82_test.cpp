// The F82 term C(mu, r) (table f82) and the F82-tint F_avg (Favg --fresnel
// f82): C against a brute-force product rule over the light direction written
// here (its own GGX, Beckmann and Smith formulas), the mirror's closed form,
// the bounds 0 <= C <= B / 4 and C <= 6^6/7^7 E, the panel quadrature against
// the adaptive reference, the sampled estimators within their bounds, and
// bake, check and the header through the library (lutbake::Bake,
// CheckBakedSet); eval's options for these tables are tests/cli/eval_tables_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "lutbake/formats/binary_format.h"
#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/lutbake.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

constexpr double kPiHere = 3.14159265358979323846;
// The maximum of (o.h) (1 - o.h)^6, at o.h = 1/7: 6^6 / 7^7.
constexpr double kBumpMax = 46656.0 / 823543.0;

BakeSettings Model(NdfKind ndf, SmithForm smith) {
  BakeSettings s;
  s.ndf = ndf;
  s.smith = smith;
  return s;
}

// ---- the independent computation -------------------------------------
// C = integral over the light direction i of D(h) G2(o, i) / (4 mu_o)
// (o.h) (1 - o.h)^6 d omega_i, with d omega_i = dmu_i dphi_i, over mu_i in
// (0, 1] and phi_i in [0, 2 pi) (twice [0, pi] by the symmetry about the
// plane of o and n). Composite Gauss-Legendre in both, uniform panels.

// Lambda of GGX and Beckmann at cosine m (written here, not the library's).
double LambdaHere(NdfKind ndf, double alpha, double m) {
  const double tan2 = (1.0 - m * m) / (m * m);
  if (ndf == NdfKind::kGgx) return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
  // Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = 1 / (alpha tan(theta)).
  const double a = 1.0 / (alpha * std::sqrt(tan2));
  return 0.5 * (std::exp(-a * a) / (a * std::sqrt(kPiHere)) - std::erfc(a));
}

double DHere(NdfKind ndf, double alpha, double cosH) {
  const double c2 = cosH * cosH, a2 = alpha * alpha;
  if (ndf == NdfKind::kGgx) {
    const double d = c2 * (a2 - 1.0) + 1.0;
    return a2 / (kPiHere * d * d);
  }
  const double tan2 = (1.0 - c2) / c2;
  return std::exp(-tan2 / a2) / (kPiHere * a2 * c2 * c2);
}

double BruteForceC(NdfKind ndf, SmithForm smith, double mu_o, double r, int panels = 120) {
  const double alpha = r * r;
  const double s_o = std::sqrt(1.0 - mu_o * mu_o);
  const double L_o = LambdaHere(ndf, alpha, mu_o);
  const GaussLegendreRule &rule = GaussLegendre(10);
  double sum = 0.0;
  for (int pm = 0; pm < panels; ++pm)
    for (int jm = 0; jm < rule.n; ++jm) {
      const double mu_i = (pm + rule.x[jm]) / panels, wm = rule.w[jm] / panels;
      const double s_i = std::sqrt(1.0 - mu_i * mu_i);
      const double L_i = LambdaHere(ndf, alpha, mu_i);
      const double G2 = smith == SmithForm::kCorrelated ? 1.0 / (1.0 + L_o + L_i)
                                                        : 1.0 / ((1.0 + L_o) * (1.0 + L_i));
      double inner = 0.0;
      for (int pp = 0; pp < panels; ++pp)
        for (int jp = 0; jp < rule.n; ++jp) {
          const double phi = kPiHere * (pp + rule.x[jp]) / panels;
          const double hx = s_o + s_i * std::cos(phi), hy = s_i * std::sin(phi), hz = mu_o + mu_i;
          const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
          const double oh = (s_o * hx + mu_o * hz) / len;
          const double y = 1.0 - oh;
          inner += rule.w[jp] / panels * DHere(ndf, alpha, hz / len) * oh * std::pow(y, 6);
        }
      sum += wm * inner * kPiHere * G2;
    }
  return 2.0 * sum / (4.0 * mu_o);
}

TEST(F82Table, IsDefinedAndRegistered) {
  const TableDefinition &c = TableNamed("f82");
  EXPECT_EQ(c.Channels(), 1);
  EXPECT_EQ(c.ChannelMeanings(), std::vector<std::string>{"C"});
  std::map<uint64_t, std::string> seeds;
  for (const TableDefinition *t : AllTables())
    EXPECT_TRUE(seeds.emplace(t->SeedId(), t->Name()).second) << t->Name();
  Axis x, y;
  DefaultAxes(c, BakeSettings{}, &x, &y);
  EXPECT_EQ(x.name, "mu");
  EXPECT_EQ(y.name, "perceptualRoughness");
  EXPECT_EQ(x.count, 128);  // dfg's texels
  EXPECT_EQ(y.count, 128);
  EXPECT_EQ(c.AlphaMetadata(BakeSettings{}), "alpha = perceptualRoughness^2");
}

// The brute-force rule above, at points where its uniform panels resolve the
// lobe (alpha >= 0.16; 1200 x 1200 nodes): the quadrature agrees within its
// own bound. The brute force's own error, measured by doubling its panels,
// was at most 1.7e-17 at these points; the quadrature's at most 2.9e-12
// (bounds 1.3e-10 to 1.8e-9).
TEST(F82Table, MatchesABruteForceProductRule) {
  const TableDefinition &table = TableNamed("f82");
  struct Case {
    NdfKind ndf;
    SmithForm smith;
    double mu, r;
  };
  const Case cases[] = {
      {NdfKind::kGgx, SmithForm::kCorrelated, 0.5, 0.5},
      {NdfKind::kGgx, SmithForm::kCorrelated, 0.15, 0.8},
      {NdfKind::kGgx, SmithForm::kCorrelated, 0.9, 0.4},
      {NdfKind::kGgx, SmithForm::kCorrelated, 0.05, 0.6},
      {NdfKind::kGgx, SmithForm::kSeparable, 0.3, 0.7},
      {NdfKind::kGgx, SmithForm::kSeparable, 0.8, 1.0},
      {NdfKind::kBeckmann, SmithForm::kCorrelated, 0.4, 0.6},
      {NdfKind::kBeckmann, SmithForm::kSeparable, 0.7, 0.9},
  };
  for (const Case &c : cases) {
    const BakeSettings s = Model(c.ndf, c.smith);
    const PointValue v = table.Evaluate(s, c.mu, c.r);
    const double truth = BruteForceC(c.ndf, c.smith, c.mu, c.r);
    EXPECT_NEAR(v.value[0], truth, v.error[0] + 1e-15)
        << ToString(c.ndf) << " " << ToString(c.smith) << " mu " << c.mu << " r " << c.r;
    EXPECT_NEAR(v.value[0], truth, 1e-11);  // measured: at most 2.9e-12
    EXPECT_LE(v.error[0], 1e-8);
    EXPECT_GT(truth, 0.0);
  }
}

// r = 0, the mirror: o.h = mu, G2 = 1, C = mu (1 - mu)^6 exactly, error 0;
// and r -> 0 approaches it.
TEST(F82Table, MirrorIsTheClosedForm) {
  const TableDefinition &table = TableNamed("f82");
  for (double mu : {0.0, 1e-7, 0.01, 1.0 / 7.0, 0.5, 0.99, 1.0}) {
    const PointValue v = table.Evaluate(BakeSettings{}, mu, 0.0);
    EXPECT_DOUBLE_EQ(v.value[0], mu * std::pow(1.0 - mu, 6)) << mu;
    EXPECT_EQ(v.error[0], 0.0);
    EXPECT_TRUE(v.exact);
    if (mu >= 0.01) {
      // alpha = 1e-6, far below mu: the lobe is a mirror to within ~alpha.
      const PointValue near = table.Evaluate(BakeSettings{}, mu, 1e-3);
      EXPECT_NEAR(near.value[0], mu * std::pow(1.0 - mu, 6), 1e-5) << mu;
    }
  }
}

// Pointwise (o.h) (1 - o.h) <= 1/4 and (o.h) (1 - o.h)^6 <= 6^6/7^7, so
// 0 <= C <= B / 4 and C <= 6^6/7^7 E, with B and E of dfg and E at the same
// point; within the bounds the three carry.
TEST(F82Table, LiesBelowAQuarterOfBAndTheBumpTimesE) {
  const TableDefinition &c = TableNamed("f82"), &dfg = TableNamed("dfg"), &e = TableNamed("E");
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable}) {
      const BakeSettings s = Model(ndf, smith);
      for (double mu : {0.0, 0.01, 0.1, 1.0 / 7.0, 0.3, 0.6, 1.0})
        for (double r : {0.0, 0.01, 0.1, 0.3, 0.6, 1.0}) {
          const PointValue vc = c.Evaluate(s, mu, r), vd = dfg.Evaluate(s, mu, r),
                           ve = e.Evaluate(s, mu, r);
          EXPECT_GE(vc.value[0], 0.0);
          EXPECT_LE(vc.value[0], 0.25 * vd.value[1] + vc.error[0] + vd.error[1]) << mu << " " << r;
          // (At mu = 1/7, r = 0 the two sides are equal: a few ulps allowed.)
          EXPECT_LE(vc.value[0], kBumpMax * ve.value[0] * (1.0 + 1e-15) + vc.error[0] + ve.error[0])
              << mu << " " << r;
        }
    }
}

// The panel quadrature against the adaptive reference (nested Gauss-Kronrod
// over another parameterisation) at smooth, grazing and rough points, both
// NDFs and Smith forms: within the sum of their bounds.
TEST(F82Table, QuadratureMatchesTheAdaptiveReference) {
  const TableDefinition &table = TableNamed("f82");
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (SmithForm smith : {SmithForm::kCorrelated, SmithForm::kSeparable}) {
      const BakeSettings q = Model(ndf, smith);
      BakeSettings a = q;
      a.estimator = Estimator::kAdaptiveQuadrature;
      for (double mu : {0.0, 1e-4, 0.02, 0.3, 0.9, 1.0})
        for (double r : {1e-3, 0.03, 0.2, 0.5, 1.0}) {
          const PointValue vq = table.Evaluate(q, mu, r), va = table.Evaluate(a, mu, r);
          EXPECT_NEAR(vq.value[0], va.value[0], std::max(1e-10, vq.error[0]) + va.error[0])
              << ToString(ndf) << " " << ToString(smith) << " mu " << mu << " r " << r;
          EXPECT_LE(vq.error[0], 1e-8);
          EXPECT_LE(std::abs(vq.value[0] - va.value[0]), 1e-9);
        }
    }
}

// Sampled (visible normals, scrambled Sobol): each texel within its 99%
// bound of the quadrature, and eval at a texel centre gives that texel.
TEST(F82Table, SampledBakeIsWithinItsBounds) {
  const TableDefinition &table = TableNamed("f82");
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann}) {
    BakeSettings s = Model(ndf, SmithForm::kCorrelated);
    s.size = 6;
    s.samples = 4096;
    s.estimator = Estimator::kVisibleNormal;
    const Table t = BakeTable(table, s);
    BakeSettings q = s;
    q.estimator = Estimator::kQuadrature;
    int outside = 0;
    for (int y = 0; y < t.height(); ++y)
      for (int x = 0; x < t.width(); ++x) {
        const double mu = t.x.TexelCenter(x), r = t.y.TexelCenter(y);
        const PointValue truth = table.Evaluate(q, mu, r);
        const size_t i = t.index(x, y, 0);
        outside += std::abs(t.values[i] - truth.value[0]) > t.errors[i] + truth.error[0];
        EXPECT_EQ(table.Evaluate(s, mu, r).value[0], t.values[i]);
      }
    // 36 texels, each outside its 99% bound with probability <= 1%.
    EXPECT_LE(outside, 3);
  }
}

// Evaluation as `lutbake eval` does it with no sampling option: the
// settings' defaults through ApplySampling (the quadrature).
BakeSettings EvalSettings(BakeSettings settings = {}) {
  ApplySampling(SamplingRequest{}, &settings);
  return settings;
}

// A bake of f82 and dfg in every format, checked by CheckBakedSet; eval at
// a texel centre is the texel; the bake is the same for 1 and 2 threads.
TEST(F82Table, BakeEvalAndCheck) {
  const fs::path out = test::Scratch("f82_bake"), one = test::Scratch("f82_bake_one");
  BakeRequest request = test::BakeRequestFor(out);  // --tables f82,dfg,E --size 16 --error-map
  request.tables = {"f82", "dfg", "E"};
  request.size = 16;
  request.errorMaps = true;
  Bake(request);
  BakeRequest single = test::BakeRequestFor(one);  // --tables f82 --size 16 --threads 1
  single.tables = {"f82"};
  single.size = 16;
  single.threads = 1;
  Bake(single);
  for (const char *file : {"f82.exr", "f82.bin", "f82.h", "f82.err.exr"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const Table t = ReadBinaryTable((out / "f82.bin").string());
  const Table t1 = ReadBinaryTable((one / "f82.bin").string());
  EXPECT_EQ(t.values, t1.values);
  const Table dfg = ReadBinaryTable((out / "dfg.bin").string());
  EXPECT_EQ(*t.FindMetadata("channelLayout"), "Y = C");
  for (size_t i = 0; i < t.values.size(); ++i) {
    EXPECT_LE(t.errors[i], 4e-8) << i;  // float32-exact: 1e-8 plus the rounding
    EXPECT_LE(t.values[i], 0.25 * dfg.values[2 * i + 1] + t.errors[i] + dfg.errors[2 * i + 1]);
  }
  // Texel (3, 5): mu = 3.5 / 16, r = 5.5 / 16 (eval --table f82 --mu 0.21875
  // --roughness 0.34375).
  const PointValue eval = TableNamed("f82").Evaluate(EvalSettings(), 0.21875, 0.34375);
  EXPECT_EQ(static_cast<float>(eval.value[0]), t.values[t.index(3, 5, 0)]);
  const CheckReport check = CheckBakedSet(out.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  std::map<std::string, std::string> status = test::CheckStatuses(check);
  for (const char *expected : {"f82 range", "f82 texels", "f82 points", "f82+dfg at most"})
    EXPECT_EQ(status[expected], "pass") << expected << "\n" << test::Describe(check);
  fs::remove_all(out);
  fs::remove_all(one);
}

// The header's helpers: a of the F82 model and F0 A + F90 B - a C, compiled
// and run with both compilers.
TEST(F82Table, HeaderHelpersAreTheSplitSumWithTheF82Term) {
  const fs::path out = test::Scratch("f82_header");
  BakeRequest request = test::BakeRequestFor(out);  // --tables f82 --size 8
  request.tables = {"f82"};
  request.size = 8;
  Bake(request);
  const fs::path program = out / "albedo.cpp";
  std::ofstream(program) << "#include <cstdio>\n#include \"f82.h\"\n"
                            "int main() {\n"
                            "  using namespace lutbake_luts;\n"
                            "  const float a = f82_tint_a(0.9f, 0.6f);\n"
                            "  std::printf(\"%.9g %.9g\\n\", a,\n"
                            "      specular_albedo_f82(0.8f, 0.1f, 0.01f, 0.9f, 1.0f, a));\n"
                            "}\n";
  const double a = F82TintCoefficient(0.9f, 0.6f);
  for (const std::string &compiler : test::HeaderCompilers()) {
    const std::string exe = (out / "albedo").string();
    ASSERT_EQ(std::system((compiler + " -std=c++17 -Wall -Wextra -Werror -I" + out.string() + " " +
                           program.string() + " -o " + exe)
                              .c_str()),
              0)
        << compiler;
    FILE *pipe = popen(exe.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    double got = 0, albedo = 0;
    ASSERT_EQ(std::fscanf(pipe, "%lf %lf", &got, &albedo), 2);
    pclose(pipe);
    EXPECT_FLOAT_EQ(static_cast<float>(got), static_cast<float>(a)) << compiler;
    EXPECT_NEAR(albedo, 0.9 * 0.8 + 0.1 - a * 0.01, 1e-6) << compiler;
  }
  fs::remove_all(out);
}

// ---- Favg --fresnel f82 ----------------------------------------------

// The closed form against composite Gauss-Legendre of 2 mu F(mu) written
// here (the integrand is a polynomial of degree 8: 5 nodes per panel are
// exact; what remains is rounding).
TEST(F82Favg, ClosedFormMatchesNumericIntegration) {
  const GaussLegendreRule &rule = GaussLegendre(5);
  for (double f0 : {0.0, 0.04, 0.5, 0.9, 1.0})
    for (double tint : {0.0, 0.3, 0.8, 1.0}) {
      double sum = 0.0;
      for (int p = 0; p < 16; ++p)
        for (int j = 0; j < rule.n; ++j) {
          const double mu = (p + rule.x[j]) / 16.0;
          const double schlick = f0 + (1.0 - f0) * std::pow(1.0 - mu, 5);
          const double schlickBar = f0 + (1.0 - f0) * std::pow(6.0 / 7.0, 5);
          const double a = schlickBar * (1.0 - tint) / (std::pow(6.0 / 7.0, 6) / 7.0);
          sum += rule.w[j] / 16.0 * 2.0 * mu * (schlick - a * mu * std::pow(1.0 - mu, 6));
        }
      EXPECT_NEAR(F82TintFresnelAverage(f0, tint).value, sum, 1e-15) << f0 << " " << tint;
      EXPECT_NEAR(TableNamed("Favg")
                      .Evaluate(
                          [] {
                            BakeSettings s;
                            s.fresnel = FresnelModel::kF82;
                            return s;
                          }(),
                          f0, tint)
                      .value[0],
                  sum, 1e-15);
    }
  // tint = 1: Schlick's 20/21 F0 + 1/21; the extreme, F0 = tint = 0: -13/756.
  EXPECT_NEAR(F82TintFresnelAverage(0.3, 1.0).value, 20.0 / 21.0 * 0.3 + 1.0 / 21.0, 1e-16);
  EXPECT_NEAR(F82TintFresnelAverage(0.0, 0.0).value, -13.0 / 756.0, 1e-16);
}

TEST(F82Favg, BakeEvalAndCheck) {
  const fs::path out = test::Scratch("f82_favg");
  BakeRequest request = test::BakeRequestFor(out);  // --tables Favg --fresnel f82 --size 8
  request.tables = {"Favg"};
  request.fresnel = FresnelModel::kF82;
  request.size = 8;
  Bake(request);
  const Table t = ReadBinaryTable((out / "Favg.bin").string());
  EXPECT_EQ(t.x.name, "F0");
  EXPECT_EQ(t.y.name, "tint");
  EXPECT_EQ(*t.FindMetadata("fresnel"), "f82");
  const double f0 = t.x.TexelCenter(2), tint = t.y.TexelCenter(5);
  EXPECT_EQ(t.values[t.index(2, 5, 0)], static_cast<float>(F82TintFresnelAverage(f0, tint).value));
  // eval --table Favg --fresnel f82 --f0 0.9 --tint 0.6
  BakeSettings f82;
  f82.fresnel = FresnelModel::kF82;
  EXPECT_EQ(TableNamed("Favg").Evaluate(EvalSettings(f82), 0.9, 0.6).value[0],
            F82TintFresnelAverage(0.9, 0.6).value);
  const CheckReport check = CheckBakedSet(out.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  fs::remove_all(out);
}

// A manifest of F82-tint metals: planned, baked (f82 at dfg's texels, and
// Favg over the F0 and tint used) and checked, C <= B / 4 included, since
// dfg and f82 share their axes here.
TEST(F82Table, ManifestMetalsArePlannedBakedAndChecked) {
  const fs::path out = test::Scratch("f82_manifest");
  BakeRequest request = test::BakeRequestFor(out);
  request.manifests = {LUTBAKE_TEST_DATA "/plans/f82.json"};  // --manifest
  request.tables = {"f82", "dfg", "Favg"};
  request.size = 8;
  request.formats = {"bin"};
  Bake(request);
  EXPECT_EQ(test::FileNames(out),
            (std::vector<std::string>{"Favg_dielectric.bin", "Favg_f82.bin", "dfg.bin", "f82.bin",
                                      "lutbake-set.json"}));
  const Table c = ReadBinaryTable((out / "f82.bin").string());
  EXPECT_EQ(c.x.count, 8);
  EXPECT_EQ(c.y.nodes, (std::vector<double>{0.1, 0.25, 0.3}));
  EXPECT_EQ(*c.FindMetadata("planMaterials"), "brass, chrome");
  const Table favg = ReadBinaryTable((out / "Favg_f82.bin").string());
  EXPECT_EQ(*favg.FindMetadata("fresnel"), "f82");
  EXPECT_EQ(favg.x.nodes, (std::vector<double>{0.55, 0.78, 0.9, 0.91}));
  // Tint: linear over [0.5, 0.8], 8 x 0.3 rounded up = 3 texels.
  EXPECT_EQ(favg.y.min, 0.5);
  EXPECT_EQ(favg.y.max, 0.8);
  EXPECT_EQ(favg.y.count, 3);
  for (int x = 0; x < favg.width(); ++x)
    for (int y = 0; y < favg.height(); ++y)
      EXPECT_EQ(
          favg.values[favg.index(x, y, 0)],
          static_cast<float>(F82TintFresnelAverage(favg.x.nodes[x], favg.y.TexelCenter(y)).value));
  const CheckReport check = CheckBakedSet(out.string());
  EXPECT_TRUE(check.passed()) << test::Describe(check);
  std::map<std::string, std::string> status = test::CheckStatuses(check);
  for (const char *expected : {"f82 texels", "f82+dfg at most", "Favg_f82 closed form"})
    EXPECT_EQ(status[expected], "pass") << expected << "\n" << test::Describe(check);
  fs::remove_all(out);
}

}  // namespace
}  // namespace lutbake
