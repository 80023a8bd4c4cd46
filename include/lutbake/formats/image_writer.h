// Plain images, for pictures rather than tables: 8-bit PNG and float EXR.
//
// The PNG is written here without zlib: a deflate stream of "stored"
// (uncompressed) blocks of at most 65535 bytes, each scanline with filter
// type 0, the zlib header 0x78 0x01 and Adler-32 trailer, and a CRC-32 per
// chunk (PNG specification, sections 5 and 10; RFC 1950 and 1951). Files
// are larger than compressed ones, and every PNG reader opens them.
// Both throw IoError when the file cannot be written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lutbake {

// channels 1 (grey), 3 (RGB) or 4 (RGBA); pixels row by row from the top,
// width * height * channels bytes.
void WritePng(const std::string &path, int width, int height, int channels,
              const std::vector<uint8_t> &pixels);

// One 32-bit float channel per name ("Y", or "R", "G", "B"), interleaved
// like pixels; y = 0 the top scanline.
void WriteExrImage(const std::string &path, int width, int height,
                   const std::vector<std::string> &channelNames, const std::vector<float> &pixels);

// x in [0, 1] to 8 bits, rounded to nearest, clamped.
uint8_t ToByte(double x);

}  // namespace lutbake
