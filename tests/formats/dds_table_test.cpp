// DDS tables (--format dds, dds-half). OpenImageIO 2.4 (Debian 12) cannot
// read DX10-header DDS files in float formats ("Unsupported compression
// type"), so the files are parsed here by an independent reader written
// from Microsoft's documentation ("DDS_HEADER structure", "DDS_PIXELFORMAT",
// "DDS_HEADER_DXT10"): the structures as Microsoft declares them, read
// with memcpy, none of lutbake's code. Where OpenImageIO does read the file
// (a later version), its texels are compared too.
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::FormatTempDir;

// Microsoft's declarations (dds.h of the DirectX SDK documentation).
struct DDS_PIXELFORMAT {
  uint32_t dwSize, dwFlags, dwFourCC, dwRGBBitCount, dwRBitMask, dwGBitMask, dwBBitMask, dwABitMask;
};
struct DDS_HEADER {
  uint32_t dwSize, dwFlags, dwHeight, dwWidth, dwPitchOrLinearSize, dwDepth, dwMipMapCount;
  uint32_t dwReserved1[11];
  DDS_PIXELFORMAT ddspf;
  uint32_t dwCaps, dwCaps2, dwCaps3, dwCaps4, dwReserved2;
};
struct DDS_HEADER_DXT10 {
  uint32_t dxgiFormat, resourceDimension, miscFlag, arraySize, miscFlags2;
};
static_assert(sizeof(DDS_HEADER) == 124 && sizeof(DDS_HEADER_DXT10) == 20);

struct Case {
  std::string name;
  Table table;
  ValueType storage;
  uint32_t dxgiFormat;
};

TEST(DdsTable, MicrosoftLayoutHoldsHeaderAndTexels) {
  const fs::path dir = FormatTempDir("dds");
  const std::vector<Case> cases = {
      {"E", test::SmallTableOf(TableNamed("E")), ValueType::kFloat32, 41},        // R32_FLOAT
      {"dfg", test::SmallTableOf(TableNamed("dfg")), ValueType::kFloat32, 16},    // R32G32_FLOAT
      {"E_half", test::SmallTableOf(TableNamed("E")), ValueType::kHalf, 54},      // R16_FLOAT
      {"dfg_half", test::SmallTableOf(TableNamed("dfg")), ValueType::kHalf, 34},  // R16G16_FLOAT
      {"E3d", test::ThreeSliceTable(), ValueType::kFloat32, 41},
      {"E3d_half", test::ThreeSliceTable(), ValueType::kHalf, 54},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.name);
    const Table &t = c.table;
    const std::string path = (dir / (c.name + ".dds")).string();
    MakeDdsWriter(c.storage)->Write(t, path, {});
    const std::vector<unsigned char> bytes = test::FileBytes(path);
    ASSERT_GE(bytes.size(), 148u);
    EXPECT_EQ(std::memcmp(bytes.data(), "DDS ", 4), 0);
    DDS_HEADER h;
    DDS_HEADER_DXT10 dx10;
    std::memcpy(&h, bytes.data() + 4, sizeof h);
    std::memcpy(&dx10, bytes.data() + 128, sizeof dx10);
    const bool volume = t.is3D();
    const uint32_t typeSize = c.storage == ValueType::kHalf ? 2 : 4;
    EXPECT_EQ(h.dwSize, 124u);
    // DDSD_CAPS | HEIGHT | WIDTH | PITCH | PIXELFORMAT, + DEPTH for a volume.
    EXPECT_EQ(h.dwFlags, 0x1u | 0x2u | 0x4u | 0x8u | 0x1000u | (volume ? 0x800000u : 0u));
    EXPECT_EQ(h.dwWidth, static_cast<uint32_t>(t.width()));
    EXPECT_EQ(h.dwHeight, static_cast<uint32_t>(t.height()));
    EXPECT_EQ(h.dwDepth, volume ? static_cast<uint32_t>(t.depth()) : 0u);
    EXPECT_EQ(h.dwPitchOrLinearSize, t.width() * typeSize * t.channels);
    EXPECT_EQ(h.ddspf.dwSize, 32u);
    EXPECT_EQ(h.ddspf.dwFlags, 0x4u);  // DDPF_FOURCC
    EXPECT_EQ(std::memcmp(&h.ddspf.dwFourCC, "DX10", 4), 0);
    EXPECT_EQ(h.dwCaps, 0x1000u | (volume ? 0x8u : 0u));  // TEXTURE, + COMPLEX
    EXPECT_EQ(h.dwCaps2, volume ? 0x200000u : 0u);        // DDSCAPS2_VOLUME
    EXPECT_EQ(dx10.dxgiFormat, c.dxgiFormat);
    EXPECT_EQ(dx10.resourceDimension, volume ? 4u : 3u);  // TEXTURE3D or TEXTURE2D
    EXPECT_EQ(dx10.arraySize, 1u);
    const size_t count = t.values.size();
    ASSERT_GE(bytes.size(), 148 + count * typeSize + 8);
    for (size_t i = 0; i < count; ++i) {
      double v;
      if (typeSize == 2) {
        uint16_t bits;
        std::memcpy(&bits, bytes.data() + 148 + 2 * i, 2);
        Imath::half half;
        half.setBits(bits);
        v = static_cast<float>(half);
      } else {
        float f;
        std::memcpy(&f, bytes.data() + 148 + 4 * i, 4);
        v = f;
      }
      ASSERT_EQ(v, StoredValue(t.values[i], c.storage)) << "value " << i;
    }
    // lutbake's trailer after the texels: "LBMD", a length, the metadata.
    const size_t trailer = 148 + count * typeSize;
    EXPECT_EQ(std::memcmp(bytes.data() + trailer, "LBMD", 4), 0);
    const std::string json(bytes.begin() + trailer + 8, bytes.end());
    EXPECT_NE(json.find("\"errorStorage\":\"" + std::string(ToString(c.storage)) + "\""),
              std::string::npos);
    EXPECT_NE(
        json.find("\"errorMax\":\"" + FormatDouble(SummarizeStoredBounds(t, c.storage).max) + "\""),
        std::string::npos);
    // lutbake's own reader, for check.
    const Table back = ReadDdsTable(path);
    EXPECT_EQ(DescribeAxis(back.z), DescribeAxis(t.z));
    ASSERT_EQ(back.values.size(), count);
    for (size_t i = 0; i < count; ++i)
      ASSERT_EQ(back.values[i], StoredValue(t.values[i], c.storage)) << i;
    // OpenImageIO, where it can.
    if (auto in = OIIO::ImageInput::open(path)) {
      std::vector<float> pixels(static_cast<size_t>(in->spec().image_pixels()) *
                                in->spec().nchannels);
      ASSERT_TRUE(
          in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
      for (size_t i = 0; i < count && t.channels == in->spec().nchannels; ++i)
        EXPECT_EQ(pixels[i], static_cast<float>(StoredValue(t.values[i], c.storage)));
    } else {
      std::cout << "OpenImageIO " << OIIO::openimageio_version()
                << " does not read it: " << OIIO::geterror() << "\n";
    }
  }
}

TEST(DdsTable, SecondWriteGivesTheSameBytes) {
  const fs::path dir = FormatTempDir("dds_again");
  const Table t = test::ThreeSliceTable();
  MakeDdsWriter(ValueType::kFloat32)->Write(t, (dir / "a.dds").string(), {});
  MakeDdsWriter(ValueType::kFloat32)->Write(t, (dir / "b.dds").string(), {});
  EXPECT_EQ(test::FileBytes(dir / "a.dds"), test::FileBytes(dir / "b.dds"));
}

TEST(DdsTable, ReaderRejectsAnotherFormat) {
  const fs::path dir = FormatTempDir("dds_other");
  const std::string path = (dir / "E.dds").string();
  MakeDdsWriter(ValueType::kFloat32)->Write(test::SmallTableOf(TableNamed("E")), path, {});
  std::vector<unsigned char> bytes = test::FileBytes(path);
  bytes[128] = 28;  // DXGI_FORMAT_R8G8B8A8_UNORM
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char *>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  EXPECT_THROW(ReadDdsTable(path), IoError);
}

}  // namespace
}  // namespace lutbake
