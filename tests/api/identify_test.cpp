// check FILE --as TABLE and identify FILE (lutbake/api/identify.h) on
// tables the test makes itself in several engines' conventions, with known
// defects planted: transposed, flipped, one texel off, sRGB-encoded,
// separable Smith, Schlick-GGX, 8-bit banding. The planted values come from
// the tables' own evaluators at coordinates the test computes (texel
// centres, mu = (i + 0.5) / N), not from the presets' layout code that
// identify uses.
#include "lutbake/api/identify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "lutbake/core/error.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/image_reader.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

fs::path Scratch(const std::string &name) {
  const fs::path dir = fs::temp_directory_path() / ("lutbake_identify_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A file's texels: x fastest, row 0 first, channels interleaved.
struct Planted {
  int width = 0, height = 0, channels = 0;
  std::vector<double> values;
  double &at(int x, int y, int c) {
    return values[(static_cast<size_t>(y) * width + x) * channels + c];
  }
};

// The split sum {A, B} at x = mu, y = perceptual roughness, texel centres
// of an nx x ny grid shifted by (dx, dy) texels (the coordinate clamped to
// [0, 1], as a generator's min(u, 1)); smith "correlated" and "separable"
// through table dfg's own evaluator, "schlick-ggx-ibl" through the fitted
// panel quadrature (k = alpha / 2).
Planted Dfg(int nx, int ny, const std::string &smith, int dx = 0, int dy = 0) {
  Planted p{nx, ny, 2, std::vector<double>(static_cast<size_t>(nx) * ny * 2)};
  BakeSettings settings;
  settings.smith = smith == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const double mu = std::clamp((x + dx + 0.5) / nx, 0.0, 1.0);
      const double r = std::clamp((y + dy + 0.5) / ny, 0.0, 1.0);
      if (smith == "schlick-ggx-ibl") {
        const SplitSumQuadrature q = IntegrateFittedSplitSumQuadrature(
            r * r, FittedVisibility::kSchlickGgx, mu, kDefaultQuadratureTolerance);
        p.at(x, y, 0) = q.A;
        p.at(x, y, 1) = q.B;
      } else {
        const PointValue v = TableNamed("dfg").Evaluate(settings, mu, r);
        p.at(x, y, 0) = v.value[0];
        p.at(x, y, 1) = v.value[1];
      }
    }
  return p;
}

Planted Transposed(const Planted &p) {
  Planted out{p.height, p.width, p.channels, p.values};
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      for (int c = 0; c < p.channels; ++c)
        out.at(y, x, c) = p.values[(static_cast<size_t>(y) * p.width + x) * p.channels + c];
  return out;
}

Planted Flipped(Planted p, bool flipX, bool flipY) {
  const Planted in = p;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      for (int c = 0; c < p.channels; ++c)
        p.at(flipX ? p.width - 1 - x : x, flipY ? p.height - 1 - y : y, c) =
            in.values[(static_cast<size_t>(y) * p.width + x) * p.channels + c];
  return p;
}

Planted SrgbEncoded(Planted p) {
  for (double &v : p.values)
    v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return p;
}

// "const float lut[] = { ... };" with float32-exact literals (%.9g).
fs::path WriteArray(const fs::path &path, const Planted &p) {
  std::ofstream out(path);
  out << "// a table made by identify_test\nconst float lut[" << p.values.size() << "] = {\n";
  char text[32];
  for (double v : p.values) {
    std::snprintf(text, sizeof text, "%.9gf,\n", static_cast<float>(v));
    out << text;
  }
  out << "};\n";
  return path;
}

// An 8-bit RGB PNG: channel c of the table in R, G (B = 0), each value
// rounded to q / 255.
fs::path WritePng8(const fs::path &path, const Planted &p) {
  std::vector<uint8_t> rgb(static_cast<size_t>(p.width) * p.height * 3, 0);
  for (size_t t = 0; t < static_cast<size_t>(p.width) * p.height; ++t)
    for (int c = 0; c < std::min(p.channels, 3); ++c)
      rgb[3 * t + c] = static_cast<uint8_t>(std::lround(255.0 * p.values[t * p.channels + c]));
  WriteRgb8Png(path.string(), p.width, p.height, rgb);
  return path;
}

TableFileOutcome Identify(const fs::path &path) {
  TableFileRequest request;
  request.path = path.string();
  return IdentifyTable(request);
}

TableFileOutcome CheckAs(const fs::path &path, std::map<std::string, std::string> options) {
  TableFileRequest request;
  request.path = path.string();
  request.options = std::move(options);
  return CheckTableFile(request);
}

// What identify names, as its --json says it.
struct Expected {
  bool transposed = false, flipX = false, flipY = false;
  int offsetX = 0, offsetY = 0;
  std::string encoding = "linear", smith = "correlated";
};

void ExpectNamed(const TableFileOutcome &o, const Expected &e, double maxError) {
  const nlohmann::json j = nlohmann::json::parse(o.json);
  SCOPED_TRACE(o.text);
  EXPECT_TRUE(o.matched);
  EXPECT_TRUE(j["preset"].is_null());
  EXPECT_EQ(j["table"], "dfg");
  EXPECT_EQ(j["transposed"], e.transposed);
  EXPECT_EQ(j["flipX"], e.flipX);
  EXPECT_EQ(j["flipY"], e.flipY);
  EXPECT_EQ(j["offsetX"], e.offsetX);
  EXPECT_EQ(j["offsetY"], e.offsetY);
  EXPECT_EQ(j["encoding"], e.encoding);
  EXPECT_EQ(j["smith"], e.smith);
  EXPECT_LE(j["maxError"].get<double>(), maxError);
  EXPECT_LE(j["rmsError"].get<double>(), j["maxError"].get<double>());
}

// float32 literals: the table's value rounded to float (2^-24 relative),
// the integrators' 1e-8, and the sRGB round trip in float.
constexpr double kFloatExact = 2e-7;

TEST(Identify, NamesLutbakesOwnLayoutExactly) {
  const fs::path dir = Scratch("own");
  const TableFileOutcome o = Identify(WriteArray(dir / "dfg.h", Dfg(32, 32, "correlated")));
  ExpectNamed(o, {}, kFloatExact);
  EXPECT_TRUE(o.passed) << o.text;
  EXPECT_EQ(o.width, 32);
  EXPECT_EQ(o.channels, 2);
  EXPECT_EQ(o.storage, "text");
}

TEST(Identify, NamesEachPlantedDefect) {
  const fs::path dir = Scratch("defects");
  const Planted exact = Dfg(32, 32, "correlated");
  struct Case {
    const char *name;
    Planted table;
    Expected expected;
  };
  Expected transposed, flipX, flipY, below, left, srgb, separable, schlick;
  transposed.transposed = true;
  flipX.flipX = true;
  flipY.flipY = true;
  below.offsetY = 1;  // Filament's generator: row j holds roughness (j + 1.5) / N
  left.offsetX = -1;
  srgb.encoding = "srgb";
  separable.smith = "separable";
  schlick.smith = "schlick-ggx-ibl";
  const Case cases[] = {
      {"transposed", Transposed(exact), transposed},
      {"flipX", Flipped(exact, true, false), flipX},
      {"flipY", Flipped(exact, false, true), flipY},
      {"offsetY", Dfg(32, 32, "correlated", 0, 1), below},
      {"offsetX", Dfg(32, 32, "correlated", -1, 0), left},
      {"srgb", SrgbEncoded(exact), srgb},
      {"separable", Dfg(32, 32, "separable"), separable},
      {"schlick", Dfg(32, 32, "schlick-ggx-ibl"), schlick},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.name);
    ExpectNamed(Identify(WriteArray(dir / (std::string(c.name) + ".js"), c.table)), c.expected,
                kFloatExact * 4);
  }
}

TEST(Identify, NamesAFlippedEightBitTableWithItsBanding) {
  // 8 bits: every value within half a step of the exact one, and the flip
  // found through the banding. 48 x 40: not square, so the roughness rows
  // are told apart from the mu columns by the size as well.
  const fs::path dir = Scratch("banded");
  Expected flipY;
  flipY.flipY = true;
  const Planted banded = Flipped(Dfg(48, 40, "correlated"), false, true);
  const TableFileOutcome o = Identify(WritePng8(dir / "brdf.png", banded));
  ExpectNamed(o, flipY, 0.5 / 255 + 1e-7);
  EXPECT_EQ(o.storage, "unorm8");
  EXPECT_NE(o.sentence.find("y = roughness flipped"), std::string::npos) << o.sentence;
  EXPECT_NE(o.sentence.find("8-bit"), std::string::npos) << o.sentence;
  EXPECT_TRUE(o.passed);  // within half an 8-bit step everywhere
}

// A preset's texture as the preset writes it, its rows reversed when asked.
fs::path WritePresetTexture(const fs::path &dir, const std::string &presetName, bool flipRows) {
  const PresetTexture &texture = FindPreset(presetName)->textures.front();
  Table table = BakePresetTexture(texture, presetName);
  if (flipRows) {
    const Table in = table;
    for (int y = 0; y < table.height(); ++y)
      for (int x = 0; x < table.width(); ++x)
        for (int c = 0; c < table.channels; ++c)
          table.values[table.index(x, table.height() - 1 - y, c)] = in.values[in.index(x, y, c)];
  }
  const fs::path path = dir / texture.file;
  FindFormat(texture.format)->makeWriter()->Write(table, path.string(), WriteOptions{});
  return path;
}

TEST(Identify, NamesPresetsFromTheirOwnFiles) {
  const fs::path dir = Scratch("presets");
  const TableFileOutcome three = Identify(WritePresetTexture(dir, "threejs", false));
  const nlohmann::json j = nlohmann::json::parse(three.json);
  EXPECT_EQ(j["preset"], "threejs") << three.text;
  EXPECT_EQ(j["transposed"], false);
  EXPECT_EQ(j["flipY"], false);
  EXPECT_TRUE(three.passed) << three.text;  // half floats: within half an ulp

  // Unreal's 128 x 32 16-bit PNG with its rows the other way up.
  const TableFileOutcome unreal = Identify(WritePresetTexture(dir, "unreal", true));
  const nlohmann::json u = nlohmann::json::parse(unreal.json);
  EXPECT_EQ(u["preset"], "unreal") << unreal.text;
  EXPECT_EQ(u["smith"], "smith-joint-approx");
  EXPECT_EQ(u["flipY"], true);
  EXPECT_EQ(u["flipX"], false);
  EXPECT_LE(u["maxError"].get<double>(), 0.5 / 65535 + 1e-7);
}

TEST(CheckAs, ReportsAPlantedErrorItsSizeAndWhere) {
  const fs::path dir = Scratch("planted");
  Planted table = Dfg(32, 32, "correlated");
  const double planted = 0.01;
  table.at(5, 7, 0) += planted;
  const fs::path file = WriteArray(dir / "dfg.inc", table);
  const fs::path picture = dir / "error.png";
  const TableFileOutcome o = CheckAs(file, {{"as", "dfg"}, {"error-image", picture.string()}});
  EXPECT_FALSE(o.passed);
  EXPECT_NEAR(o.maxError, planted, kFloatExact);
  EXPECT_EQ(o.worstX, 5);
  EXPECT_EQ(o.worstY, 7);
  EXPECT_EQ(o.worstChannel, 0);
  EXPECT_DOUBLE_EQ(o.worstMu, 5.5 / 32);
  EXPECT_DOUBLE_EQ(o.worstRoughness, 7.5 / 32);
  EXPECT_EQ(o.valuesCompared, 32u * 32u * 2u);
  EXPECT_EQ(o.valuesAboveTolerance, 1u);
  // RMS: the one planted error over 2048 values, the rest float rounding.
  EXPECT_NEAR(o.rmsError, planted / std::sqrt(2048.0), 1e-6);
  // The picture: red (ten tolerances or more) at the planted texel only.
  const RawImage image = ReadPngImage(picture.string());
  ASSERT_EQ(image.width, 32);
  ASSERT_EQ(image.height, 32);
  ASSERT_EQ(image.channels, 3);
  int red = 0;
  for (int t = 0; t < 32 * 32; ++t)
    red += image.values[3 * t] == 1.0 && image.values[3 * t + 1] == 0.0;
  EXPECT_EQ(red, 1);
  EXPECT_EQ(image.values[3 * (7 * 32 + 5)], 1.0);

  table.at(5, 7, 0) -= planted;
  const TableFileOutcome clean = CheckAs(WriteArray(dir / "clean.inc", table), {{"as", "dfg"}});
  EXPECT_TRUE(clean.passed) << clean.text;
  EXPECT_LE(clean.maxError, kFloatExact);
}

TEST(CheckAs, EightBitErrorIsHalfAStep) {
  // Rounding 2048 values to 8 bits: every error at most half a step, and
  // the largest close to it (values spread over [0, 1] hit every phase).
  const fs::path dir = Scratch("eight");
  const TableFileOutcome o =
      CheckAs(WritePng8(dir / "lut.png", Dfg(32, 32, "correlated")), {{"as", "dfg"}});
  EXPECT_TRUE(o.passed) << o.text;
  EXPECT_LE(o.maxError, 0.5 / 255 + 1e-7);
  EXPECT_GE(o.maxError, 0.45 / 255);
  // Uniform rounding error: RMS step / sqrt(12).
  EXPECT_NEAR(o.rmsError, 1.0 / 255 / std::sqrt(12.0), 0.15 / 255);
}

TEST(CheckAs, TheRightConventionPassesAndTheWrongOneFails) {
  const fs::path dir = Scratch("conventions");
  const fs::path file = WriteArray(dir / "dfg.js", Flipped(Dfg(32, 32, "correlated"), false, true));
  const TableFileOutcome wrong = CheckAs(file, {{"as", "dfg"}});
  EXPECT_FALSE(wrong.passed);
  EXPECT_GT(wrong.maxError, 0.1);
  const TableFileOutcome right = CheckAs(file, {{"as", "dfg"}, {"flip", "y"}});
  EXPECT_TRUE(right.passed) << right.text;
  EXPECT_LE(right.maxError, kFloatExact);
  // Separable Smith checked as correlated: the difference of the two G2
  // at grazing, rough texels, far above float rounding.
  const fs::path separable = WriteArray(dir / "sep.js", Dfg(32, 32, "separable"));
  EXPECT_GT(CheckAs(separable, {{"as", "dfg"}}).maxError, 1e-2);
  EXPECT_TRUE(CheckAs(separable, {{"as", "dfg"}, {"smith", "separable"}}).passed);
  // The channels the other way (B, E as Filament and Godot store them).
  Planted be = Dfg(32, 32, "correlated");
  for (size_t t = 0; t < be.values.size(); t += 2) {
    const double a = be.values[t], b = be.values[t + 1];
    be.values[t] = b;
    be.values[t + 1] = a + b;
  }
  EXPECT_TRUE(CheckAs(WriteArray(dir / "be.js", be), {{"as", "dfg"}, {"channels", "B,E"}}).passed);
}

TEST(CheckAs, AForeignPngNamedDfgIsNoTableAndSaysSo) {
  // A picture, not a table: a colour gradient with a ripple.
  const fs::path dir = Scratch("foreign");
  Planted picture{40, 30, 3, std::vector<double>(40 * 30 * 3)};
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      picture.at(x, y, 0) = 0.5 + 0.5 * std::sin(0.7 * x + 0.3 * y);
      picture.at(x, y, 1) = y / 29.0;
      picture.at(x, y, 2) = 1.0 - x / 39.0;
    }
  const fs::path file = WritePng8(dir / "dfg.png", picture);
  const TableFileOutcome id = Identify(file);
  EXPECT_FALSE(id.matched) << id.text;
  EXPECT_NE(id.text.find("no known convention matches"), std::string::npos) << id.text;
  EXPECT_FALSE(nlohmann::json::parse(id.json)["matched"].get<bool>());
  const TableFileOutcome check = CheckAs(file, {{"as", "dfg"}});
  EXPECT_FALSE(check.passed);
  EXPECT_GT(check.maxError, 0.1);
  // In a bake's directory, the table reader says it is no lutbake table and
  // how to judge it, instead of naming a tEXt key.
  try {
    ReadPngTable(file.string());
    ADD_FAILURE() << "a foreign PNG was read as a table";
  } catch (const IoError &e) {
    EXPECT_NE(std::string(e.what()).find("not a table lutbake wrote"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("lutbake identify"), std::string::npos);
  }
}

TEST(CheckAs, UnreadableFilesAreUnreadableErrors) {
  const fs::path dir = Scratch("unreadable");
  const fs::path good = WritePng8(dir / "good.png", Dfg(8, 8, "correlated"));
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir / "cut.png", std::ios::binary) << bytes.substr(0, 40);
  std::ofstream(dir / "noise.bin", std::ios::binary) << std::string("\x01\x02\x03\x00\xff", 5);
  std::ofstream(dir / "words.txt") << "no numbers here at all\n";
  for (const char *name : {"missing.png", "cut.png", "noise.bin", "words.txt"}) {
    SCOPED_TRACE(name);
    const fs::path path = dir / name;
    EXPECT_THROW(Identify(path), UnreadableError);
    EXPECT_THROW(CheckAs(path, {{"as", "dfg"}}), UnreadableError);
  }
}

TEST(CheckAs, ConventionsThatDoNotFitAreUsageErrors) {
  const fs::path dir = Scratch("usage");
  const fs::path file = WriteArray(dir / "lut.h", Dfg(16, 16, "correlated"));
  EXPECT_THROW(CheckAs(file, {}), UsageError);                     // no convention
  EXPECT_THROW(CheckAs(file, {{"as", "DFG"}}), UsageError);        // no such table
  EXPECT_THROW(CheckAs(file, {{"preset", "godot"}}), UsageError);  // 128 x 128
  EXPECT_THROW(CheckAs(file, {{"as", "dfg"}, {"channels", "A,B,E"}}), UsageError);
  EXPECT_THROW(CheckAs(file, {{"as", "dfg"}, {"offset-x", "one"}}), UsageError);
}

}  // namespace
}  // namespace lutbake

namespace lutbake {
namespace {

TEST(CheckAs, ReadsEveryFormatAPresetCanBeWrittenIn) {
  // three.js's 16 x 16 table written by each writer, judged by the preset.
  const fs::path dir = Scratch("formats");
  const PresetTexture &texture = FindPreset("threejs")->textures.front();
  const Table table = BakePresetTexture(texture, "threejs");
  for (const char *format : {"exr", "dds", "dds-half", "ktx2", "ktx2-half", "png16", "inc",
                             "inc-half", "js-half", "glsl-array", "hlsl-array", "threejs-dfg"}) {
    SCOPED_TRACE(format);
    const TableFormat *f = FindFormat(format);
    ASSERT_NE(f, nullptr);
    const fs::path path = dir / (std::string(format) + f->extension);
    f->makeWriter()->Write(table, path.string(), WriteOptions{});
    const TableFileOutcome o = CheckAs(path, {{"preset", "threejs"}});
    EXPECT_TRUE(o.passed) << o.text;
    EXPECT_EQ(o.valuesCompared, 16u * 16u * 2u);
  }
}

// A Radiance HDR file of `p` (R, G = channels 0, 1; B = 0) in the new
// run-length form, each plane as literal runs of up to 128 bytes; values
// rounded to the nearest RGBE.
void WriteHdr(const fs::path &path, const Planted &p) {
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << p.height << " +X " << p.width << "\n";
  for (int y = 0; y < p.height; ++y) {
    std::vector<uint8_t> planes[4];
    for (int x = 0; x < p.width; ++x) {
      const double r = p.values[(static_cast<size_t>(y) * p.width + x) * 2];
      const double g = p.values[(static_cast<size_t>(y) * p.width + x) * 2 + 1];
      const double top = std::max(r, g);
      int e = 0;
      if (top > 1e-32) std::frexp(top, &e);  // top = f 2^e, f in [0.5, 1)
      const auto mantissa = [&](double v) {
        return top > 1e-32 ? static_cast<uint8_t>(std::min(255.0, std::floor(std::ldexp(v, 8 - e))))
                           : uint8_t{0};
      };
      planes[0].push_back(mantissa(r));
      planes[1].push_back(mantissa(g));
      planes[2].push_back(0);
      planes[3].push_back(top > 1e-32 ? static_cast<uint8_t>(e + 128) : 0);
    }
    out << static_cast<char>(2) << static_cast<char>(2) << static_cast<char>(p.width >> 8)
        << static_cast<char>(p.width & 255);
    for (const std::vector<uint8_t> &plane : planes)
      for (size_t at = 0; at < plane.size(); at += 128) {
        const size_t n = std::min<size_t>(128, plane.size() - at);
        out << static_cast<char>(n);
        out.write(reinterpret_cast<const char *>(&plane[at]), static_cast<std::streamsize>(n));
      }
  }
}

TEST(CheckAs, ReadsARadianceHdrWithinItsRgbeStep) {
  const fs::path dir = Scratch("hdr");
  const Planted exact = Dfg(16, 16, "correlated");
  WriteHdr(dir / "dfg.hdr", exact);
  const TableFileOutcome o = CheckAs(dir / "dfg.hdr", {{"as", "dfg"}});
  EXPECT_EQ(o.format, "Radiance HDR");
  EXPECT_EQ(o.storage, "rgbe");
  EXPECT_TRUE(o.passed) << o.text;
  EXPECT_GT(o.maxError, 0.0);  // the 8-bit mantissa's step shows
  EXPECT_LE(o.maxError, 1.0 / 128);
}

}  // namespace
}  // namespace lutbake
