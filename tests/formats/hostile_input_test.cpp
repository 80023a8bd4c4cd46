// Hostile files, built here byte by byte: headers that claim more texels than
// the file can hold, which every reader refuses with IoError before it
// allocates for the claim (without the guards these tests end in
// std::bad_alloc or std::length_error, or a multi-gigabyte allocation, not
// in IoError), and what the fuzzers found (tests/fuzz/, scripts/fuzz.sh).
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

std::string WriteFile(const fs::path &path, const std::string &bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

void PutLE(std::string *out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void PutBE32(std::string *out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out->push_back(static_cast<char>((v >> shift) & 0xff));
}

// The IoError message of reading `path` with `read`, or a failure.
template <typename Read>
std::string Refusal(Read read, const std::string &path) {
  try {
    read(path);
  } catch (const IoError &e) {
    return e.what();
  }
  ADD_FAILURE() << path << " was read";
  return {};
}

// The header of a version 2 (3D) .bin of `size`^3 texels, 2 channels,
// float64 with errors, linear axes over [0, `xMax`] (x) and [0, 1], no
// metadata; the values are not there.
std::string BinaryHeader(uint32_t size, double xMax) {
  std::string bin(kBinaryMagic, 8);
  PutLE(&bin, kBinaryVersion3D, 4);
  PutLE(&bin, 192, 4);  // data offset
  PutLE(&bin, 3, 4);
  for (int i = 0; i < 2; ++i) PutLE(&bin, size, 4);
  PutLE(&bin, 2, 4);
  PutLE(&bin, kBinaryFloat64, 4);
  PutLE(&bin, 1, 4);  // error block
  for (const char *name : {"mu", "perceptualRoughness", "eta"}) {
    std::string field(name);
    field.resize(24, '\0');
    bin += field;
    for (double v : {0.0, name[0] == 'm' ? xMax : 1.0}) {
      uint64_t bits;
      std::memcpy(&bits, &v, 8);
      PutLE(&bin, bits, 8);
    }
    PutLE(&bin, size, 4);
    PutLE(&bin, 0, 4);  // linear
  }
  PutLE(&bin, 0, 4);  // no metadata
  bin.resize(192, '\0');
  return bin;
}

TEST(HostileInput, BinaryClaimingTwoToThe49ValuesIsRefused) {
  // 65536^3 texels, 2 channels, float64 with errors: 2^53 bytes of values
  // claimed by a 256-byte file.
  const auto dir = test::FormatTempDir("oversized_bin");
  const std::string bin = BinaryHeader(1u << 16, 1.0) + std::string(64, '\0');
  const std::string message = Refusal(ReadBinaryTable, WriteFile(dir / "huge.bin", bin));
  EXPECT_NE(message.find("truncated or oversized"), std::string::npos) << message;
}

TEST(HostileInput, BinaryAxisWithAnInfiniteRangeIsRefused) {
  // Found by the .bin fuzzer (tests/fuzz/corpus/bin/regress-bin-infinite-
  // axis-range): an axis over [0, inf] was read, and every lookup in it
  // then cast a NaN coordinate to int. Also a finite range whose width
  // overflows.
  const auto dir = test::FormatTempDir("infinite_axis_bin");
  for (double xMax : {std::numeric_limits<double>::infinity(), 1e308}) {
    std::string bin = BinaryHeader(2, xMax) + std::string(2 * 8 * 8 * 2, '\0');
    if (xMax == 1e308) {  // min -1e308: the width, 2e308, overflows
      const double min = -1e308;
      uint64_t bits;
      std::memcpy(&bits, &min, 8);
      for (int i = 0; i < 8; ++i) bin[40 + 24 + i] = static_cast<char>((bits >> (8 * i)) & 0xff);
    }
    const std::string message = Refusal(ReadBinaryTable, WriteFile(dir / "axis.bin", bin));
    EXPECT_NE(message.find("axis x has an empty or infinite range"), std::string::npos) << message;
  }
  Axis axis;
  EXPECT_FALSE(ParseAxisDescription("mu linear [-1e308, 1e308], 4 texels", &axis));
  EXPECT_TRUE(ParseAxisDescription("mu linear [-1e307, 1e307], 4 texels", &axis));
}

TEST(HostileInput, HeaderClaimingMoreValuesThanItsInitialiserHoldsIsRefused) {
  // 65536 x 65536 x 65536 x 2 values (2^49 floats, 2 PiB) claimed, 3 written.
  const std::string header =
      "//   table: E\n\n"
      "constexpr int kWidth = 65536;\nconstexpr int kHeight = 65536;\n"
      "constexpr int kDepth = 65536;\nconstexpr int kChannels = 2;\n"
      "constexpr float kValues[] = {0.5f, 0.25f, 1f};\n";
  const auto dir = test::FormatTempDir("oversized_header");
  const std::string message = Refusal(ReadHeaderValues, WriteFile(dir / "huge.h", header));
  EXPECT_NE(message.find("too few for the 562949953421312 values"), std::string::npos) << message;
}

TEST(HostileInput, SourceEmbeddingClaimingMoreValuesThanItsBlockHoldsIsRefused) {
  // 65536 x 65536 texels x 4 channels (2^34 floats, 64 GiB) claimed by the
  // opening comment, 3 literals written: refused after reading the 3, with
  // no allocation sized by the claim (ReadSourceTable reserves what the
  // block's length can hold).
  const std::string source =
      "//   table: E\n//   axisX: mu linear [0, 1], 65536 texels\n"
      "//   axisY: perceptualRoughness linear [0, 1], 65536 texels\n"
      "//   width: 65536\n//   height: 65536\n//   depth: 1\n//   channels: 4\n"
      "//   errorStorage: float32\n//\n"
      "// lutbake-values-begin\n0.5f, 0.25f, 1e-05\n// lutbake-values-end\n";
  const auto dir = test::FormatTempDir("oversized_source");
  const std::string message = Refusal(ReadSourceTable, WriteFile(dir / "huge.inc", source));
  EXPECT_NE(message.find("3 values, 17179869184 expected"), std::string::npos) << message;
}

// A PNG chunk: length, type, data, CRC-32 of type and data.
void PutPngChunk(std::string *png, const std::string &type, const std::string &data) {
  PutBE32(png, static_cast<uint32_t>(data.size()));
  const std::string typed = type + data;
  *png += typed;
  PutBE32(png, static_cast<uint32_t>(
                   crc32(0L, reinterpret_cast<const Bytef *>(typed.data()), typed.size())));
}

TEST(HostileInput, PngLargerThanItsImageDataCanInflateToIsRefused) {
  // 32768 x 32767 grey, 8 bits (1 GiB less a row) from a 20-byte IDAT.
  std::string png("\x89PNG\r\n\x1a\n", 8), ihdr;
  PutBE32(&ihdr, 32768);
  PutBE32(&ihdr, 32767);
  ihdr += std::string("\x08\x00\x00\x00\x00", 5);
  PutPngChunk(&png, "IHDR", ihdr);
  const std::pair<std::string, std::string> metadata[] = {
      {"table", "E"},
      {"axisX", "mu linear [0, 1], 32768 texels"},
      {"axisY", "perceptualRoughness linear [0, 1], 32767 texels"},
      {"errorStorage", "unorm8"}};
  for (const auto &[key, value] : metadata)
    PutPngChunk(&png, "tEXt", key + std::string(1, '\0') + value);
  const std::string row(64, '\0');
  std::string packed(compressBound(row.size()), '\0');
  uLongf packedSize = packed.size();
  ASSERT_EQ(compress2(reinterpret_cast<Bytef *>(packed.data()), &packedSize,
                      reinterpret_cast<const Bytef *>(row.data()), row.size(), 9),
            Z_OK);
  packed.resize(packedSize);
  PutPngChunk(&png, "IDAT", packed);
  PutPngChunk(&png, "IEND", "");
  const auto dir = test::FormatTempDir("oversized_png");
  const std::string message = Refusal(ReadPngTable, WriteFile(dir / "huge.png", png));
  EXPECT_NE(message.find("more than deflate can hold"), std::string::npos) << message;
}

// An EXR attribute: name, type, size, value.
void PutExrAttribute(std::string *exr, const std::string &name, const std::string &type,
                     const std::string &value) {
  *exr += name + std::string(1, '\0') + type + std::string(1, '\0');
  PutLE(exr, value.size(), 4);
  *exr += value;
}

// The start of a scanline EXR of one float32 channel Y, `size` texels a
// side, ZIP: every attribute but the lutbake metadata and the header's end.
std::string ExrHeaderStart(uint32_t size) {
  std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8), channels("Y", 2), box, value;
  PutLE(&channels, 2, 4);  // FLOAT
  PutLE(&channels, 0, 4);  // pLinear, reserved
  PutLE(&channels, 1, 4);  // xSampling
  PutLE(&channels, 1, 4);  // ySampling
  channels.push_back('\0');
  PutExrAttribute(&exr, "channels", "chlist", channels);
  PutExrAttribute(&exr, "compression", "compression", std::string(1, '\x03'));  // ZIP
  for (uint32_t v : {0u, 0u, size - 1, size - 1}) PutLE(&box, v, 4);
  PutExrAttribute(&exr, "dataWindow", "box2i", box);
  PutExrAttribute(&exr, "displayWindow", "box2i", box);
  PutExrAttribute(&exr, "lineOrder", "lineOrder", std::string(1, '\0'));
  PutLE(&value, 0x3f800000u, 4);  // 1.0f
  PutExrAttribute(&exr, "pixelAspectRatio", "float", value);
  PutExrAttribute(&exr, "screenWindowCenter", "v2f", std::string(8, '\0'));
  PutExrAttribute(&exr, "screenWindowWidth", "float", value);
  return exr;
}

TEST(HostileInput, ExrLargerThanItsFileCanHoldIsRefused) {
  // A 65536 x 65536 ZIP scanline image (16 GiB of float32 Y) whose 4096
  // chunk offsets are there but whose chunks are not: 32 KiB in all.
  std::string exr = ExrHeaderStart(65536);
  PutExrAttribute(&exr, "table", "string", "E");
  PutExrAttribute(&exr, "axisX", "string", "mu linear [0, 1], 65536 texels");
  PutExrAttribute(&exr, "axisY", "string", "perceptualRoughness linear [0, 1], 65536 texels");
  exr.push_back('\0');
  const size_t chunks = 65536 / 16;  // ZIP: 16 scanlines a chunk
  const size_t firstChunk = exr.size() + 8 * chunks;
  for (size_t i = 0; i < chunks; ++i) PutLE(&exr, firstChunk, 8);
  const auto dir = test::FormatTempDir("oversized_exr");
  const std::string message = Refusal(ReadExrTable, WriteFile(dir / "huge.exr", exr));
  EXPECT_NE(message.find("cannot be held in"), std::string::npos) << message;
}

TEST(HostileInput, ExrAttributesAreCheckedBeforeOpenExrAllocatesForThem) {
  // Found by the EXR fuzzer (tests/fuzz/corpus/exr/regress-exr-*): OpenEXR
  // allocates an attribute's value at the size the file states (1.7 GB
  // asked by a 1.6 KB file), and reads a channel list to its own end
  // whatever size is stated, so that the attributes after it are read
  // from the wrong place.
  const auto dir = test::FormatTempDir("hostile_exr");
  std::string exr = ExrHeaderStart(4);
  exr += std::string("table\0string\0", 13);
  PutLE(&exr, 0x70000000u, 4);
  exr += "E";
  std::string message = Refusal(ReadExrTable, WriteFile(dir / "attribute.exr", exr));
  EXPECT_NE(message.find("attribute table says 1879048192 bytes, more than the file has left"),
            std::string::npos)
      << message;
  // A channel list of two channels (37 bytes) said to be one (19 bytes).
  std::string channels;
  for (const char *name : {"G", "R"}) {
    channels += std::string(name, 2);
    for (uint32_t v : {2u, 0u, 1u, 1u}) PutLE(&channels, v, 4);
  }
  channels.push_back('\0');
  exr = std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) + std::string("channels\0chlist\0", 16);
  PutLE(&exr, 19, 4);
  exr += channels + std::string(64, '\0');
  message = Refusal(ReadExrTable, WriteFile(dir / "chlist.exr", exr));
  EXPECT_NE(message.find("attribute channels (chlist) is malformed"), std::string::npos) << message;
}

}  // namespace
}  // namespace lutbake
