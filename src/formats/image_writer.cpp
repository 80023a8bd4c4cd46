#include "lutbake/formats/image_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <array>
#include <cmath>
#include <fstream>

#include "lutbake/formats/writer.h"

namespace lutbake {

namespace {

// CRC-32 of PNG chunks (polynomial 0xEDB88320, reflected), table-driven.
uint32_t Crc32(const uint8_t *data, size_t size, uint32_t crc = 0) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

void PutBigEndian(std::vector<uint8_t> &out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
}

void AppendChunk(std::vector<uint8_t> &file, const char type[4], const std::vector<uint8_t> &data) {
  PutBigEndian(file, static_cast<uint32_t>(data.size()));
  std::vector<uint8_t> typed(type, type + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  file.insert(file.end(), typed.begin(), typed.end());
  PutBigEndian(file, Crc32(typed.data(), typed.size()));
}

}  // namespace

uint8_t ToByte(double x) {
  if (!(x > 0.0)) return 0;
  if (x >= 1.0) return 255;
  return static_cast<uint8_t>(std::lround(x * 255.0));
}

void WritePng(const std::string &path, int width, int height, int channels,
              const std::vector<uint8_t> &pixels) {
  const uint8_t colourType = channels == 1 ? 0 : (channels == 3 ? 2 : 6);
  // The raw stream: a filter byte (0, none) before every scanline.
  const size_t rowBytes = static_cast<size_t>(width) * channels;
  std::vector<uint8_t> raw;
  raw.reserve((rowBytes + 1) * height);
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), pixels.begin() + y * rowBytes, pixels.begin() + (y + 1) * rowBytes);
  }
  // zlib: header, stored deflate blocks, Adler-32 of the raw stream.
  std::vector<uint8_t> z{0x78, 0x01};
  for (size_t pos = 0; pos < raw.size() || pos == 0;) {
    const size_t n = std::min<size_t>(65535, raw.size() - pos);
    const bool last = pos + n == raw.size();
    z.push_back(last ? 1 : 0);
    z.push_back(static_cast<uint8_t>(n & 0xFF));
    z.push_back(static_cast<uint8_t>(n >> 8));
    z.push_back(static_cast<uint8_t>(~n & 0xFF));
    z.push_back(static_cast<uint8_t>((~n >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + pos, raw.begin() + pos + n);
    pos += n;
    if (last) break;
  }
  uint32_t a = 1, b = 0;
  for (uint8_t v : raw) {
    a = (a + v) % 65521u;
    b = (b + a) % 65521u;
  }
  PutBigEndian(z, (b << 16) | a);

  std::vector<uint8_t> file{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> header;
  PutBigEndian(header, static_cast<uint32_t>(width));
  PutBigEndian(header, static_cast<uint32_t>(height));
  header.insert(header.end(),
                {8, colourType, 0, 0, 0});  // depth, type, deflate, filter, no interlace
  AppendChunk(file, "IHDR", header);
  AppendChunk(file, "IDAT", z);
  AppendChunk(file, "IEND", {});
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char *>(file.data()), static_cast<std::streamsize>(file.size()));
  out.close();
  if (!out) throw IoError("cannot write " + path);
}

void WriteExrImage(const std::string &path, int width, int height,
                   const std::vector<std::string> &channelNames, const std::vector<float> &pixels) {
  const int channels = static_cast<int>(channelNames.size());
  std::vector<float> copy = pixels;
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.lineOrder() = Imf::INCREASING_Y;
    for (const std::string &name : channelNames)
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::FrameBuffer frame;
    const size_t xStride = sizeof(float) * channels, yStride = xStride * width;
    for (int c = 0; c < channels; ++c)
      frame.insert(
          channelNames[c],
          Imf::Slice(Imf::FLOAT, reinterpret_cast<char *>(copy.data() + c), xStride, yStride));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception &e) {
    throw IoError("cannot write " + path + ": " + e.what());
  }
}

}  // namespace lutbake
