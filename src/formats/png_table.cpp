// Tables as 8- or 16-bit PNG (--format png8, png16), and their reader for
// `lutbake check`. Written and read here with zlib (the PNG chunk layout is
// a few lines; OpenImageIO, which the tests use as the independent reader,
// would link ~250 shared libraries into every lutbake process and cost
// 0.5 s of start-up, 30x an eval). The image is filter type 0 (none) on
// every row, deflated at level 9; the reader takes any filter type.
//
// A texel value v in [0, 1] is stored as q = floor(v (2^b - 1) + 0.5)
// (QuantizeUnorm, storage.h) and read back as q / (2^b - 1): at most half a
// step, 0.5 / (2^b - 1), from v. Values outside [0, 1] (sheen E reaches
// 1.05) or NaN are refused, not clamped or scaled: PNG would state a bound
// that does not hold, and a scale is one more thing an engine could forget.
// One channel is grey; two channels (dfg's A, B) are RGB with R = channel 0,
// G = channel 1, B = 0 (grey + alpha would invite readers to premultiply).
// A 3D table's slices are stacked along y, as in the EXR. Every metadata
// pair, errorMax and errorRms included (those of the quantised values,
// errorStorage unorm8 / unorm16), is a tEXt chunk; so are quantisationStep
// and channelMapping. No gAMA, sRGB or tIME chunk: the values are data, and
// equal tables give equal files.
//
// --format png-rgbd (presets only: Babylon.js's BRDF textures): 8-bit RGBA,
// RGB = a texel's one to three channels and A = their shared divisor, in
// Babylon.js's RGBD (rgbd.h): value = (rgb / 255)^2.2 / (a / 255), every
// texel encoded with the divisor of smallest error. Values >= 0, up to
// 255; errorStorage rgbd8, the bounds those of the decoded values.
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

#include "file_io.h"
#include "format_list.h"
#include "lutbake/formats/image_reader.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/rgbd.h"

namespace lutbake {

namespace {

std::string ChannelMapping(int channels) {
  if (channels == 1) return "grey = channel 0 (Y)";
  return channels == 2 ? "R = channel 0, G = channel 1, B = 0 (unused)"
                       : "R = channel 0, G = channel 1, B = channel 2";
}

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void PutU32(std::string *out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out->push_back(static_cast<char>((v >> shift) & 0xff));
}

uint32_t GetU32(const unsigned char *p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}

// One chunk: length, type, data, CRC-32 of type and data.
void PutChunk(std::string *out, const char type[4], const std::string &data) {
  PutU32(out, static_cast<uint32_t>(data.size()));
  const std::string typed = std::string(type, 4) + data;
  out->append(typed);
  PutU32(out, static_cast<uint32_t>(
                  crc32(0L, reinterpret_cast<const Bytef *>(typed.data()), typed.size())));
}

// The RGBA bytes of a texel in RGBD.
RgbdTexel EncodeTexel(const Table &table, size_t texel, const std::string &path) {
  try {
    return RgbdEncode(&table.values[texel * table.channels], table.channels);
  } catch (const std::invalid_argument &e) {
    throw IoError("cannot write " + path + " in RGBD: " + e.what());
  }
}

std::string RgbdMapping(int channels) {
  return "RGBD: channel c = (byte c / 255)^2.2 / (A / 255), " + std::to_string(channels) +
         " channel(s) in R, G, B (unused bytes 0)";
}

// A PNG file of `raw` (rows each led by filter byte 0, samples big-endian)
// with its IHDR, the tEXt pairs and one deflated IDAT. Colour type from
// the samples per pixel: 1 grey, 3 RGB, 4 RGBA.
std::string EncodePng(const std::string &path, int width, int height, int bits, int fileChannels,
                      const std::string &raw,
                      const std::vector<std::pair<std::string, std::string>> &text) {
  uLongf packedSize = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packedSize, '\0');
  if (compress2(reinterpret_cast<Bytef *>(packed.data()), &packedSize,
                reinterpret_cast<const Bytef *>(raw.data()), raw.size(), 9) != Z_OK)
    throw IoError("cannot write " + path + ": zlib could not deflate the image");
  packed.resize(packedSize);
  std::string file(reinterpret_cast<const char *>(kSignature), 8);
  std::string ihdr;
  PutU32(&ihdr, static_cast<uint32_t>(width));
  PutU32(&ihdr, static_cast<uint32_t>(height));
  ihdr.push_back(static_cast<char>(bits));
  ihdr.push_back(fileChannels == 1 ? 0 : fileChannels == 3 ? 2 : 6);  // grey, RGB, RGBA
  ihdr.append(3, '\0');  // deflate, adaptive filtering, no interlace
  PutChunk(&file, "IHDR", ihdr);
  for (const auto &[key, value] : text) {
    // tEXt: a Latin-1 keyword of 1 to 79 characters, a zero, the text.
    if (key.empty() || key.size() > 79 || value.find('\0') != std::string::npos)
      throw IoError("cannot write " + path + ": metadata key '" + key +
                    "' does not fit a PNG tEXt chunk");
    PutChunk(&file, "tEXt", key + std::string(1, '\0') + value);
  }
  PutChunk(&file, "IDAT", packed);
  PutChunk(&file, "IEND", "");
  return file;
}

class PngWriter final : public TableWriter {
 public:
  explicit PngWriter(ValueType type) : type_(type), bits_(type == ValueType::kUnorm16 ? 16 : 8) {}
  const char *formatName() const override {
    return type_ == ValueType::kRgbd8 ? "png-rgbd" : bits_ == 8 ? "png8" : "png16";
  }
  const char *extension() const override { return ".png"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    const bool rgbd = type_ == ValueType::kRgbd8;
    if (!rgbd) RequireUnitRange(table, path, "PNG");
    if (rgbd && table.channels > 3)
      throw IoError("cannot write " + path + ": RGBD holds at most three channels");
    const ValueType type = type_;
    const int width = table.width(), height = table.height() * table.depth();
    const int fileChannels = rgbd ? 4 : table.channels == 1 ? 1 : 3;
    const int bytesPerSample = bits_ / 8;
    // Rows, each led by its filter byte (0: none), samples big-endian.
    const size_t rowBytes = static_cast<size_t>(width) * fileChannels * bytesPerSample;
    std::string raw;
    raw.reserve((rowBytes + 1) * height);
    for (int y = 0; y < height; ++y) {
      raw.push_back('\0');
      for (int x = 0; x < width; ++x) {
        const size_t t = static_cast<size_t>(y) * width + x;
        if (rgbd) {
          const RgbdTexel texel = EncodeTexel(table, t, path);
          raw.append(texel.rgb.begin(), texel.rgb.end());
          raw.push_back(static_cast<char>(texel.d));
          continue;
        }
        for (int c = 0; c < fileChannels; ++c) {
          const unsigned q =
              c < table.channels ? QuantizeUnorm(table.values[t * table.channels + c], bits_) : 0u;
          if (bits_ == 16) raw.push_back(static_cast<char>(q >> 8));
          raw.push_back(static_cast<char>(q & 0xff));
        }
      }
    }
    std::vector<std::pair<std::string, std::string>> metadata = MetadataForStorage(table, type);
    if (rgbd) {
      metadata.emplace_back("channelMapping", RgbdMapping(table.channels));
    } else {
      metadata.emplace_back("quantisationStep", "1/" + std::to_string((1u << bits_) - 1u));
      metadata.emplace_back("channelMapping", ChannelMapping(table.channels));
    }
    const std::string file = EncodePng(path, width, height, bits_, fileChannels, raw, metadata);
    WriteWholeFile(path, file);
  }

 private:
  ValueType type_;
  int bits_;
};

// Undoes PNG's five row filters in place (none, sub, up, average, Paeth).
bool Unfilter(std::string *raw, size_t rowBytes, int height, int bytesPerPixel) {
  std::vector<unsigned char> previous(rowBytes, 0), current(rowBytes);
  size_t out = 0;
  for (int y = 0; y < height; ++y) {
    const size_t at = static_cast<size_t>(y) * (rowBytes + 1);
    const int filter = static_cast<unsigned char>((*raw)[at]);
    for (size_t i = 0; i < rowBytes; ++i) {
      const int x = static_cast<unsigned char>((*raw)[at + 1 + i]);
      const int a = i >= static_cast<size_t>(bytesPerPixel) ? current[i - bytesPerPixel] : 0;
      const int b = previous[i];
      const int c = i >= static_cast<size_t>(bytesPerPixel) ? previous[i - bytesPerPixel] : 0;
      int predictor = 0;
      switch (filter) {
        case 0: predictor = 0; break;
        case 1: predictor = a; break;
        case 2: predictor = b; break;
        case 3: predictor = (a + b) / 2; break;
        case 4: {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default: return false;
      }
      current[i] = static_cast<unsigned char>((x + predictor) & 0xff);
    }
    std::memcpy(&(*raw)[out], current.data(), rowBytes);
    out += rowBytes;
    previous.swap(current);
  }
  raw->resize(out);
  return true;
}

}  // namespace

std::unique_ptr<TableWriter> MakePngWriter(int bits) {
  return std::make_unique<PngWriter>(bits == 8 ? ValueType::kUnorm8 : ValueType::kUnorm16);
}

namespace {

// A PNG's chunks, checked and inflated: the samples (grey, grey + alpha,
// RGB or RGBA at 8 or 16 bits; `fileChannels` of them per pixel, row 0
// first) and its tEXt pairs. `checkText` runs on the tEXt pairs before the
// image is inflated (ReadPngTable refuses a PNG lutbake did not write there).
struct DecodedPng {
  int width = 0, height = 0, bits = 0, colourType = -1, fileChannels = 0;
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<unsigned> samples;
};

DecodedPng DecodePng(const std::string &path,
                     const std::function<void(const DecodedPng &)> &checkText) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read " + path + ": " + std::strerror(errno));
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto *bytes = reinterpret_cast<const unsigned char *>(file.data());
  const auto refuse = [&](const std::string &why) -> IoError {
    return IoError(path + ": " + why +
                   " (lutbake reads 8- or 16-bit grey, grey + alpha, RGB or RGBA PNGs)");
  };
  if (file.size() < 8 || std::memcmp(bytes, kSignature, 8) != 0) throw refuse("not a PNG");
  DecodedPng png;
  std::string packed;
  bool ended = false;
  for (size_t at = 8; at < file.size() && !ended;) {
    if (file.size() - at < 12) throw refuse("a chunk is cut off");
    const uint32_t length = GetU32(bytes + at);
    if (length > file.size() - at - 12) throw refuse("a chunk is longer than the file");
    const std::string type = file.substr(at + 4, 4);
    const std::string data = file.substr(at + 8, length);
    const uint32_t crc = GetU32(bytes + at + 8 + length);
    if (crc != crc32(0L, bytes + at + 4, length + 4))
      throw refuse("chunk " + type + " fails its CRC");
    if (type == "IHDR") {
      if (length != 13) throw refuse("IHDR is not 13 bytes");
      const auto *d = reinterpret_cast<const unsigned char *>(data.data());
      png.width = static_cast<int>(std::min<uint32_t>(GetU32(d), 1u << 24));
      png.height = static_cast<int>(std::min<uint32_t>(GetU32(d + 4), 1u << 24));
      png.bits = d[8];
      png.colourType = d[9];
      if (d[10] != 0 || d[11] != 0 || d[12] != 0)
        throw refuse("an unknown compression, filter or interlace method");
    } else if (type == "tEXt") {
      const size_t zero = data.find('\0');
      if (zero == std::string::npos) throw refuse("a tEXt chunk without its keyword's end");
      png.text.emplace_back(data.substr(0, zero), data.substr(zero + 1));
    } else if (type == "IDAT") {
      packed += data;
    } else if (type == "IEND") {
      ended = true;
    }
    at += 12 + length;
  }
  if (!ended) throw refuse("no IEND chunk");
  // Colour types: 0 grey, 2 RGB, 4 grey + alpha, 6 RGBA (3, a palette, is no table).
  static const int kChannelsOfType[] = {1, 0, 3, 0, 2, 0, 4};
  if ((png.bits != 8 && png.bits != 16) || png.colourType < 0 || png.colourType > 6 ||
      kChannelsOfType[png.colourType] == 0 || png.width <= 0 || png.height <= 0)
    throw refuse("bit depth " + std::to_string(png.bits) + ", colour type " +
                 std::to_string(png.colourType));
  png.fileChannels = kChannelsOfType[png.colourType];
  checkText(png);
  const int bytesPerPixel = png.fileChannels * png.bits / 8;
  const size_t rowBytes = static_cast<size_t>(png.width) * bytesPerPixel;
  if ((rowBytes + 1) * static_cast<size_t>(png.height) > (size_t{1} << 30))
    throw refuse("an image of " + std::to_string(png.width) + " x " + std::to_string(png.height) +
                 ", over 1 GiB");
  // Deflate inflates at most 1032-fold (a 258-byte match in two bits): an
  // image larger than that of its IDAT bytes is refused before it is
  // allocated, so that a 100-byte file cannot ask for a gigabyte.
  constexpr size_t kMaxInflateRatio = 1032;
  if ((rowBytes + 1) * static_cast<size_t>(png.height) > kMaxInflateRatio * packed.size())
    throw refuse("an image of " + std::to_string(png.width) + " x " + std::to_string(png.height) +
                 " from " + std::to_string(packed.size()) +
                 " bytes of IDAT, more than deflate can hold");
  std::string raw((rowBytes + 1) * png.height, '\0');
  uLongf rawSize = static_cast<uLongf>(raw.size());
  if (uncompress(reinterpret_cast<Bytef *>(raw.data()), &rawSize,
                 reinterpret_cast<const Bytef *>(packed.data()), packed.size()) != Z_OK ||
      rawSize != raw.size())
    throw refuse("the image data does not inflate to " + std::to_string(png.height) + " rows");
  if (!Unfilter(&raw, rowBytes, png.height, bytesPerPixel)) throw refuse("an unknown row filter");
  const auto *q = reinterpret_cast<const unsigned char *>(raw.data());
  const size_t samples = static_cast<size_t>(png.width) * png.height * png.fileChannels;
  png.samples.resize(samples);
  for (size_t i = 0; i < samples; ++i)
    png.samples[i] = png.bits == 8 ? q[i] : (unsigned{q[2 * i]} << 8) | q[2 * i + 1];
  return png;
}

}  // namespace

Table ReadPngTable(const std::string &path) {
  Table table;
  bool rgbd = false;  // 8-bit RGBA: RGBD (tables/rgbd.h), errorStorage rgbd8
  const DecodedPng png = DecodePng(path, [&](const DecodedPng &header) {
    rgbd = header.colourType == 6 && header.bits == 8;
    if (header.colourType != 0 && header.colourType != 2 && !rgbd)
      throw IoError(path + ": bit depth " + std::to_string(header.bits) + ", colour type " +
                    std::to_string(header.colourType) +
                    " (lutbake reads 8- or 16-bit grey or RGB PNGs, and 8-bit RGBA in RGBD)");
    table.metadata = header.text;
    const std::string *storage = table.FindMetadata("errorStorage");
    const std::string expected = rgbd ? "rgbd8" : header.bits == 8 ? "unorm8" : "unorm16";
    if (!storage || *storage != expected)
      throw IoError(path + ": not a table lutbake wrote (no tEXt errorStorage " + expected +
                    " in this " + std::to_string(header.bits) +
                    "-bit PNG); to judge it, run 'lutbake check " + path +
                    " --as TABLE' or 'lutbake identify " + path + "'");
    // RGB holds two channels and an unused B, or three (channelMapping says which).
    const std::string *mapping = table.FindMetadata("channelMapping");
    table.channels = header.fileChannels == 1                   ? 1
                     : mapping && *mapping == ChannelMapping(3) ? 3
                                                                : 2;
    for (int c = 1; rgbd && c <= 3; ++c)
      if (mapping && *mapping == RgbdMapping(c)) table.channels = c;
    table.channelNames = table.channels == 1   ? std::vector<std::string>{"Y"}
                         : table.channels == 2 ? std::vector<std::string>{"R", "G"}
                                               : std::vector<std::string>{"R", "G", "B"};
    ShapeFromMetadata(path, header.width, header.height, &table);
  });
  const double top = png.bits == 8 ? 255.0 : 65535.0;
  const size_t texels = static_cast<size_t>(png.width) * png.height;
  table.values.reserve(texels * table.channels);
  for (size_t t = 0; t < texels; ++t)
    for (int c = 0; c < table.channels; ++c) {
      if (!rgbd) {
        table.values.push_back(png.samples[t * png.fileChannels + c] / top);
        continue;
      }
      const unsigned d = png.samples[t * 4 + 3];
      if (d == 0) throw IoError(path + ": an RGBD divisor of 0 at texel " + std::to_string(t));
      table.values.push_back(RgbdDecode(static_cast<unsigned char>(png.samples[t * 4 + c]),
                                        static_cast<unsigned char>(d)));
    }
  return table;
}

RawImage ReadPngImage(const std::string &path) {
  const DecodedPng png = DecodePng(path, [](const DecodedPng &) {});
  RawImage image;
  image.format = "PNG";
  image.width = png.width;
  image.height = png.height;
  image.channels = png.fileChannels;
  image.storage = png.bits == 8 ? "unorm8" : "unorm16";
  const double top = png.bits == 8 ? 255.0 : 65535.0;
  image.values.reserve(png.samples.size());
  for (unsigned q : png.samples) image.values.push_back(q / top);
  static const std::vector<std::string> kNames[] = {
      {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  image.channelNames = kNames[png.fileChannels - 1];
  return image;
}

void WriteRgb8Png(const std::string &path, int width, int height, const std::vector<uint8_t> &rgb) {
  std::string raw;
  raw.reserve((static_cast<size_t>(width) * 3 + 1) * height);
  for (int y = 0; y < height; ++y) {
    raw.push_back('\0');
    raw.append(reinterpret_cast<const char *>(rgb.data()) + static_cast<size_t>(y) * width * 3,
               static_cast<size_t>(width) * 3);
  }
  const std::string file = EncodePng(path, width, height, 8, 3, raw, {});
  // A temporary beside it, renamed over it: never a half-written picture.
  const std::string temporary = path + ".lutbake-tmp";
  WriteWholeFile(temporary, file);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw IoError("cannot write " + path + ": " + reason);
  }
}

std::vector<TableFormat> PngFormats() {
  return {{"png8", ".png", FixedStorage(ValueType::kUnorm8), [] { return MakePngWriter(8); },
           ReadPngTable, true},
          {"png16", ".png", FixedStorage(ValueType::kUnorm16), [] { return MakePngWriter(16); },
           ReadPngTable, true},
          {"png-rgbd", ".png", FixedStorage(ValueType::kRgbd8),
           [] { return std::make_unique<PngWriter>(ValueType::kRgbd8); }, ReadPngTable, false}};
}

}  // namespace lutbake
