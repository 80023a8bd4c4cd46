// 3D tables (a third axis z outermost, glass_E(mu, r, eta)) in every format:
// EXR with the slices stacked along the image's y (read back by OpenImageIO,
// an independent reader, and by lutbake's own reader), .bin version 2 at
// its documented offsets, the C++ header's trilinear lookup compiled and
// run, and the library's lookup. The table is E's values scaled differently
// in each slice, so that a slice mixed up with another shows.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/lookup.h"
#include "support/cli_run.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

// Slice z holds E (1 - 0.25 z) (support/small_tables.h).
Table ThreeDTable(const Axis &z) { return test::ThreeSliceTable(z); }

fs::path TempDir(const std::string &name) {
  const fs::path dir =
      fs::temp_directory_path() / ("lutbake_3d_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void ExpectSameAxis(const Axis &a, const Axis &b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.nodes, b.nodes);
}

TEST(ThreeDTable, LayoutAndLibraryLookup) {
  const Table t = ThreeDTable(LinearAxis("eta", 1.0, 2.5, 3));
  ASSERT_TRUE(t.is3D());
  EXPECT_EQ(t.texelCount(), 4u * 4u * 3u);
  EXPECT_EQ(t.values.size(), t.texelCount());
  // Slice z starts at z * width * height.
  EXPECT_EQ(t.index(1, 2, 2, 0), (2u * 4u + 2u) * 4u + 1u);
  EXPECT_EQ(t.values[t.index(1, 2, 2, 0)], 0.5 * t.values[t.index(1, 2, 0, 0)]);
  // At texel centres the lookup returns the texel; halfway between two
  // slices, their mean (trilinear, z outermost).
  for (int iz = 0; iz < 3; ++iz)
    EXPECT_EQ(Lookup(t, t.values, t.x.TexelCenter(1), t.y.TexelCenter(2), t.z.TexelCenter(iz), 0),
              t.values[t.index(1, 2, iz, 0)]);
  const double between = 0.5 * (t.z.TexelCenter(0) + t.z.TexelCenter(1));
  EXPECT_NEAR(Lookup(t, t.values, t.x.TexelCenter(1), t.y.TexelCenter(2), between, 0),
              0.5 * (t.values[t.index(1, 2, 0, 0)] + t.values[t.index(1, 2, 1, 0)]), 1e-15);
}

TEST(ThreeDTable, ExrStacksSlicesAlongY) {
  const fs::path dir = TempDir("exr");
  const Table t = ThreeDTable(LinearAxis("eta", 1.0, 2.5, 3));
  const std::string path = (dir / "E3.exr").string();
  MakeExrWriter()->Write(t, path, {});
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().width, 4);
  EXPECT_EQ(in->spec().height, 12);
  EXPECT_EQ(in->spec().get_string_attribute("axisZ"), "eta linear [1, 2.5], 3 texels");
  std::vector<float> pixels(t.values.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, pixels.data()));
  for (size_t i = 0; i < pixels.size(); ++i)
    EXPECT_EQ(pixels[i], static_cast<float>(t.values[i])) << i;
  const Table back = ReadExrTable(path);
  ASSERT_TRUE(back.is3D());
  ExpectSameAxis(back.z, t.z);
  ASSERT_EQ(back.values.size(), t.values.size());
  for (size_t i = 0; i < t.values.size(); ++i)
    EXPECT_EQ(back.values[i], static_cast<float>(t.values[i]));
  fs::remove_all(dir);
}

uint32_t U32At(const std::string &b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

TEST(ThreeDTable, BinaryVersionTwoAtItsDocumentedOffsets) {
  const fs::path dir = TempDir("bin");
  // A listed z axis too (a bake plan's IORs).
  for (const Axis &z : {LinearAxis("eta", 1.0, 2.5, 3), ListedAxis("eta", {1.0 / 1.5, 1.33, 1.5})})
    for (ValueType type : {ValueType::kFloat32, ValueType::kFloat64}) {
      const Table t = ThreeDTable(z);
      const std::string path = (dir / "E3.bin").string();
      WriteOptions options;
      options.binaryValues = type;
      MakeBinaryWriter()->Write(t, path, options);
      std::ifstream file(path, std::ios::binary);
      std::stringstream buffer;
      buffer << file.rdbuf();
      const std::string b = buffer.str();
      EXPECT_EQ(U32At(b, 8), kBinaryVersion3D);
      EXPECT_EQ(U32At(b, 16), 3u);
      EXPECT_EQ(std::string(b.data() + 136), "eta");
      EXPECT_EQ(U32At(b, 136 + 40), 3u);                    // z count
      EXPECT_EQ(U32At(b, 136 + 44), z.listed() ? 1u : 0u);  // z mapping
      const uint32_t metadataLength = U32At(b, 184);
      EXPECT_EQ(b.substr(188, 8), "table=E\n");
      const size_t D = U32At(b, 12);
      EXPECT_GE(D, 188 + metadataLength + 8 * z.nodes.size());
      const size_t S = type == ValueType::kFloat64 ? 8 : 4;
      EXPECT_EQ(b.size(), D + 2 * S * t.values.size());
      const Table back = ReadBinaryTable(path);
      ASSERT_TRUE(back.is3D());
      ExpectSameAxis(back.z, t.z);
      const std::vector<double> bounds = StoredBounds(t, type);
      for (size_t i = 0; i < t.values.size(); ++i) {
        EXPECT_EQ(back.values[i], StoredValue(t.values[i], type));
        EXPECT_EQ(back.errors[i], bounds[i]);
      }
    }
  fs::remove_all(dir);
}

TEST(ThreeDTable, HeaderLooksUpTrilinearly) {
  const fs::path dir = TempDir("header");
  Table t = ThreeDTable(ListedAxis("eta", {1.0 / 1.5, 1.33, 1.5}));
  t.name = "E3";
  MakeCppHeaderWriter()->Write(t, (dir / "E3.h").string(), {});
  const HeaderValues h = ReadHeaderValues((dir / "E3.h").string());
  EXPECT_EQ(h.depth, 3);
  ASSERT_EQ(h.values.size(), t.values.size());
  for (size_t i = 0; i < t.values.size(); ++i)
    EXPECT_EQ(h.values[i], static_cast<float>(t.values[i]));
  // The lookup at every texel centre returns the texel, and halfway between
  // eta = 1.33 and 1.5 the mean of the two slices.
  std::ostringstream main;
  main.precision(17);
  main << "#include <cmath>\n#include <cstdio>\n#include \"E3.h\"\nint main() {\n  int fail = 0;\n"
       << "  using namespace lutbake_luts::E3_table;\n"
       << "  static_assert(kDepth == 3 && kWidth == 4 && kHeight == 4, \"size\");\n"
       << "  for (std::size_t z = 0; z < kDepth; ++z)\n"
       << "    for (std::size_t y = 0; y < kHeight; ++y)\n"
       << "      for (std::size_t x = 0; x < kWidth; ++x) {\n"
       << "        const float mu = float((x + 0.5) / kWidth), r = float((y + 0.5) / kHeight);\n"
       << "        const float v = lutbake_luts::lookup_E3(mu, r, float(kZNodes[z]));\n"
       << "        if (v != kValues[(z * kHeight + y) * kWidth + x]) ++fail;\n"
       << "      }\n"
       << "  const float mid = lutbake_luts::lookup_E3(0.375f, 0.625f, 0.5f * (1.33f + 1.5f));\n"
       << "  const double want = 0.5 * (kValues[(1 * kHeight + 2) * kWidth + 1] +\n"
       << "                             kValues[(2 * kHeight + 2) * kWidth + 1]);\n"
       << "  if (std::fabs(mid - want) > 1e-6) ++fail;\n"
       << "  std::printf(\"%d failures\\n\", fail);\n  return fail == 0 ? 0 : 1;\n}\n";
  std::ofstream(dir / "main.cpp") << main.str();
  LUTBAKE_EXPECT_COMPILES_AND_RUNS(dir, "c++17", "c++20");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
