// `lutbake furnace` through the command line: its JSON against the library
// and closed forms, refusals, atomic output, and the pictures read back.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "lutbake/models/blinn_phong.h"
#include "lutbake/validation/furnace_report.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

TEST(FurnaceCli, JsonHoldsTheClosedForms) {
  // Normalised Phong (n+1)/2pi at normal incidence: (n+1)/(n+2).
  const test::CommandResult r = test::Lutbake(
      "furnace --model phong --normalisation n+1 --parameter 3,30 --mu 1 --json", true);
  ASSERT_EQ(r.status, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["model"], "phong");
  EXPECT_EQ(j["options"]["normalisation"], "n+1");
  ASSERT_EQ(j["albedo"].size(), 2u);
  for (const auto &a : j["albedo"]) {
    const double n = a["parameter"];
    EXPECT_NEAR(a["value"].get<double>(), (n + 1) / (n + 2), a["error"].get<double>());
  }
  ASSERT_EQ(j["average"].size(), 2u);
  // The worst loss is the largest 1 - albedo: n = 3 gives 1/5.
  EXPECT_NEAR(j["worst"]["loss"]["amount"].get<double>(), 0.2, 1e-9);
  EXPECT_EQ(j["worst"]["loss"]["parameter"].get<double>(), 3.0);
  // Normalised Phong at n = 3 never reflects more than it receives.
  EXPECT_TRUE(j["worst"]["gain"].is_null()) << j["worst"].dump();
}

TEST(FurnaceCli, RefusesBadInput) {
  struct Case {
    std::string args, says;
  };
  for (const Case &c : std::vector<Case>{
           {"furnace --model torrance", "lambert, phong, blinn-phong"},
           {"furnace --model phong --normalisation n+8", "accepted: none, n+1, n+2"},
           {"furnace --model oren-nayar --parameter 2", "sigma in radians in [0, pi/2]"},
           {"furnace --model microfacet --parameter 0.5,x", "'x' is not a number"},
           {"furnace --model eon --mu 1.5", "view cosines in [0, 1]"},
           {"furnace --model lambert --compensation", "applies only to --model microfacet"},
           {"furnace --model microfacet --f0 0.04 --eta 1.5", "exclude each other"},
           {"furnace --model oren-nayar --variant exact", "accepted: full, qualitative"},
       }) {
    const test::CommandResult r = test::Lutbake(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
  }
  // An --out that is a file: usage error, nothing written.
  const std::filesystem::path dir = test::Scratch("furnace_file");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "plain") << "x";
  const test::CommandResult r =
      test::Lutbake("furnace --model lambert --out " + (dir / "plain").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(test::FileNames(dir), std::vector<std::string>{"plain"});
  std::filesystem::remove_all(dir);
}

// Reads a one-channel or RGB image into floats (OpenImageIO converts 8 bits
// to [0, 1]).
std::vector<float> ReadImage(const std::string &path, int *width, int *height, int *channels) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  const OIIO::ImageSpec &spec = in->spec();
  *width = spec.width;
  *height = spec.height;
  *channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  return pixels;
}

TEST(FurnaceCli, PicturesMatchTheNumbers) {
  // Blinn-Phong with (n+8)/8pi: gains at normal incidence (the sphere's
  // centre) and loses at grazing (its rim).
  const std::filesystem::path dir = test::Scratch("furnace_pictures");
  const test::CommandResult r = test::Lutbake(
      "furnace --model blinn-phong --normalisation n+8 --parameter 1,10 --mu 0,0.5,1 --out " +
      dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(
      test::FileNames(dir),
      (std::vector<std::string>{"furnace.csv", "furnace.json", "furnace_plot.png",
                                "furnace_plot.svg", "furnace_spheres.exr", "furnace_spheres.png"}));
  std::ifstream jsonFile(dir / "furnace.json");
  const nlohmann::json j = nlohmann::json::parse(jsonFile);
  // The albedo at mu = 1 for n = 10 against the exact normalisation's ratio.
  const double expected = BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kNPlus8, 10) /
                          BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kExact, 10);
  double atNormal = 0, atNormalError = 0;
  for (const auto &a : j["albedo"])
    if (a["parameter"] == 10.0 && a["mu"] == 1.0) atNormal = a["value"], atNormalError = a["error"];
  EXPECT_NEAR(atNormal, expected, atNormalError);

  int w = 0, h = 0, c = 0;
  const std::vector<float> exr = ReadImage((dir / "furnace_spheres.exr").string(), &w, &h, &c);
  ASSERT_EQ(c, 1);
  EXPECT_EQ(w, kSphereGap + 2 * (kSphereDiameter + kSphereGap));
  EXPECT_EQ(h, kSphereDiameter + 2 * kSphereGap);
  int wp = 0, hp = 0, cp = 0;
  const std::vector<float> png = ReadImage((dir / "furnace_spheres.png").string(), &wp, &hp, &cp);
  ASSERT_EQ(wp, w);
  ASSERT_EQ(cp, 1);
  // Background: 1 (EXR), 128/255 (PNG).
  EXPECT_EQ(exr[0], 1.0f);
  EXPECT_NEAR(png[0], 128.0f / 255.0f, 1e-6);
  // Each sphere's pixels: mu = sqrt(1 - x^2 - y^2) at the pixel centre, the
  // albedo linear between the values at mu = k/128, which at the grid's
  // mu = 0.5 and 1 are the JSON's. Pixel near the centre: mu ~ 1.
  for (int p = 0; p < 2; ++p) {
    const double n = p == 0 ? 1.0 : 10.0;
    double json1 = 0, json05 = 0, err = 0;
    for (const auto &a : j["albedo"])
      if (a["parameter"] == n) {
        if (a["mu"] == 1.0) json1 = a["value"], err = a["error"];
        if (a["mu"] == 0.5) json05 = a["value"];
      }
    const int x0 = kSphereGap + p * (kSphereDiameter + kSphereGap), y0 = kSphereGap;
    const double radius = 0.5 * kSphereDiameter;
    for (int y = 0; y < kSphereDiameter; y += 3)
      for (int x = 0; x < kSphereDiameter; x += 3) {
        const double dx = (x + 0.5 - radius) / radius, dy = (y + 0.5 - radius) / radius;
        if (dx * dx + dy * dy >= 1.0) continue;
        const size_t i = static_cast<size_t>(y0 + y) * w + x0 + x;
        const double mu = std::sqrt(1.0 - dx * dx - dy * dy);
        // Bracketed by the albedo at the neighbouring grid points, which
        // for mu near 1 and 0.5 we know from the JSON.
        if (std::abs(mu - 1.0) < 1e-3) {
          EXPECT_NEAR(exr[i], json1, 2e-3 + err) << p;
        }
        if (std::abs(mu - 0.5) < 1e-3) {
          EXPECT_NEAR(exr[i], json05, 2e-3 + err) << p;
        }
        // PNG = round(255 albedo / 2) / 255, within half a step of 8 bits.
        EXPECT_NEAR(png[i], std::min(1.0, 0.5 * exr[i]), 0.5 / 255.0 + 1e-6);
      }
  }
  // The plot PNG opens and has the SVG's size.
  const std::vector<float> plot = ReadImage((dir / "furnace_plot.png").string(), &w, &h, &c);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 400);
  EXPECT_EQ(c, 3);
  std::filesystem::remove_all(dir);
}

TEST(FurnaceCli, CompensatedSpheresVanish) {
  // Compensated GGX with F = 1 conserves energy: every sphere pixel is 1
  // within the albedo errors and float32 rounding.
  const std::filesystem::path dir = test::Scratch("furnace_vanish");
  const test::CommandResult r = test::Lutbake(
      "furnace --model microfacet --compensation --parameter 0.3,1 --mu 0.5 --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  int w = 0, h = 0, c = 0;
  const std::vector<float> exr = ReadImage((dir / "furnace_spheres.exr").string(), &w, &h, &c);
  float worst = 0;
  for (float v : exr) worst = std::max(worst, std::abs(v - 1.0f));
  EXPECT_LE(worst, 1e-7f);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
