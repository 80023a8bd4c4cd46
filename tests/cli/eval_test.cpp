// `lutbake eval`: any table at any point, over the extreme grid, against the
// library's quadrature and the closed forms; sampled points reproduce the
// bake; bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lutbake/formats/binary_format.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/tables/bake.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

using test::Lutbake;

const char *kGridMu = "0,1e-7,1e-4,1e-3,0.01,0.1,0.5,0.9,1";
const char *kGridRoughness = "0,1e-4,1e-3,0.01,0.05,0.1,0.25,0.5,0.75,1";

std::vector<nlohmann::json> JsonLines(const std::string &text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// The whole extreme grid for one model through the command line: one JSON
// object per point, every value finite and in [0, 1], and within `tolerance`
// of the library's quadrature at 1e-12 (the mirror exactly).
void CheckGrid(const std::string &model, const std::string &settings, double tolerance) {
  const test::CommandResult run =
      Lutbake(std::string("eval --table dfg --mu ") + kGridMu + " --roughness " + kGridRoughness +
                  " " + model + " " + settings + " --json",
              true);
  ASSERT_EQ(run.status, 0) << run.output;
  const std::vector<nlohmann::json> lines = JsonLines(run.output);
  ASSERT_EQ(lines.size(), 90u);
  const NdfKind ndf =
      model.find("beckmann") != std::string::npos ? NdfKind::kBeckmann : NdfKind::kGgx;
  const SmithForm smith =
      model.find("separable") != std::string::npos ? SmithForm::kSeparable : SmithForm::kCorrelated;
  for (const nlohmann::json &p : lines) {
    const double mu = p["mu"], r = p["roughness"];
    const double a = p["value"][0], b = p["value"][1];
    ASSERT_TRUE(std::isfinite(a) && std::isfinite(b)) << p;
    EXPECT_GE(a, 0.0) << p;
    EXPECT_GE(b, 0.0) << p;
    EXPECT_LE(a + b, 1.0 + 4e-16) << p;
    const ReferenceAlbedo truth = IntegrateReferenceAlbedo(Ndf{ndf, r * r}, smith, mu);
    EXPECT_NEAR(a, truth.A, tolerance) << model << " " << settings << " " << p;
    EXPECT_NEAR(b, truth.B, tolerance) << model << " " << settings << " " << p;
    // The reported error bound holds.
    EXPECT_LE(std::abs(a - truth.A), double(p["error"][0]) + 1e-15) << p;
    if (r == 0.0) {
      EXPECT_EQ(p["estimator"], "exact");
      EXPECT_EQ(double(p["error"][0]), 0.0);
    }
  }
}

TEST(Eval, ExtremeGridByDefaultMatchesTheQuadrature) {
  for (const char *model :
       {"--ndf ggx --smith correlated", "--ndf ggx --smith separable",
        "--ndf beckmann --smith correlated", "--ndf beckmann --smith separable"})
    CheckGrid(model, "", 1e-9);
}

TEST(Eval, ExtremeGridWithToleranceOneE6) {
  CheckGrid("--ndf ggx", "--tolerance 1e-6", 1e-6);
  CheckGrid("--ndf beckmann --smith separable", "--tolerance 1e-6", 1e-6);
}

TEST(Eval, ExtremeGridSampledAtTheBakesDefault) {
  // --samples 65536 is the bake's default: within 1e-4 everywhere (the
  // measured worst is 7.9e-5, docs/tables.md "Extreme corners").
  CheckGrid("--ndf ggx", "--samples 65536", 1e-4);
}

TEST(Eval, SampledPointAtATexelCentreReproducesTheBake) {
  const std::filesystem::path out = test::Scratch("eval_bake");
  ASSERT_EQ(Lutbake("bake --out " + out.string() +
                    " --tables E,dfg,Eavg --size 4 --samples 4096 "
                    "--format bin --seed 9")
                .status,
            0);
  for (const char *name : {"E", "dfg"}) {
    const Table t = ReadBinaryTable((out / (std::string(name) + ".bin")).string());
    for (int y = 0; y < t.height(); ++y)
      for (int x = 0; x < t.width(); ++x) {
        const test::CommandResult run =
            Lutbake(std::string("eval --table ") + name + " --mu " +
                        FormatDouble(t.x.TexelCenter(x)) + " --roughness " +
                        FormatDouble(t.y.TexelCenter(y)) + " --samples 4096 --seed 9 --json",
                    true);
        ASSERT_EQ(run.status, 0);
        const nlohmann::json p = nlohmann::json::parse(run.output);
        for (int c = 0; c < t.channels; ++c) {
          const double v = t.channels == 2 ? double(p["value"][c]) : double(p["value"]);
          EXPECT_EQ(static_cast<float>(v), static_cast<float>(t.value(x, y, c)))
              << name << " " << x << "," << y;
        }
      }
  }
  const Table eavg = ReadBinaryTable((out / "Eavg.bin").string());
  const test::CommandResult run =
      Lutbake("eval --table Eavg --roughness " + FormatDouble(eavg.x.TexelCenter(2)) +
                  " --samples 4096 --seed 9 --json",
              true);
  EXPECT_EQ(static_cast<float>(double(nlohmann::json::parse(run.output)["value"])),
            static_cast<float>(eavg.values[2]));
  std::filesystem::remove_all(out);
}

TEST(Eval, AveragesAndFresnel) {
  const test::CommandResult eavg = Lutbake("eval --table Eavg --roughness 0,1 --json", true);
  ASSERT_EQ(eavg.status, 0);
  const std::vector<nlohmann::json> a = JsonLines(eavg.output);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(double(a[0]["value"]), 1.0);  // E_avg(0) = 1, exact
  EXPECT_NEAR(
      double(a[1]["value"]),
      IntegrateReferenceAlbedoAverage(Ndf{NdfKind::kGgx, 1.0}, SmithForm::kCorrelated).value, 1e-9);
  const test::CommandResult favg =
      Lutbake("eval --table Favg --fresnel dielectric --eta 1.0001,1.5,4,0.5 --json", true);
  ASSERT_EQ(favg.status, 0);
  const std::vector<nlohmann::json> f = JsonLines(favg.output);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_NEAR(double(f[1]["value"]), 0.091777959342351209, 1e-14);  // Favg.csv, mpmath
  // eta = 0.5 is the inside of eta = 2: 1 - (1 - F_avg(2)) / 4 (Favg.csv).
  EXPECT_NEAR(double(f[3]["value"]), 0.79014915926740148, 1e-14);
  const test::CommandResult schlick = Lutbake("eval --table Favg --f0 0,1", false);
  ASSERT_EQ(schlick.status, 0);
  EXPECT_NE(schlick.output.find("Favg 0.047619047619047616"), std::string::npos) << schlick.output;
  const test::CommandResult conductor =
      Lutbake("eval --table Favg --fresnel conductor --eta 0.2,1 --k 0,10 --json", true);
  ASSERT_EQ(conductor.status, 0);
  EXPECT_EQ(JsonLines(conductor.output).size(), 4u);
}

TEST(Eval, HumanOutputIsOneLinePerPoint) {
  const test::CommandResult run = Lutbake("eval --table E --mu 1e-7,0.5 --roughness 0,1e-4,0.3");
  ASSERT_EQ(run.status, 0);
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 6);
  EXPECT_NE(run.output.find("E 1  error 0  (exact)"), std::string::npos) << run.output;
}

// -v: first a line saying how the values are made, as the table's
// definition states it (the closed form of burley_E, the panel rule of E,
// the sampler when one is asked), then the points as without it.
TEST(Eval, VerboseSaysHowTheValuesAreMade) {
  struct Case {
    const char *options, *method;
  };
  for (const Case &c :
       {Case{"--table E --mu 0.5 --roughness 0.3", "lutbake eval: panel Gauss-Legendre quadrature"},
        Case{"--table burley_E --mu 0.5 --roughness 0.3", "lutbake eval: closed form: "},
        Case{"--table E --mu 0.5 --roughness 0.3 --samples 64",
             "lutbake eval: vndf with Owen-scrambled Sobol points"}}) {
    const test::CommandResult run = Lutbake("eval -v " + std::string(c.options));
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(run.output.rfind(c.method, 0), 0u) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 2) << run.output;
  }
}

TEST(Eval, BadInputIsRefused) {
  struct Bad {
    std::string args, mentions;
  };
  for (const Bad &bad : std::vector<Bad>{
           {"--table E --mu 0.5", "needs --roughness"},
           {"--table E --roughness 0.5", "needs --mu"},
           {"--table E --mu 2 --roughness 0.5", "[0, 1]"},
           {"--table E --mu 0.5 --roughness 1e-13", "0 (a mirror) or 1e-12 to 1"},
           {"--table E --mu 0.5 --roughness 1e-400", "out of range"},
           {"--table E --mu 0.5 --roughness nan", "not a number"},
           {"--table E --mu 0.5,x --roughness 0.1", "'x' is not a number"},
           {"--table Eavg --mu 0.5 --roughness 0.1", "--mu does not apply"},
           {"--table Favg --eta 1.5", "schlick takes --f0"},
           {"--table Favg --fresnel dielectric --eta 0", "1e-3 to 1000"},
           {"--table E --mu 0.5 --roughness 0.1 --f0 0.3", "only to --table Favg"},
           {"--table E --mu 0.5 --roughness 0.1 --estimator quadrature --samples 8",
            "not to --estimator quadrature"},
           {"--table X --mu 0.5 --roughness 0.1", "E, Eavg, Favg, dfg"},
       }) {
    const test::CommandResult run = Lutbake("eval " + bad.args);
    EXPECT_EQ(run.status, 2) << bad.args << "\n" << run.output;
    EXPECT_NE(run.output.find(bad.mentions), std::string::npos) << bad.args << "\n" << run.output;
  }
}

}  // namespace
}  // namespace lutbake
