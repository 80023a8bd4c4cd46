// The Babylon.js preset: its files read back by readers of their own (the
// PNGs by OpenImageIO, the DDS bytes here) and decoded as Babylon decodes
// them (fromRGBD, written out again here), against lutbake's exact values
// at Babylon's texels; the RGBD divisor against a brute force over every
// divisor and byte; and Babylon's own shipped textures (tests/data/presets/
// babylon/) read in the preset's layout.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "lutbake/lutbake.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/table_definition.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

// Babylon's fromRGBD with useExactSrgbConversions off: pow(rgb, 2.2) / a.
double FromRgbd(int byte, int alpha) { return std::pow(byte / 255.0, 2.2) / (alpha / 255.0); }

// An 8-bit image as its bytes (alpha as stored, not premultiplied).
struct Bytes8 {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> data;
  int at(int x, int y, int c) const {
    return data[(static_cast<size_t>(y) * width + x) * channels + c];
  }
};

Bytes8 ReadPngBytes(const std::string &path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  Bytes8 image;
  if (!in) return image;
  image.width = in->spec().width;
  image.height = in->spec().height;
  image.channels = in->spec().nchannels;
  image.data.resize(static_cast<size_t>(image.width) * image.height * image.channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT8, image.data.data()));
  return image;
}

// IEEE binary16 bits to double, written out here.
double HalfBits(unsigned bits) {
  const int sign = (bits >> 15) & 1, exponent = (bits >> 10) & 31, mantissa = bits & 1023;
  const double magnitude =
      exponent == 0 ? std::ldexp(mantissa, -24) : std::ldexp(1024 + mantissa, exponent - 25);
  return sign ? -magnitude : magnitude;
}

// The RGBA16F texels of a DX10 DDS (header 148 bytes), as doubles.
std::vector<double> ReadDdsHalves(const std::string &path, int *width, int *height) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
  const auto u32 = [&](size_t at) {
    return static_cast<uint32_t>(bytes[at]) | static_cast<uint32_t>(bytes[at + 1]) << 8 |
           static_cast<uint32_t>(bytes[at + 2]) << 16 | static_cast<uint32_t>(bytes[at + 3]) << 24;
  };
  EXPECT_EQ(u32(128), 10u) << "DXGI_FORMAT_R16G16B16A16_FLOAT";
  *height = static_cast<int>(u32(12));
  *width = static_cast<int>(u32(16));
  std::vector<double> values(static_cast<size_t>(*width) * *height * 4);
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = HalfBits(bytes[148 + 2 * i] | bytes[148 + 2 * i + 1] << 8);
  return values;
}

// lutbake's exact values at Babylon's texel (i, j) of N: NdotV = (i + 0.5)
// / N, perceptualRoughness = (j + 0.5) / N, through the tables (not the
// preset): B, E and the sheen albedo (Ashikhmin, alpha = r^2), or B, E and
// C (f82); their bounds.
struct Texel {
  double value[3], bound[3];
};
Texel ExactTexel(bool openpbr, int i, int j, int n) {
  const double mu = (i + 0.5) / n, r = (j + 0.5) / n;
  const PointValue dfg = TableNamed("dfg").Evaluate(BakeSettings{}, mu, r);
  Texel t{{dfg.value[1], dfg.value[0] + dfg.value[1], 0.0},
          {dfg.error[1], dfg.error[0] + dfg.error[1], 0.0}};
  PointValue third;
  if (openpbr) {
    third = TableNamed("f82").Evaluate(BakeSettings{}, mu, r);
  } else {
    BakeSettings sheen;
    sheen.sheenVisibility = SheenVisibility::kAshikhmin;
    sheen.sheenAlpha = SheenAlpha::kSquared;
    third = TableNamed("sheen_E").Evaluate(sheen, mu, r);
  }
  t.value[2] = third.value[0];
  t.bound[2] = third.error[0];
  return t;
}

// Texels every `stride` on both axes, and the first two rows and columns
// (the grazing and smooth edges, where the values change fastest).
std::vector<std::pair<int, int>> SampleTexels(int n, int stride) {
  std::vector<std::pair<int, int>> texels;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if ((i % stride == 0 && j % stride == 0) || i < 2 || j < 2) texels.emplace_back(i, j);
  return texels;
}

double ErrorMaxOf(const nlohmann::json &manifest, const std::string &file) {
  for (const auto &f : manifest["files"])
    if (f["file"] == file) return f["errorMax"];
  ADD_FAILURE() << file << " is not in preset.json";
  return 0.0;
}

// Every file of the preset, read back by OpenImageIO (PNG) or here (DDS)
// and decoded as Babylon decodes it, holds lutbake's exact value at
// Babylon's texels within the errorMax preset.json states, the OpenPBR z
// in its stored, times-16, units; `lutbake check` passes the directory.
TEST(Presets, BabylonFilesDecodeToTheExactValues) {
  const auto dir = test::Scratch("preset_babylon");
  BakeRequest request = test::BakeRequestFor(dir);
  request.preset = "babylon";
  Bake(request);
  std::ifstream in(dir / "preset.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["files"][0]["storage"], "rgbd8");
  EXPECT_EQ(manifest["files"][2]["storage"], "rgbd8");
  EXPECT_EQ(manifest["files"][3]["storage"], "half");
  for (const bool openpbr : {false, true}) {
    const int n = openpbr ? 128 : 256;
    const std::string name = openpbr ? "openPBREnvironmentBRDFTexture" : "environmentBRDFTexture";
    const Bytes8 png = ReadPngBytes((dir / (name + ".png")).string());
    ASSERT_EQ(png.width, n);
    ASSERT_EQ(png.height, n);
    ASSERT_EQ(png.channels, 4);
    int ddsWidth = 0, ddsHeight = 0;
    const std::vector<double> dds =
        ReadDdsHalves((dir / (name + ".dds")).string(), &ddsWidth, &ddsHeight);
    ASSERT_EQ(ddsWidth, n);
    ASSERT_EQ(ddsHeight, n);
    const double pngMax = ErrorMaxOf(manifest, name + ".png");
    const double ddsMax = ErrorMaxOf(manifest, name + ".dds");
    double worstPng = 0.0, worstDds = 0.0;
    for (const auto &[i, j] : SampleTexels(n, 7)) {
      const Texel exact = ExactTexel(openpbr, i, j, n);
      for (int c = 0; c < 3; ++c) {
        // The file's z holds 16 C: its bound is in those units.
        const double scale = openpbr && c == 2 ? 16.0 : 1.0;
        const double stored = FromRgbd(png.at(i, j, c), png.at(i, j, 3));
        const double fromDds = dds[(static_cast<size_t>(j) * n + i) * 4 + c];
        const double dPng = std::abs(stored - scale * exact.value[c]);
        const double dDds = std::abs(fromDds - scale * exact.value[c]);
        worstPng = std::max(worstPng, dPng);
        worstDds = std::max(worstDds, dDds);
        ASSERT_LE(dPng, pngMax + scale * exact.bound[c])
            << name << " " << i << " " << j << " " << c;
        ASSERT_LE(dDds, ddsMax + scale * exact.bound[c])
            << name << " " << i << " " << j << " " << c;
      }
      EXPECT_EQ(dds[(static_cast<size_t>(j) * n + i) * 4 + 3], 1.0);
    }
    // The stated bounds are those of the stored values, not loose: the
    // sampled texels (which include the grazing, smooth corner where the
    // PNG's largest error lies) reach a third of them.
    EXPECT_GE(worstPng, pngMax / 3) << name;
    EXPECT_LE(ddsMax, openpbr ? 1e-3 : 3e-2) << name;  // half of values up to 42
    std::cout << name << ": PNG errorMax " << pngMax << ", worst sampled " << worstPng
              << "; DDS errorMax " << ddsMax << ", worst sampled " << worstDds << "\n";
  }
  const PresetCheck checked = CheckPresetDirectory(dir.string());
  EXPECT_TRUE(checked.pass) << checked.json;
}

// The smallest max-norm error of a texel in RGBD over every divisor and
// every byte (no bracketing, no table shared with lutbake).
double BestRgbdError(const double *values) {
  double best = 1e300;
  for (int d = 1; d <= 255; ++d) {
    double texel = 0.0;
    for (int c = 0; c < 3; ++c) {
      double channel = 1e300;
      for (int q = 0; q <= 255; ++q)
        channel = std::min(channel, std::abs(FromRgbd(q, d) - values[c]));
      texel = std::max(texel, channel);
    }
    best = std::min(best, texel);
  }
  return best;
}

// The divisor of each texel the PNG holds: within 1.5x of the best the
// encoding allows (by brute force), and never worse than Babylon's own
// toRGBD rule d = floor(255 / max v), bytes rounded in gamma space.
TEST(Presets, BabylonRgbdDivisorIsNearTheBest) {
  const auto dir = test::Scratch("preset_babylon_rgbd");
  BakeRequest request = test::BakeRequestFor(dir);
  request.preset = "babylon";
  request.presetFiles =
      std::vector<std::string>{"environmentBRDFTexture.png", "openPBREnvironmentBRDFTexture.png"};
  Bake(request);
  int worseThanBabylon = 0, texels = 0;
  double worstRatio = 0.0;
  for (const bool openpbr : {false, true}) {
    const int n = openpbr ? 128 : 256;
    const Bytes8 png = ReadPngBytes(
        (dir / (openpbr ? "openPBREnvironmentBRDFTexture.png" : "environmentBRDFTexture.png"))
            .string());
    ASSERT_EQ(png.width, n);
    for (const auto &[i, j] : SampleTexels(n, 37)) {
      const Texel exact = ExactTexel(openpbr, i, j, n);
      double v[3] = {exact.value[0], exact.value[1], exact.value[2] * (openpbr ? 16.0 : 1.0)};
      double stored = 0.0, babylon = 0.0;
      const double largest = std::max({v[0], v[1], v[2]});
      const int babylonD = std::clamp(static_cast<int>(std::floor(255.0 / largest)), 1, 255);
      for (int c = 0; c < 3; ++c) {
        stored = std::max(stored, std::abs(FromRgbd(png.at(i, j, c), png.at(i, j, 3)) - v[c]));
        const double gamma = std::pow(v[c] * babylonD / 255.0, 1 / 2.2);
        const int q = std::min(255, static_cast<int>(std::floor(gamma * 255 + 0.5)));
        babylon = std::max(babylon, std::abs(FromRgbd(q, babylonD) - v[c]));
      }
      const double best = BestRgbdError(v);
      ASSERT_LE(stored, 1.5 * best + 1e-15) << i << " " << j << " " << openpbr;
      worstRatio = std::max(worstRatio, best > 0 ? stored / best : 1.0);
      worseThanBabylon += stored > babylon + 1e-15;
      ++texels;
    }
  }
  EXPECT_EQ(worseThanBabylon, 0);
  std::cout << texels << " texels: stored error / best " << worstRatio << " at most\n";
}

// Babylon's own shipped textures, decoded as Babylon decodes them: they
// agree with the preset's layout (NdotV on x, roughness on y, PNG row 0 at
// roughness 0.5 / N) to their own error, and not transposed or flipped.
TEST(Presets, BabylonShippedTexturesMatchThePresetsLayout) {
  for (const bool openpbr : {false, true}) {
    const int n = openpbr ? 128 : 256;
    const Bytes8 shipped =
        ReadPngBytes(test::DataPath(openpbr ? "presets/babylon/openPBREnvironmentBRDF.png"
                                            : "presets/babylon/environmentBRDF.png"));
    ASSERT_EQ(shipped.width, n);
    // E (channel y) decides the layout: smooth in neither axis, and the
    // flip and transpose move it by 0.1 or more over most of the table.
    std::vector<double> asLaid, transposed, flipped;
    for (const auto &[i, j] : SampleTexels(n, 9)) {
      if (i < 2 || j < 2) continue;  // the grid only
      const double e = ExactTexel(openpbr, i, j, n).value[1];
      const auto read = [&](int x, int y) {
        return FromRgbd(shipped.at(x, y, 1), shipped.at(x, y, 3));
      };
      asLaid.push_back(std::abs(read(i, j) - e));
      transposed.push_back(std::abs(read(j, i) - e));
      flipped.push_back(std::abs(read(i, n - 1 - j) - e));
    }
    const auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    std::cout << (openpbr ? "OpenPBR" : "BRDF") << " E: median |shipped - exact| " << median(asLaid)
              << ", transposed " << median(transposed) << ", flipped " << median(flipped) << "\n";
    // Half an 8-bit step of pow 2.2 near E = 0.9 is 4.2e-3.
    EXPECT_LT(median(asLaid), 6e-3);
    EXPECT_GT(median(transposed), 10 * median(asLaid));
    EXPECT_GT(median(flipped), 10 * median(asLaid));
  }
}

// Zeltner's published table (tests/data/presets/babylon/), [alpha index
// i][cos index j][a, b, R], and its bilinear value, written out here.
using ZeltnerTable = std::vector<std::array<double, 3>>;
ZeltnerTable ReadZeltner() {
  ZeltnerTable table(32 * 32);
  for (const test::CsvRow &row :
       test::ReadCsv(test::DataPath("presets/babylon/zeltner_ltc_volume.csv")))
    table[static_cast<size_t>(row.Number("i") * 32 + row.Number("j"))] = {
        row.Number("a"), row.Number("b"), row.Number("R")};
  return table;
}
double ZeltnerAt(const ZeltnerTable &t, double alpha, double mu, int c) {
  const double x = alpha * 31, y = mu * 31;
  const int i = std::min(30, static_cast<int>(x)), j = std::min(30, static_cast<int>(y));
  const double fx = x - i, fy = y - j;
  const auto at = [&](int a, int b) { return t[static_cast<size_t>(a * 32 + b)][c]; };
  return (1 - fx) * ((1 - fy) * at(i, j) + fy * at(i, j + 1)) +
         fx * ((1 - fy) * at(i + 1, j) + fy * at(i + 1, j + 1));
}

// Babylon's fuzz ranges: value = low + (high - low) x.
constexpr double kFuzzLow[3] = {0.005, -0.18, 0.0}, kFuzzHigh[3] = {0.88, 0.002, 0.75};

// The fuzz texture, read by OpenImageIO and decoded as Babylon's expansion
// decodes it (fromRGBD) and then getFuzzBRDFLookup (the ranges), holds
// Zeltner's table at the coordinates Babylon's lookup samples, x = alpha =
// (i + 0.5) / 32 and y = NdotV = (j + 0.5) / 32, within the errorMax
// preset.json states (range-normalised units); the DDS holds them to half.
TEST(Presets, BabylonFuzzTextureDecodesToZeltnersTable) {
  const auto dir = test::Scratch("preset_babylon_fuzz");
  BakeRequest request = test::BakeRequestFor(dir);
  request.preset = "babylon";
  request.presetFiles =
      std::vector<std::string>{"environmentFuzzBRDFTexture.png", "environmentFuzzBRDFTexture.dds"};
  Bake(request);
  std::ifstream in(dir / "preset.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  const double pngMax = ErrorMaxOf(manifest, "environmentFuzzBRDFTexture.png");
  const double ddsMax = ErrorMaxOf(manifest, "environmentFuzzBRDFTexture.dds");
  const Bytes8 png = ReadPngBytes((dir / "environmentFuzzBRDFTexture.png").string());
  ASSERT_EQ(png.width, 32);
  ASSERT_EQ(png.channels, 4);
  int w = 0, h = 0;
  const std::vector<double> dds =
      ReadDdsHalves((dir / "environmentFuzzBRDFTexture.dds").string(), &w, &h);
  ASSERT_EQ(w, 32);
  const ZeltnerTable zeltner = ReadZeltner();
  double worst = 0.0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i)
      for (int c = 0; c < 3; ++c) {
        const double range = kFuzzHigh[c] - kFuzzLow[c];
        // What the shader reads, in Babylon's units, and the table there
        // (the bound covers the clamp to Babylon's range too).
        const double read = kFuzzLow[c] + range * FromRgbd(png.at(i, j, c), png.at(i, j, 3));
        const double want = ZeltnerAt(zeltner, (i + 0.5) / 32, (j + 0.5) / 32, c);
        worst = std::max(worst, std::abs(read - want) / range);
        ASSERT_LE(std::abs(read - want), range * pngMax + 1e-12) << i << " " << j << " " << c;
        const double fromDds = kFuzzLow[c] + range * dds[(static_cast<size_t>(j) * 32 + i) * 4 + c];
        ASSERT_LE(std::abs(fromDds - want), range * ddsMax + 1e-12) << i << " " << j << " " << c;
      }
  // The largest error is the clamp: a = 0.0000 (alpha -> 0) below a's
  // range [0.005, 0.88], 0.005 / 0.875 = 5.7e-3 normalised.
  EXPECT_GE(worst, pngMax / 2);
  EXPECT_LT(pngMax, 6e-3);
  std::cout << "fuzz: errorMax " << pngMax << " (normalised), worst " << worst << "\n";
  EXPECT_TRUE(CheckPresetDirectory(dir.string()).pass);
}

// Babylon's shipped fuzz texture holds Zeltner's entry (i, j) in texel
// (x = i, y = j) linearly: read as bytes / 255 it agrees to its 8 bits,
// but Babylon's expansion reads pow(bytes / 255, 2.2), which is far off.
TEST(Presets, BabylonShippedFuzzTextureIsLinearButDecodedWithPow22) {
  const Bytes8 shipped = ReadPngBytes(test::DataPath("presets/babylon/environmentFuzzBRDF.png"));
  ASSERT_EQ(shipped.width, 32);
  ASSERT_EQ(shipped.channels, 3);
  const ZeltnerTable zeltner = ReadZeltner();
  double linear[3] = {0, 0, 0}, expanded[3] = {0, 0, 0};
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i)
      for (int c = 0; c < 3; ++c) {
        const double range = kFuzzHigh[c] - kFuzzLow[c];
        const double entry = zeltner[static_cast<size_t>(i * 32 + j)][c];
        const double byte = shipped.at(i, j, c) / 255.0;
        linear[c] = std::max(linear[c], std::abs(kFuzzLow[c] + range * byte - entry));
        expanded[c] =
            std::max(expanded[c], std::abs(kFuzzLow[c] + range * std::pow(byte, 2.2) - entry));
      }
  for (int c = 0; c < 3; ++c) {
    std::cout << "channel " << c << ": linear " << linear[c] << ", as Babylon decodes "
              << expanded[c] << "\n";
    EXPECT_LT(linear[c], 0.01) << c;
    EXPECT_GT(expanded[c], 0.04) << c;
  }
}

}  // namespace
}  // namespace lutbake
