// Reading any table file, not only those lutbake wrote, for `lutbake check
// FILE --as TABLE` and `lutbake identify FILE`: the texels of a PNG (8 or
// 16 bits, grey, grey + alpha, RGB or RGBA), an OpenEXR image (any float or
// half channels), a DDS (DX10 header or the legacy float FourCCs), a KTX2
// (unorm, half or float formats, one level), a Radiance HDR (RGBE) or the
// numbers of a C/C++/JS/shader array, with no metadata asked of them. What
// the values mean is the caller's question (lutbake/api/identify.h).
//
// Values are as stored: q / (2^b - 1) for unorm, the float or half widened,
// RGBE decoded as (m + 0.5) 2^(e - 136) (Radiance's own colr_color); row 0
// is the first row in the file, x fastest, channels interleaved.
// Throws UnreadableError (core/error.h) naming the file when it cannot be
// opened, is no image of these formats or is malformed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lutbake {

struct RawImage {
  std::string format;  // "PNG", "OpenEXR", "DDS", "KTX2", "Radiance HDR", "source array"
  int width = 0, height = 0, channels = 0;
  std::vector<double> values;
  // How the values are stored: "unorm8", "unorm16", "half", "float32",
  // "rgbe" or "text" (decimal literals; half or float bit patterns are
  // "half" / "float32").
  std::string storage;
  // A source array has no shape: width = values / channels, height 1, and
  // `flat` set; `groupSize` is the length of its innermost braces or
  // brackets when they are all equal ({{a, b}, {c, d}}: 2), else 0.
  bool flat = false;
  int groupSize = 0;
  // Decimal literals only: half a unit in the last digit written, per
  // value (0.125 -> 5e-4; 1e-05 -> 5e-6).
  std::vector<double> literalHalfUnit;
  // Channel names where the file has them (EXR), else R, G, B, A or Y.
  std::vector<std::string> channelNames;
};

// By the file's first bytes, not its name.
RawImage ReadRawImage(const std::string &path);

// The format readers ReadRawImage dispatches to (PNG in png_table.cpp,
// OpenEXR in table_reader.cpp, the rest in image_reader.cpp); each throws
// IoError on a malformed file.
RawImage ReadPngImage(const std::string &path);
RawImage ReadExrImage(const std::string &path);
RawImage ReadDdsImage(const std::string &path);
RawImage ReadKtx2Image(const std::string &path);
RawImage ReadHdrImage(const std::string &path);
RawImage ReadSourceArray(const std::string &path);

// A picture (the error image of `check --as`): an 8-bit RGB PNG, `rgb`
// holding width x height x 3 bytes, row 0 at the top; written to a
// temporary and renamed. Throws IoError naming the file.
void WriteRgb8Png(const std::string &path, int width, int height, const std::vector<uint8_t> &rgb);

}  // namespace lutbake
