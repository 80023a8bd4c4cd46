// PNG tables (--format png8, png16): read back through OpenImageIO, an
// independent reader, every texel is the float value rounded to the nearest
// b-bit step (so within half a step, 0.5 / (2^b - 1)); the tEXt errorMax
// covers that rounding; a second write gives the same bytes; values outside
// [0, 1] are refused; lutbake's own reader recovers table and metadata.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

using test::FormatTempDir;

std::string Attribute(const OIIO::ImageSpec &spec, const std::string &name) {
  return spec.get_string_attribute(name);
}

TEST(PngTable, EveryTexelWithinHalfAStepThroughOpenImageIO) {
  const auto dir = FormatTempDir("png");
  for (int bits : {8, 16}) {
    const double top = bits == 8 ? 255.0 : 65535.0;
    for (const std::string name : {"E", "dfg", "Eavg"}) {
      const Table t = test::SmallTableOf(TableNamed(name));
      const std::string path = (dir / (name + std::to_string(bits) + ".png")).string();
      MakePngWriter(bits)->Write(t, path, {});
      auto in = OIIO::ImageInput::open(path);
      ASSERT_TRUE(in) << OIIO::geterror();
      const OIIO::ImageSpec spec = in->spec();
      EXPECT_EQ(spec.width, t.width());
      EXPECT_EQ(spec.height, t.height());
      EXPECT_EQ(spec.nchannels, t.channels == 1 ? 1 : 3);  // RG as RGB with B = 0
      EXPECT_EQ(spec.format, bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
      std::vector<uint16_t> q(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
      ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, q.data()));
      double worstStored = 0.0;
      for (size_t texel = 0; texel < t.texelCount(); ++texel) {
        for (int c = 0; c < spec.nchannels; ++c) {
          // OpenImageIO widens 8 bits to 16 as q * 257.
          const double stored = q[texel * spec.nchannels + c] / 65535.0;
          if (c >= t.channels) {
            EXPECT_EQ(stored, 0.0) << path << ": the unused B channel";
            continue;
          }
          const double v = t.values[texel * t.channels + c];
          EXPECT_LE(std::abs(stored - v), 0.5 / top) << path << " texel " << texel;
          EXPECT_EQ(stored, QuantizeUnorm(v, bits) / top) << path << " texel " << texel;
          worstStored =
              std::max(worstStored, t.errors[texel * t.channels + c] + std::abs(stored - v));
        }
      }
      // The stated bound holds for the stored values, and is at most the
      // integration bound plus half a step.
      const double errorMax = std::stod(Attribute(spec, "errorMax"));
      EXPECT_GE(errorMax, worstStored);
      EXPECT_LE(errorMax, RoundUpToFloat(t.MaxError() + 0.5 / top));
      EXPECT_EQ(Attribute(spec, "errorStorage"), bits == 8 ? "unorm8" : "unorm16");
      EXPECT_EQ(Attribute(spec, "table"), name);
      EXPECT_EQ(Attribute(spec, "axisX"), *t.FindMetadata("axisX"));
      EXPECT_EQ(Attribute(spec, "quantisationStep"), bits == 8 ? "1/255" : "1/65535");
      EXPECT_NE(Attribute(spec, "channelMapping"), "");
      EXPECT_EQ(Attribute(spec, "DateTime"), "") << "no date: equal tables, equal files";
    }
  }
}

TEST(PngTable, SecondWriteGivesTheSameBytes) {
  const auto dir = FormatTempDir("png_again");
  const Table t = test::SmallTableOf(TableNamed("dfg"));
  MakePngWriter(16)->Write(t, (dir / "a.png").string(), {});
  MakePngWriter(16)->Write(t, (dir / "b.png").string(), {});
  const auto a = test::FileBytes(dir / "a.png");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, test::FileBytes(dir / "b.png"));
}

TEST(PngTable, ThreeDSlicesStackAlongY) {
  const auto dir = FormatTempDir("png3d");
  const Table t = test::ThreeSliceTable();
  const std::string path = (dir / "E.png").string();
  MakePngWriter(16)->Write(t, path, {});
  const Table back = ReadPngTable(path);
  ASSERT_TRUE(back.is3D());
  EXPECT_EQ(back.depth(), 3);
  ASSERT_EQ(back.values.size(), t.values.size());
  for (size_t i = 0; i < t.values.size(); ++i)
    EXPECT_EQ(back.values[i], StoredValue(t.values[i], ValueType::kUnorm16)) << i;
}

TEST(PngTable, ReaderRecoversTableAndMetadata) {
  const auto dir = FormatTempDir("png_read");
  const Table t = test::SmallTableOf(TableNamed("dfg"));
  const std::string path = (dir / "dfg.png").string();
  MakePngWriter(8)->Write(t, path, {});
  const Table back = ReadPngTable(path);
  EXPECT_EQ(back.definition, &TableNamed("dfg"));
  EXPECT_EQ(back.channels, 2);
  EXPECT_EQ(DescribeAxis(back.x), DescribeAxis(t.x));
  EXPECT_EQ(DescribeAxis(back.y), DescribeAxis(t.y));
  ASSERT_EQ(back.values.size(), t.values.size());
  for (size_t i = 0; i < t.values.size(); ++i)
    EXPECT_EQ(back.values[i], StoredValue(t.values[i], ValueType::kUnorm8)) << i;
  EXPECT_EQ(*back.FindMetadata("errorMax"),
            FormatDouble(SummarizeStoredBounds(t, ValueType::kUnorm8).max));
}

TEST(PngTable, RefusesValuesOutsideTheUnitInterval) {
  const auto dir = FormatTempDir("png_range");
  Table t = test::SmallTableOf(TableNamed("E"));
  t.values[7] = 1.0625;  // as sheen E can be
  const std::string path = (dir / "E.png").string();
  try {
    MakePngWriter(8)->Write(t, path, {});
    FAIL() << "a value of 1.0625 was written to PNG";
  } catch (const IoError &e) {
    EXPECT_NE(std::string(e.what()).find("1.0625"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace lutbake
