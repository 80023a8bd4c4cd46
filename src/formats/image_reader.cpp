// ReadRawImage (image_reader.h): any table file, by its first bytes. PNG
// and OpenEXR are decoded beside their table readers (png_table.cpp,
// table_reader.cpp); DDS, KTX2, Radiance HDR and source arrays here.
#include "lutbake/formats/image_reader.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "lutbake/core/error.h"
#include "texel_bytes.h"

namespace lutbake {

namespace {

using texel_bytes::Reader;

// `count` values from `offset` stored as "unorm8", "unorm16", "half" or
// "float32", widened (unorm as q / (2^b - 1)).
std::vector<double> Texels(const Reader &r, size_t offset, size_t count,
                           const std::string &storage) {
  if (storage == "half") return r.Values(offset, count, ValueType::kHalf);
  if (storage == "float32") return r.Values(offset, count, ValueType::kFloat32);
  const int bytes = storage == "unorm8" ? 1 : 2;
  r.Need(offset, count * bytes);  // count <= file size: no overflow
  std::vector<double> values(count);
  const double top = bytes == 1 ? 255.0 : 65535.0;
  for (size_t i = 0; i < count; ++i) values[i] = r.Get(offset + i * bytes, bytes) / top;
  return values;
}

struct TexelFormat {
  uint32_t code;
  int channels;
  const char *storage;
};

const char *const kRgba[] = {"R", "G", "B", "A"};

void CheckSize(const std::string &path, uint64_t width, uint64_t height) {
  if (width < 1 || height < 1 || width > (1u << 16) || height > (1u << 16))
    throw IoError(path + ": image size " + std::to_string(width) + " x " + std::to_string(height) +
                  " out of range");
}

}  // namespace

// DDS: the DX10 header (dxgiFormat) or a legacy D3DFMT FourCC, one 2D
// texture (or a volume's slices stacked along y), mip level 0.
RawImage ReadDdsImage(const std::string &path) {
  const std::vector<uint8_t> bytes = texel_bytes::ReadFileBytes(path);
  const Reader r(bytes, path);
  r.Need(0, 128);
  if (r.Get32(0) != 0x20534444u || r.Get32(4) != 124) throw IoError(path + ": not a DDS file");
  static const TexelFormat kDxgi[] = {{2, 4, "float32"},  {6, 3, "float32"},  {10, 4, "half"},
                                      {11, 4, "unorm16"}, {16, 2, "float32"}, {28, 4, "unorm8"},
                                      {29, 4, "unorm8"},  {34, 2, "half"},    {35, 2, "unorm16"},
                                      {41, 1, "float32"}, {49, 2, "unorm8"},  {54, 1, "half"},
                                      {56, 1, "unorm16"}, {61, 1, "unorm8"}};
  static const TexelFormat kFourCc[] = {{111, 1, "half"},    {112, 2, "half"},
                                        {113, 4, "half"},    {114, 1, "float32"},
                                        {115, 2, "float32"}, {116, 4, "float32"}};
  const bool dx10 = r.Get32(84) == 0x30315844u;
  const uint32_t code = dx10 ? r.Get32(128) : r.Get32(84);
  const TexelFormat *format = nullptr;
  for (const TexelFormat &f :
       dx10 ? std::vector<TexelFormat>(std::begin(kDxgi), std::end(kDxgi))
            : std::vector<TexelFormat>(std::begin(kFourCc), std::end(kFourCc)))
    if (f.code == code) format = &f;
  if (!format)
    throw IoError(path + ": " + (dx10 ? "dxgiFormat " : "FourCC ") + std::to_string(code) +
                  " is not an uncompressed unorm, half or float format lutbake reads");
  RawImage image;
  image.format = "DDS";
  image.width = static_cast<int>(std::min<uint32_t>(r.Get32(16), 1u << 20));
  const uint32_t slices = (r.Get32(112) & 0x200000u) ? std::max<uint32_t>(r.Get32(24), 1) : 1;
  CheckSize(path, image.width, uint64_t{r.Get32(12)} * slices);
  image.height = static_cast<int>(r.Get32(12) * slices);
  image.channels = format->channels;
  image.storage = format->storage;
  image.channelNames.assign(kRgba, kRgba + image.channels);
  image.values =
      Texels(r, dx10 ? 148 : 128, static_cast<size_t>(image.width) * image.height * image.channels,
             image.storage);
  return image;
}

// KTX2: one face, one layer, no supercompression; level 0 (the largest).
RawImage ReadKtx2Image(const std::string &path) {
  static const uint8_t kIdentifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                          '0',  0xBB, '\r', '\n', 0x1A, '\n'};
  const std::vector<uint8_t> bytes = texel_bytes::ReadFileBytes(path);
  const Reader r(bytes, path);
  r.Need(0, 104);
  if (!std::equal(kIdentifier, kIdentifier + 12, bytes.begin()))
    throw IoError(path + ": no KTX 2.0 identifier");
  static const TexelFormat kVk[] = {
      {9, 1, "unorm8"},    {16, 2, "unorm8"},   {23, 3, "unorm8"},   {37, 4, "unorm8"},
      {43, 4, "unorm8"},   {70, 1, "unorm16"},  {77, 2, "unorm16"},  {91, 4, "unorm16"},
      {76, 1, "half"},     {83, 2, "half"},     {90, 3, "half"},     {97, 4, "half"},
      {100, 1, "float32"}, {103, 2, "float32"}, {106, 3, "float32"}, {109, 4, "float32"}};
  const uint32_t vkFormat = r.Get32(12);
  const TexelFormat *format = nullptr;
  for (const TexelFormat &f : kVk)
    if (f.code == vkFormat) format = &f;
  if (!format)
    throw IoError(path + ": vkFormat " + std::to_string(vkFormat) +
                  " is not an uncompressed unorm, half or float format lutbake reads");
  if (r.Get32(36) > 1 || r.Get32(40) != 1 || r.Get32(44) != 0)
    throw IoError(path + ": not a single-face, single-layer, unsupercompressed texture");
  const uint32_t slices = std::max<uint32_t>(r.Get32(28), 1);
  CheckSize(path, r.Get32(20), uint64_t{r.Get32(24)} * slices);
  RawImage image;
  image.format = "KTX2";
  image.width = static_cast<int>(r.Get32(20));
  image.height = static_cast<int>(std::max<uint32_t>(r.Get32(24), 1) * slices);
  image.channels = format->channels;
  image.storage = format->storage;
  image.channelNames.assign(kRgba, kRgba + image.channels);
  const size_t count = static_cast<size_t>(image.width) * image.height * image.channels;
  image.values = Texels(r, static_cast<size_t>(std::min<uint64_t>(r.Get(80, 8), bytes.size())),
                        count, image.storage);
  return image;
}

// Radiance HDR: "#?RADIANCE" (or "#?RGBE"), header lines up to an empty
// one, "-Y H +X W", then each scanline flat or in the new run-length form
// (2, 2, W / 256, W % 256, then the four byte planes, each as runs: n >
// 128 is n - 128 copies of the next byte, else n literal bytes).
RawImage ReadHdrImage(const std::string &path) {
  const std::vector<uint8_t> bytes = texel_bytes::ReadFileBytes(path);
  const auto refuse = [&](const std::string &why) { return IoError(path + ": " + why); };
  size_t at = 0;
  const auto line = [&] {
    const auto end = std::find(bytes.begin() + static_cast<ptrdiff_t>(at), bytes.end(), '\n');
    if (end == bytes.end()) throw refuse("the Radiance header is cut off");
    std::string text(bytes.begin() + static_cast<ptrdiff_t>(at), end);
    at = static_cast<size_t>(end - bytes.begin()) + 1;
    return text;
  };
  if (line().rfind("#?", 0) != 0) throw refuse("not a Radiance HDR file");
  for (std::string l = line(); !l.empty(); l = line())
    if (l.rfind("FORMAT=", 0) == 0 && l != "FORMAT=32-bit_rle_rgbe")
      throw refuse("FORMAT " + l.substr(7) + " (lutbake reads 32-bit_rle_rgbe)");
  long height = 0, width = 0;
  if (std::sscanf(line().c_str(), "-Y %ld +X %ld", &height, &width) != 2)
    throw refuse("the resolution line is not '-Y H +X W'");
  CheckSize(path, static_cast<uint64_t>(std::max(width, 0L)),
            static_cast<uint64_t>(std::max(height, 0L)));
  if (static_cast<uint64_t>(width) * height > 4 * bytes.size())
    throw refuse("more pixels than the file can hold");
  std::vector<uint8_t> rgbe(static_cast<size_t>(width) * height * 4);
  const auto next = [&] {
    if (at >= bytes.size()) throw refuse("the pixels are cut off");
    return bytes[at++];
  };
  for (long y = 0; y < height; ++y) {
    uint8_t *row = &rgbe[static_cast<size_t>(y) * width * 4];
    const bool rle = width >= 8 && width < 32768 && at + 4 <= bytes.size() && bytes[at] == 2 &&
                     bytes[at + 1] == 2 && ((bytes[at + 2] << 8) | bytes[at + 3]) == width;
    if (!rle) {
      for (long i = 0; i < width * 4; ++i) row[i] = next();
      continue;
    }
    at += 4;
    for (int plane = 0; plane < 4; ++plane)
      for (long x = 0; x < width;) {
        const int n = next();
        const int run = n > 128 ? n - 128 : n;
        if (run == 0 || x + run > width) throw refuse("a run overruns its scanline");
        const uint8_t repeated = n > 128 ? next() : 0;
        for (int k = 0; k < run; ++k, ++x) row[x * 4 + plane] = n > 128 ? repeated : next();
      }
  }
  RawImage image;
  image.format = "Radiance HDR";
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.channels = 3;
  image.storage = "rgbe";
  image.channelNames = {"R", "G", "B"};
  image.values.reserve(static_cast<size_t>(width) * height * 3);
  for (size_t p = 0; p < rgbe.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      image.values.push_back(rgbe[p + 3] == 0 ? 0.0
                                              : std::ldexp(rgbe[p + c] + 0.5, rgbe[p + 3] - 136));
  return image;
}

namespace {

// The text without comments (// ..., /* ... */) and preprocessor lines,
// which hold numbers that are no values.
std::string WithoutComments(const std::string &text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if (text.compare(i, 2, "//") == 0 || (text[i] == '#' && (i == 0 || text[i - 1] == '\n'))) {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    } else if (text.compare(i, 2, "/*") == 0) {
      i = text.find("*/", i + 2);
      if (i == std::string::npos) break;
      i += 2;
      out += ' ';
    } else {
      out += text[i++];
    }
  }
  return out;
}

bool IdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// One bracketed group's literals: each value, whether it was a hexadecimal
// or bare integer, its half unit, and the sizes of the innermost groups.
struct Literals {
  std::vector<double> values;
  std::vector<double> halfUnit;  // 0 for an integer
  size_t hex = 0, integers = 0;
  int innermost = -1;  // size of the innermost groups: -1 none seen, 0 unequal
  size_t end = 0;      // just after the group's closing bracket
};

// The literals of the group opening at text[open].
Literals GroupLiterals(const std::string &text, size_t open) {
  Literals out;
  std::vector<size_t> counts{0};  // values directly in each open group
  std::vector<bool> nested{false};
  size_t i = open + 1;
  for (; i < text.size() && !counts.empty(); ++i) {
    const char c = text[i];
    if (c == '{' || c == '[' || c == '(') {
      counts.push_back(0);
      nested.back() = true;
      nested.push_back(false);
    } else if (c == '}' || c == ']' || c == ')') {
      if (!nested.back() && counts.size() > 1 && counts.back() > 0) {
        const int size = static_cast<int>(counts.back());
        out.innermost = out.innermost == -1 || out.innermost == size ? size : 0;
      }
      counts.pop_back();
      nested.pop_back();
    } else if ((std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') &&
               !IdentifierChar(text[i - 1]) && text[i - 1] != '.') {
      const char *start = text.c_str() + i;
      char *after = nullptr;
      const bool isHex = c == '0' && (text[i + 1] == 'x' || text[i + 1] == 'X');
      const double v = isHex ? static_cast<double>(std::strtoull(start, &after, 16))
                             : std::strtod(start, &after);
      if (after == start) continue;  // a sign or dot alone
      const std::string literal(start, static_cast<size_t>(after - start));
      const size_t dot = literal.find('.'), exponent = literal.find_first_of("eE");
      const bool integer = isHex || (dot == std::string::npos && exponent == std::string::npos);
      double halfUnit = 0.0;
      if (!integer) {
        const size_t mantissaEnd = exponent == std::string::npos ? literal.size() : exponent;
        const long decimals =
            dot == std::string::npos ? 0 : static_cast<long>(mantissaEnd - dot - 1);
        const long power = exponent == std::string::npos ? 0 : std::atol(&literal[exponent + 1]);
        halfUnit = 0.5 * std::pow(10.0, static_cast<double>(power - decimals));
      }
      out.values.push_back(v);
      out.halfUnit.push_back(halfUnit);
      out.hex += isHex;
      out.integers += integer;
      ++counts.back();
      i = static_cast<size_t>(after - text.c_str());
      while (i < text.size() && std::strchr("fFhHuUlL", text[i])) ++i;
      --i;
    }
  }
  out.end = i;
  return out;
}

}  // namespace

// A source array: the bracketed group ({...}, [...] or (...), nested or
// not) with the most numeric literals, comments left out. Hexadecimal
// literals, or integers under a Uint16Array / uint16_t type, are binary16
// bit patterns; otherwise the literals are the values.
RawImage ReadSourceArray(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path);
  const std::string raw{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (raw.size() > (size_t{1} << 28)) throw IoError(path + ": over 256 MiB");
  const std::string text = WithoutComments(raw);
  Literals best;
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '{' || text[i] == '[' || text[i] == '(') {
      Literals group = GroupLiterals(text, i);
      i = group.end - 1;  // the loop steps onto the character after the group
      if (group.values.size() > best.values.size()) best = std::move(group);
    }
  // A bare list (Filament's dfg.inc, included between braces elsewhere):
  // the whole text, when most of its literals lie outside any one group.
  Literals whole = GroupLiterals("{" + text + "}", 0);
  if (2 * best.values.size() < whole.values.size()) best = std::move(whole);
  if (best.values.size() < 2)
    throw IoError(path +
                  ": no array of numbers (lutbake reads PNG, OpenEXR, DDS, KTX2, "
                  "Radiance HDR and C, C++, JS or shader arrays)");
  RawImage image;
  image.format = "source array";
  const bool halfBits =
      best.hex == best.values.size() ||
      (best.integers == best.values.size() &&
       (raw.find("Uint16Array") != std::string::npos || raw.find("uint16_t") != std::string::npos));
  if (halfBits) {
    image.storage = "half";
    for (double &v : best.values) {
      if (v < 0.0 || v > 65535.0)
        throw IoError(path + ": an integer literal is no binary16 bit pattern");
      Imath::half h;
      h.setBits(static_cast<unsigned short>(v));
      v = static_cast<float>(h);
    }
  } else {
    image.storage = "text";
    // A bare integer ("1" where %g dropped ".00000") is as precise as the
    // file's typical literal: the median of the others' half units.
    std::vector<double> units;
    for (double u : best.halfUnit)
      if (u > 0.0) units.push_back(u);
    std::nth_element(units.begin(), units.begin() + static_cast<ptrdiff_t>(units.size() / 2),
                     units.end());
    const double typical = units.empty() ? 0.0 : units[units.size() / 2];
    for (double &u : best.halfUnit)
      if (u == 0.0) u = typical;
    image.literalHalfUnit = best.halfUnit;
  }
  image.groupSize = best.innermost > 0 && best.innermost <= 4 ? best.innermost : 0;
  image.flat = true;
  image.channels = 1;
  image.width = static_cast<int>(best.values.size());
  image.height = 1;
  image.values = std::move(best.values);
  image.channelNames = {"Y"};
  return image;
}

RawImage ReadRawImage(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UnreadableError("cannot open " + path + ": " + std::strerror(errno));
  char head[16] = {};
  in.read(head, sizeof head);
  const size_t got = static_cast<size_t>(in.gcount());
  if (got == 0) throw UnreadableError(path + ": empty (or a directory)");
  const auto starts = [&](const char *magic, size_t n) {
    return got >= n && std::memcmp(head, magic, n) == 0;
  };
  try {
    if (starts("\x89PNG\r\n\x1a\n", 8)) return ReadPngImage(path);
    if (starts("\x76\x2f\x31\x01", 4)) return ReadExrImage(path);
    if (starts("DDS ", 4)) return ReadDdsImage(path);
    if (starts("\xabKTX 20", 7)) return ReadKtx2Image(path);
    if (starts("#?", 2)) return ReadHdrImage(path);
    // Text: no NUL and no control bytes but white space in the first bytes.
    for (size_t i = 0; i < got; ++i)
      if (static_cast<unsigned char>(head[i]) < 0x20 && !std::strchr("\t\n\r\f", head[i]))
        throw IoError(path +
                      ": not a PNG, OpenEXR, DDS, KTX2 or Radiance HDR image, nor the text of an "
                      "array");
    return ReadSourceArray(path);
  } catch (const IoError &e) {
    throw UnreadableError(e.what());
  }
}

}  // namespace lutbake
