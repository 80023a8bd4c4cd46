// Round trips of the three formats: EXR read back through OpenImageIO (an
// independent reader), .bin through its documented layout, and the C++
// header compiled with -Werror and checked through its own lookups.
#include "lutbake/formats/writer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string &name) {
  const fs::path dir =
      fs::temp_directory_path() / ("lutbake_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Writes dir/main.cpp (the includes, then `checks` as statements that add
// to `fail`) and expects it to compile as an engine would and report no
// failure, in C++17 and C++20.
void ExpectHeadersPass(const fs::path &dir, const std::string &includes,
                       const std::string &checks) {
  std::ofstream(dir / "main.cpp") << "#include <cmath>\n#include <cstdio>\n"
                                  << includes << "int main() {\n  int fail = 0;\n"
                                  << checks
                                  << "  std::printf(\"%d failures\\n\", fail);\n"
                                     "  return fail == 0 ? 0 : 1;\n}\n";
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(dir, "c++17", "c++20");
}

Table SmallTable(const TableDefinition *kind, int size = 8) {
  BakeSettings s;
  s.size = size;
  s.samples = 64;
  s.depthSize = 1;  // 3D tables: one slice, at eta = 1 (the format is what is tested)
  s.commandLine = "lutbake bake --test";
  return BakeTable(*kind, s);
}

TEST(ExrWriter, ReadsBackThroughOpenImageIO) {
  const fs::path dir = TempDir("exr");
  for (const TableDefinition *kind : AllTables()) {
    const Table t = SmallTable(kind, 6);
    const std::string path = (dir / (std::string(kind->Name()) + ".exr")).string();
    MakeExrWriter()->Write(t, path, {});
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec &spec = in->spec();
    EXPECT_EQ(spec.width, t.width());
    EXPECT_EQ(spec.height, t.height());
    ASSERT_EQ(spec.nchannels, t.channels);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    // EXR keeps its channels sorted by name (ltc_ggx's six come back as
    // fresnel, m00, ...): each of the table's channels by its name.
    std::vector<size_t> fileChannel;
    for (int c = 0; c < t.channels; ++c) {
      const auto it =
          std::find(spec.channelnames.begin(), spec.channelnames.end(), t.channelNames[c]);
      ASSERT_NE(it, spec.channelnames.end()) << t.channelNames[c];
      fileChannel.push_back(static_cast<size_t>(it - spec.channelnames.begin()));
    }
    if (t.channels <= 2) {  // Y; R, G: in the table's order
      for (int c = 0; c < t.channels; ++c) EXPECT_EQ(fileChannel[c], static_cast<size_t>(c));
    }
    EXPECT_EQ(spec.get_string_attribute("table"), kind->Name());
    EXPECT_EQ(spec.get_string_attribute("commandLine"), "lutbake bake --test");
    EXPECT_FALSE(spec.get_string_attribute("texelConvention").empty());
    // errorMax bounds the stored float32 values: the largest integration
    // bound plus rounding, each rounded up to float32 (storage.h).
    const BoundSummary stored = SummarizeStoredBounds(t, ValueType::kFloat32);
    EXPECT_DOUBLE_EQ(spec.get_float_attribute("errorMax"), static_cast<float>(stored.max));
    EXPECT_GE(stored.max, t.MaxError());
    EXPECT_EQ(spec.get_string_attribute("errorStorage"), "float32");
    EXPECT_EQ(spec.find_attribute("DateTime"), nullptr);
    std::vector<float> pixels(t.values.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, t.channels, OIIO::TypeDesc::FLOAT, pixels.data()));
    // Scanline 0 of the file is texel row y = 0 (the smoothest row).
    const size_t channels = static_cast<size_t>(t.channels);
    for (size_t i = 0; i < pixels.size(); ++i)
      ASSERT_EQ(pixels[i - i % channels + fileChannel[i % channels]],
                static_cast<float>(t.values[i]))
          << i;
  }
  fs::remove_all(dir);
}

TEST(ExrWriter, SameTableGivesSameBytes) {
  const fs::path dir = TempDir("exrbytes");
  const Table t = SmallTable(&TableNamed("dfg"));
  MakeExrWriter()->Write(t, (dir / "a.exr").string(), {});
  MakeExrWriter()->Write(t, (dir / "b.exr").string(), {});
  std::ifstream a(dir / "a.exr", std::ios::binary), b(dir / "b.exr", std::ios::binary);
  const std::string sa((std::istreambuf_iterator<char>(a)), {}),
      sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_FALSE(sa.empty());
  EXPECT_EQ(sa, sb);
  fs::remove_all(dir);
}

TEST(BinaryWriter, RoundTrip) {
  const fs::path dir = TempDir("bin");
  for (const TableDefinition *kind : AllTables()) {
    const Table t = SmallTable(kind, 5);
    const std::string path = (dir / "t.bin").string();
    MakeBinaryWriter()->Write(t, path, {});
    const Table back = ReadBinaryTable(path);
    EXPECT_EQ(back.width(), t.width());
    EXPECT_EQ(back.height(), t.height());
    EXPECT_EQ(back.channels, t.channels);
    EXPECT_EQ(back.is2D(), t.is2D());
    EXPECT_EQ(back.x.name, t.x.name);
    EXPECT_EQ(back.x.min, t.x.min);
    EXPECT_EQ(back.x.max, t.x.max);
    EXPECT_EQ(back.y.name, t.y.name);
    ASSERT_EQ(back.values.size(), t.values.size());
    for (size_t i = 0; i < t.values.size(); ++i) {
      const double stored = static_cast<double>(static_cast<float>(t.values[i]));
      EXPECT_EQ(back.values[i], stored);
      // The error block bounds the stored value: the integration bound plus
      // the rounding, rounded up to a float32.
      EXPECT_EQ(back.errors[i], StoredBound(t.values[i], t.errors[i], ValueType::kFloat32));
      EXPECT_GE(back.errors[i], t.errors[i] + std::abs(stored - t.values[i]));
      EXPECT_EQ(back.errors[i], static_cast<double>(static_cast<float>(back.errors[i])));
    }
    ASSERT_NE(back.FindMetadata("table"), nullptr);
    EXPECT_EQ(*back.FindMetadata("table"), kind->Name());
  }
  // A truncated file is refused, not misread.
  std::string bytes;
  {
    std::ifstream in(dir / "t.bin", std::ios::binary);
    bytes.assign((std::istreambuf_iterator<char>(in)), {});
  }
  std::ofstream(dir / "cut.bin", std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size() - 3));
  EXPECT_THROW(ReadBinaryTable((dir / "cut.bin").string()), IoError);
  fs::remove_all(dir);
}

TEST(CppHeaderWriter, CompilesWithWerrorAndLooksUpExactly) {
  const fs::path dir = TempDir("header");
  WriteOptions options;
  options.headerNamespace = "engine::luts";
  std::string checks;
  char line[512];
  for (const TableDefinition *kind : AllTables()) {
    // A size that is not a power of two, so texel centres are not exact in float.
    const Table t = SmallTable(kind, 10);
    MakeCppHeaderWriter()->Write(t, (dir / (std::string(kind->Name()) + ".h")).string(), options);
    for (int y = 0; y < t.height(); ++y)
      for (int x = 0; x < t.width(); ++x) {
        const float fx = static_cast<float>(t.x.TexelCenter(x));
        const float fy = static_cast<float>(t.y.TexelCenter(y));
        // On an axis that is not [0, 1] (Oren-Nayar's sigma in [0, pi/2]) a
        // float texel centre maps back to the centre only to float rounding:
        // the lookup may blend in ~1e-6 of a neighbour.
        // A listed axis finds its node exactly, and [0, 1] maps back exactly.
        const auto exact = [](const Axis &a) {
          return a.listed() || a.count == 1 || (a.min == 0.0 && a.max == 1.0);
        };
        const bool unitAxes = exact(t.x) && (!t.is2D() || exact(t.y));
        for (int c = 0; c < t.channels; ++c) {
          const float expected = static_cast<float>(t.value(x, y, c));
          if (t.channels > 1 && !t.is3D())  // dfg, ltc_ggx: an array of the channels
            std::snprintf(line, sizeof line,
                          "  fail += engine::luts::lookup_%s(%#.9gf, %#.9gf)[%d] != %#.9gf;\n",
                          kind->Name(), fx, fy, c, expected);
          else if (t.is3D())  // its one slice (SmallTable's depthSize 1)
            std::snprintf(
                line, sizeof line,
                "  fail += engine::luts::lookup_%s(%#.9gf, %#.9gf, float(%.17g)) != %#.9gf;\n",
                kind->Name(), fx, fy, t.z.TexelCenter(0), expected);
          else if (t.is2D() && !unitAxes)
            std::snprintf(line, sizeof line,
                          "  fail += std::fabs(engine::luts::lookup_%s(%#.9gf, %#.9gf) - %#.9gf) > "
                          "1e-6f;\n",
                          kind->Name(), fx, fy, expected);
          else if (t.is2D())
            std::snprintf(line, sizeof line,
                          "  fail += engine::luts::lookup_%s(%#.9gf, %#.9gf) != %#.9gf;\n",
                          kind->Name(), fx, fy, expected);
          else
            std::snprintf(line, sizeof line,
                          "  fail += engine::luts::lookup_%s(%#.9gf) != %#.9gf;\n", kind->Name(),
                          fx, expected);
          checks += line;
        }
      }
  }
  // Between centres and outside the range: bilinear and clamped.
  const Table e = SmallTable(&TableNamed("E"), 10);
  const double mid = 0.5 * (e.value(2, 3) + e.value(3, 3));
  std::snprintf(line, sizeof line,
                "  fail += std::fabs(engine::luts::lookup_E(0.3f, 0.35f) - %.9gf) > 1e-6f;\n", mid);
  checks += line;
  std::snprintf(line, sizeof line, "  fail += engine::luts::lookup_E(-5.0f, 7.0f) != %.9gf;\n",
                static_cast<float>(e.value(0, 9)));
  checks += line;
  checks += "  fail += !(engine::luts::lookup_E(std::nanf(\"\"), 0.5f) >= 0.0f);\n";
  // The conventions as constants, checked at compile time, and a command
  // line with quotes, a backslash and a newline kept exactly.
  Table quoted = SmallTable(&TableNamed("Eavg"), 3);
  quoted.name = "Eavg_quoted";
  for (auto &[key, value] : quoted.metadata)
    if (key == "commandLine") value = "lutbake bake --out 'a \"b\"\\c'\n--tables Eavg";
  MakeCppHeaderWriter()->Write(quoted, (dir / "Eavg_quoted.h").string(), options);
  checks += R"(  namespace e = engine::luts::E_table;
  namespace d = engine::luts::dfg_table;
  static_assert(std::string_view(e::kXAxis) == "mu" && std::string_view(e::kXMapping) == "linear");
  static_assert(std::string_view(e::kYAxis) == "perceptualRoughness");
  static_assert(e::kAlphaIsPerceptualRoughnessSquared && e::kTexelCentre == 0.5);
  static_assert(std::string_view(e::kNdf) == "ggx" && std::string_view(e::kSmith) == "correlated");
  static_assert(std::string_view(d::kChannelNames[0]) == "A" &&
                std::string_view(d::kChannelNames[1]) == "B");
  static_assert(std::string_view(engine::luts::Favg_table::kXAxis) == "F0");
  static_assert(std::string_view(e::kCommandLine) == "lutbake bake --test");
  static_assert(std::string_view(engine::luts::Eavg_quoted_table::kCommandLine) ==
                "lutbake bake --out 'a \"b\"\\c'\n--tables Eavg");
)";
  checks += "  static_assert(std::string_view(e::kLutbakeVersion) == \"" +
            std::string(LutbakeVersion()) + "\");\n";
  // Every table's header (written above), then the quoted one.
  std::string includes = "#include <string_view>\n";
  for (const TableDefinition *kind : AllTables())
    includes += "#include \"" + std::string(kind->Name()) + ".h\"\n";
  ExpectHeadersPass(dir, includes + "#include \"Eavg_quoted.h\"\n", checks);
  fs::remove_all(dir);
}

// Half storage: every value is the float32 value rounded to binary16 (read
// back by an independent decoder, Imath's, and by the header's own), the
// stated kStorageErrorMax covers the real rounding and stays within 2^-12,
// and the header compiles as the float one does, with g++ and clang++.
TEST(CppHeaderWriter, HalfStorageRoundsOnceAndSaysBy) {
  const fs::path dir = TempDir("header_half");
  WriteOptions options;
  options.headerStorage = HeaderStorage::kHalf;
  std::string checks;
  char line[512];
  for (const TableDefinition *kind : {&TableNamed("E"), &TableNamed("dfg")}) {
    const Table t = SmallTable(kind, 10);
    const std::string path = (dir / (std::string(kind->Name()) + ".h")).string();
    MakeCppHeaderWriter()->Write(t, path, options);
    const HeaderValues h = ReadHeaderValues(path);
    EXPECT_TRUE(h.half);
    ASSERT_EQ(h.values.size(), t.values.size());
    double worst = 0.0;
    for (size_t i = 0; i < t.values.size(); ++i) {
      EXPECT_EQ(static_cast<double>(h.values[i]), RoundToHalf(t.values[i])) << i;
      worst = std::max(worst, std::abs(static_cast<double>(h.values[i]) -
                                       static_cast<double>(static_cast<float>(t.values[i]))));
    }
    const std::string *stated = nullptr;
    for (const auto &[key, value] : h.metadata)
      if (key == "storageErrorMax") stated = &value;
    ASSERT_NE(stated, nullptr);
    EXPECT_EQ(std::stod(*stated), worst);
    EXPECT_LE(worst, 0x1p-12);
    EXPECT_GT(worst, 0.0);
    for (int y = 0; y < t.height(); ++y)
      for (int x = 0; x < t.width(); ++x)
        for (int c = 0; c < t.channels; ++c) {
          const float fx = static_cast<float>((x + 0.5) / t.width());
          const float fy = static_cast<float>((y + 0.5) / t.height());
          const float expected = static_cast<float>(RoundToHalf(t.value(x, y, c)));
          if (kind == &TableNamed("dfg"))
            std::snprintf(line, sizeof line,
                          "  fail += lutbake_luts::lookup_dfg(%.9gf, %.9gf)[%d] != %af;\n", fx, fy,
                          c, static_cast<double>(expected));
          else
            std::snprintf(line, sizeof line,
                          "  fail += lutbake_luts::lookup_E(%.9gf, %.9gf) != %af;\n", fx, fy,
                          static_cast<double>(expected));
          checks += line;
        }
  }
  // Subnormal halves and zero decode exactly too.
  checks +=
      "  fail += lutbake_luts::E_table::HalfToFloat(0x0001) != 0x1p-24f;\n"
      "  fail += lutbake_luts::E_table::HalfToFloat(0x03ff) != 0x3ffp-24f;\n"
      "  fail += lutbake_luts::E_table::HalfToFloat(0x0000) != 0.0f;\n"
      "  fail += lutbake_luts::E_table::HalfToFloat(0x3c00) != 1.0f;\n"
      "  fail += lutbake_luts::E_table::HalfToFloat(0x3555) != 0x1.554p-2f;\n";
  ExpectHeadersPass(dir, "#include \"E.h\"\n#include \"dfg.h\"\n", checks);
  fs::remove_all(dir);
}

// kulla_conty.h: f_ms and F_ms equal their stated formulas evaluated with the
// library's own lookups of the same tables, and the compensated white
// furnace E(mu_o) + integral f_ms cos, integrated in the compiled program
// exactly (two Gauss points on each piece where the interpolated E is
// linear in mu), equals the library's closed form of the same sum,
//   E(mu_o) + (1 - E(mu_o)) (1 - 2 integral L(mu) mu dmu) / (1 - E_avg),
// with g++ and clang++, C++17 and C++20.
TEST(CppHeaderWriter, KullaContyHelpersMatchTheirFormulas) {
  const fs::path dir = TempDir("header_kc");
  BakeSettings s;
  s.tableSizes = {{"E", 12}, {"Eavg", 12}};
  s.tolerance = 1e-7;
  s.commandLine = "lutbake bake --test";
  const Table e = BakeTable(TableNamed("E"), s), eavg = BakeTable(TableNamed("Eavg"), s);
  const WriteOptions options;
  MakeCppHeaderWriter()->Write(e, (dir / "E.h").string(), options);
  MakeCppHeaderWriter()->Write(eavg, (dir / "Eavg.h").string(), options);
  WriteKullaContyHeader((dir / "kulla_conty.h").string(), options, "", {});
  std::string checks;
  char line[512];
  const auto escape = [&](double mu, double r) { return std::max(0.0, 1.0 - Lookup(e, mu, r)); };
  const double pi = 3.14159265358979323846;
  for (double r : {0.0, 0.04, 0.3, 0.55, 1.0}) {
    const double lost = 1.0 - Lookup(eavg, r, 0.0);
    ASSERT_GT(lost, 0.0) << r;
    for (double muO : {0.0, 0.02, 0.37, 0.8, 1.0})
      for (double muI : {0.0, 0.11, 0.5, 0.96}) {
        const double a = escape(muO, r), b = escape(muI, r);
        const double fms = a * b / (pi * lost);
        // The header's lookups return floats: each of 1 - E(mu_o), 1 - E(mu_i)
        // and 1 - E_avg is off by up to 2^-24 from rounding a value near 1,
        // which the ratio amplifies where they are small (smooth surfaces).
        const double eps = 0x1p-23;
        const double bound =
            fms * eps * ((a > 0 ? 1 / a : 0) + (b > 0 ? 1 / b : 0) + 1 / lost) + 1e-9;
        std::snprintf(line, sizeof line,
                      "  fail += Far(lutbake_luts::f_ms(%#.9gf, %#.9gf, %#.9gf), %.17g, %.17g, "
                      "__LINE__);\n",
                      muO, muI, r, fms, bound);
        checks += line;
      }
    for (double favg : {0.0, 0.04, 0.5, 0.95, 1.0}) {
      const double ea = 1.0 - lost;
      const double fresnel = favg * favg * ea / (1.0 - favg * (1.0 - ea));
      std::snprintf(
          line, sizeof line,
          "  fail += Far(lutbake_luts::fresnel_ms(%#.9gf, %#.9gf), %.17g, 1e-6, __LINE__);\n", favg,
          r, fresnel);
      checks += line;
    }
    // Out-of-range F_avg is clamped: 1.5 acts as 1 (F_ms = 1), -0.5 as 0.
    std::snprintf(line, sizeof line,
                  "  fail += Far(lutbake_luts::fresnel_ms(1.5f, %#.9gf), 1.0, 1e-6, __LINE__);\n"
                  "  fail += Far(lutbake_luts::fresnel_ms(-0.5f, %#.9gf), 0.0, 0.0, __LINE__);\n",
                  r, r);
    checks += line;
    // The furnace, against the library's closed form of the same sum.
    const double muAverage = LookupMuAverage(e, e.values, r, 0);
    for (double muO : {0.0, 0.02, 0.37, 1.0}) {
      const double eo = Lookup(e, muO, r);
      const double furnace = eo + std::max(0.0, 1.0 - eo) * (1.0 - muAverage) / lost;
      std::snprintf(line, sizeof line,
                    "  fail += Far(Furnace(%#.9gf, %#.9gf), %.17g, 2e-5, __LINE__);\n", muO, r,
                    furnace);
      checks += line;
      // The sum itself is 1 up to how well the interpolated E averages to
      // the exact E_avg; at these sizes and this tolerance, to 2e-3.
      EXPECT_NEAR(furnace, 1.0, 2e-3) << "mu_o " << muO << " r " << r;
    }
  }
  const std::string furnace = R"(
// 1 (and a note naming the line) when |got - expected| > bound.
int Far(double got, double expected, double bound, int line) {
  if (std::fabs(got - expected) <= bound) return 0;
  std::printf("line %d: %.9g, expected %.9g within %.3g\n", line, got, expected, bound);
  return 1;
}
// E(mu_o) + 2 pi integral_0^1 f_ms(mu_o, mu_i) mu_i dmu_i, with two Gauss
// points on each piece between the 12 texel centres (and the clamped ends).
double Furnace(float muO, float r) {
  const int n = 12;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double a = k == 0 ? 0.0 : (k - 0.5) / n, b = k == n ? 1.0 : (k + 0.5) / n;
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b), g = half / std::sqrt(3.0);
    for (double mu : {mid - g, mid + g})
      sum += half * mu * lutbake_luts::f_ms(muO, static_cast<float>(mu), r);
  }
  return lutbake_luts::lookup_E(muO, r) + 2.0 * 3.14159265358979323846 * sum;
}
)";
  ExpectHeadersPass(dir, "#include \"kulla_conty.h\"\n" + furnace, checks);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
