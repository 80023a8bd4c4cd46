#include "lutbake/formats/table_reader.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "lutbake/formats/image_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

namespace {

// "T" of "T", "T.err" or "T.fit".
std::string PlainTableName(const std::string &name) {
  for (const char *suffix : {".err", ".fit"})
    if (name.size() > 4 && name.compare(name.size() - 4, 4, suffix) == 0)
      return name.substr(0, name.size() - 4);
  return name;
}

// The channel names of the table (or fit map) the metadata key 'table'
// names, or none.
std::vector<std::string> DefinitionChannelNames(const Table &table) {
  const std::string *name = table.FindMetadata("table");
  if (!name) return {};
  const TableDefinition *definition = FindTable(PlainTableName(*name));
  if (!definition) return {};
  const bool fit = name->size() > 4 && name->compare(name->size() - 4, 4, ".fit") == 0;
  return fit ? definition->FitMapNames() : definition->ChannelNames();
}

}  // namespace

void ShapeFromMetadata(const std::string &path, long width, long height, Table *tablePtr) {
  Table &table = *tablePtr;
  const std::string *axisX = table.FindMetadata("axisX");
  const std::string *axisY = table.FindMetadata("axisY");
  if (!axisX || !ParseAxisDescription(*axisX, &table.x))
    throw IoError(path +
                  ": attribute axisX missing or not of the form "
                  "'name linear [min, max], N texels'");
  const bool axisYParsed = axisY && ParseAxisDescription(*axisY, &table.y);
  if (!axisYParsed && height == 1) {
    table.y = LinearAxis("", 0.0, 1.0, 1);  // a 1D table: axisY reads "none (1D table)"
  } else if (!axisYParsed) {
    throw IoError(path + ": attribute axisY missing or malformed for a 2D image");
  }
  // A 3D table: axisZ names the third axis, whose slices are stacked
  // along the image's y.
  if (const std::string *axisZ = table.FindMetadata("axisZ")) {
    if (!ParseAxisDescription(*axisZ, &table.z) || table.z.name.empty())
      throw IoError(path + ": attribute axisZ malformed");
    if (!axisYParsed) throw IoError(path + ": attribute axisZ without axisY");
  }
  if (table.x.count != width || static_cast<long>(table.y.count) * table.z.count != height)
    throw IoError(path + ": image is " + std::to_string(width) + " x " + std::to_string(height) +
                  " but the axes say " + std::to_string(table.x.count) + " x " +
                  std::to_string(table.y.count) +
                  (table.is3D() ? " x " + std::to_string(table.z.count) : std::string()));
  // "T", or "T.err" for an error map (ErrorMapOf), "T.fit" for a fit map (FitMapOf).
  const std::string *name = table.FindMetadata("table");
  if (name) table.definition = FindTable(PlainTableName(*name));
  // An engine preset's texture (lutbake/presets/preset.h) is no table
  // definition's: its metadata names the preset instead.
  if (!table.definition && !table.FindMetadata("preset"))
    throw IoError(path + ": attribute 'table' missing or not one of " + TableNameList());
}

namespace {

uint32_t GetLE32(const std::string &bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

// OpenEXR allocates what a header says before it can know better: each
// attribute's value at its stated size (a 2 GB attribute in a 1 KB file), a
// preview image or string vector at the sizes inside it, and line buffers and
// a chunk table for the data window; and it reads fixed-size and channel
// list values at their own length whatever size the file states, so that a
// wrong size shifts everything after it. So the header is walked here first,
// the way OpenEXR will read it, and the file refused unless it is a
// single-part scanline image (lutbake writes nothing else) whose every
// attribute fits in what is left of the file, is as long as its type says
// and holds no size larger than itself, and whose pixels the file can hold:
// no compression of OpenEXR inflates more than about 1400-fold (ZIP's
// deflate 1032-fold, PXR24 deflates 24 of every 32 bits, RLE 64-fold, PIZ's
// Huffman runs about 450-fold), so a data window over 65536 texels a side, or
// of more than 2048 times the file's size in float32 channels, is refused
// before OpenEXR allocates for it.
void CheckExrHeader(const std::string &path, const std::string &bytes) {
  const auto refuse = [&](const std::string &why) { return IoError(path + ": " + why); };
  constexpr uint32_t kMagic = 20000630;
  if (bytes.size() < 8 || GetLE32(bytes, 0) != kMagic) throw refuse("not an OpenEXR file");
  const uint32_t version = GetLE32(bytes, 4);
  constexpr uint32_t kTiled = 0x200, kLongNames = 0x400, kDeep = 0x800, kMultiPart = 0x1000;
  if ((version & 0xff) != 2 || (version & (kTiled | kDeep | kMultiPart)) != 0)
    throw refuse("not a single-part scanline OpenEXR 2 image (version field " +
                 std::to_string(version) + ")");
  const size_t maxName = (version & kLongNames) ? 255 : 31;
  // A NUL-terminated name of at most `longest` characters at *at, before `end`.
  const auto name = [&](size_t *at, size_t end, size_t longest) {
    const size_t nul = bytes.find('\0', *at);
    if (nul == std::string::npos || nul >= end || nul - *at > longest)
      throw refuse("a name in the header is unterminated or too long");
    std::string text = bytes.substr(*at, nul - *at);
    *at = nul + 1;
    return text;
  };
  // The value sizes of OpenEXR's fixed-size attribute types.
  static const std::pair<const char *, uint32_t> kFixedSizes[] = {{"box2i", 16},
                                                                  {"box2f", 16},
                                                                  {"chromaticities", 32},
                                                                  {"compression", 1},
                                                                  {"deepImageState", 1},
                                                                  {"double", 8},
                                                                  {"envmap", 1},
                                                                  {"float", 4},
                                                                  {"int", 4},
                                                                  {"keycode", 28},
                                                                  {"lineOrder", 1},
                                                                  {"m33f", 36},
                                                                  {"m33d", 72},
                                                                  {"m44f", 64},
                                                                  {"m44d", 128},
                                                                  {"rational", 8},
                                                                  {"tiledesc", 9},
                                                                  {"timecode", 8},
                                                                  {"v2i", 8},
                                                                  {"v2f", 8},
                                                                  {"v2d", 16},
                                                                  {"v3i", 12},
                                                                  {"v3f", 12},
                                                                  {"v3d", 24}};
  long width = 0, height = 0, channels = 0;
  for (size_t at = 8;;) {
    const std::string attribute = name(&at, bytes.size(), maxName);
    if (attribute.empty()) break;  // the header's end
    const std::string type = name(&at, bytes.size(), maxName);
    if (bytes.size() - at < 4) throw refuse("the header is cut off");
    const uint32_t size = GetLE32(bytes, at);
    at += 4;
    const size_t end = at + size;
    if (size > bytes.size() - at)
      throw refuse("attribute " + attribute + " says " + std::to_string(size) +
                   " bytes, more than the file has left");
    const auto malformed = [&] {
      return refuse("attribute " + attribute + " (" + type + ") is malformed");
    };
    for (const auto &[fixedType, fixedSize] : kFixedSizes)
      if (type == fixedType && size != fixedSize) throw malformed();
    if (type == "chlist") {
      // Channels: a name, NUL, 16 bytes (type, linearity, sampling); then NUL.
      size_t c = at;
      while (c < end && bytes[c] != '\0') {
        const size_t nul = bytes.find('\0', c);
        if (nul == std::string::npos || nul >= end || nul - c > 255 || end - nul - 1 < 16)
          throw malformed();
        c = nul + 17;
        ++channels;
      }
      if (c + 1 != end) throw malformed();
    } else if (type == "preview") {
      // Width and height, then 4 bytes a pixel.
      if (size < 8 ||
          uint64_t{GetLE32(bytes, at)} * GetLE32(bytes, at + 4) * 4 != uint64_t{size} - 8)
        throw malformed();
    } else if (type == "stringvector") {
      // Strings, each a length and its characters.
      for (size_t c = at; c < end; c += 4 + GetLE32(bytes, c))
        if (end - c < 4 || GetLE32(bytes, c) > end - c - 4) throw malformed();
    } else if (type == "floatvector") {
      if (size % 4 != 0) throw malformed();
    } else if (type == "idmanifest") {
      throw refuse("attribute " + attribute + ": an ID manifest, which lutbake does not read");
    }
    if (attribute == "dataWindow" && type == "box2i") {
      const auto corner = [&](int i) { return static_cast<int32_t>(GetLE32(bytes, at + 4 * i)); };
      width = static_cast<long>(corner(2)) - corner(0) + 1;
      height = static_cast<long>(corner(3)) - corner(1) + 1;
    }
    at = end;
  }
  if (width < 1 || height < 1 || width > (1 << 16) || height > (1 << 16))
    throw refuse("image size " + std::to_string(width) + " x " + std::to_string(height) +
                 " is not a lutbake table");
  constexpr uintmax_t kMaxCompressionRatio = 2048;
  const uintmax_t pixelBytes = static_cast<uintmax_t>(width) * height * channels * 4;
  if (pixelBytes > kMaxCompressionRatio * bytes.size())
    throw refuse("an image of " + std::to_string(width) + " x " + std::to_string(height) + " in " +
                 std::to_string(channels) + " channels cannot be held in " +
                 std::to_string(bytes.size()) + " bytes");
}

}  // namespace

Table ReadExrTable(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CheckExrHeader(path, bytes);
  Table table;
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile file(stream);
    const Imf::Header &header = file.header();
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (const auto *s = dynamic_cast<const Imf::StringAttribute *>(&it.attribute()))
        table.metadata.emplace_back(it.name(), s->value());
      else if (const auto *d = dynamic_cast<const Imf::DoubleAttribute *>(&it.attribute()))
        table.metadata.emplace_back(it.name(), FormatDouble(d->value()));
    }
    const Imath::Box2i window = header.dataWindow();
    const long width = static_cast<long>(window.max.x) - window.min.x + 1;
    const long height = static_cast<long>(window.max.y) - window.min.y + 1;
    if (width < 1 || height < 1 || width > (1 << 16) || height > (1 << 16))
      throw IoError(path + ": image size " + std::to_string(width) + " x " +
                    std::to_string(height) + " is not a lutbake table");
    const Imf::ChannelList &channels = header.channels();
    if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B"))
      table.channelNames = {"R", "G", "B"};  // an engine preset's three channels
    else if (channels.findChannel("R") && channels.findChannel("G"))
      table.channelNames = {"R", "G"};
    else if (channels.findChannel("Y"))
      table.channelNames = {"Y"};
    else if (const std::vector<std::string> named = DefinitionChannelNames(table);
             !named.empty() && std::all_of(named.begin(), named.end(), [&](const std::string &c) {
               return channels.findChannel(c) != nullptr;
             }))
      // More than two channels (ltc_ggx's m00 ... fresnel, or a fit map's):
      // EXR keeps channels sorted by name, so the order is the definition's.
      table.channelNames = named;
    else
      throw IoError(path +
                    ": no Y channel, no R, G channels and not the channels of the table "
                    "its metadata names");
    table.channels = static_cast<int>(table.channelNames.size());
    ShapeFromMetadata(path, width, height, &table);
    std::vector<float> pixels(static_cast<size_t>(width) * height * table.channels);
    Imf::FrameBuffer frame;
    const size_t xStride = sizeof(float) * table.channels;
    const size_t yStride = xStride * static_cast<size_t>(width);
    // The data window may not start at (0, 0): offset the base pointer so
    // that pixel (min.x, min.y) lands at pixels[0].
    char *base = reinterpret_cast<char *>(pixels.data()) -
                 static_cast<ptrdiff_t>(window.min.x) * static_cast<ptrdiff_t>(xStride) -
                 static_cast<ptrdiff_t>(window.min.y) * static_cast<ptrdiff_t>(yStride);
    for (int c = 0; c < table.channels; ++c)
      frame.insert(table.channelNames[c],
                   Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    table.values.assign(pixels.begin(), pixels.end());
  } catch (const IoError &) {
    throw;
  } catch (const std::exception &e) {
    throw IoError("cannot read " + path + ": " + e.what());
  }
  return table;
}

RawImage ReadExrImage(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CheckExrHeader(path, bytes);
  RawImage image;
  image.format = "OpenEXR";
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile file(stream);
    const Imf::Header &header = file.header();
    const Imath::Box2i window = header.dataWindow();
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    // R, G, B, A first (in that order), then Y, then the rest by name.
    const Imf::ChannelList &list = header.channels();
    bool half = true;
    for (const char *name : {"R", "G", "B", "A", "Y"})
      if (list.findChannel(name)) image.channelNames.emplace_back(name);
    for (auto it = list.begin(); it != list.end(); ++it) {
      half = half && it.channel().type == Imf::HALF;
      if (std::find(image.channelNames.begin(), image.channelNames.end(), it.name()) ==
          image.channelNames.end())
        image.channelNames.emplace_back(it.name());
    }
    if (image.channelNames.empty() || image.channelNames.size() > 16)
      throw IoError(path + ": " + std::to_string(image.channelNames.size()) +
                    " channels (1 to 16 are read)");
    image.channels = static_cast<int>(image.channelNames.size());
    image.storage = half ? "half" : "float32";
    std::vector<float> pixels(static_cast<size_t>(image.width) * image.height * image.channels);
    Imf::FrameBuffer frame;
    const size_t xStride = sizeof(float) * image.channels;
    const size_t yStride = xStride * static_cast<size_t>(image.width);
    char *base = reinterpret_cast<char *>(pixels.data()) -
                 static_cast<ptrdiff_t>(window.min.x) * static_cast<ptrdiff_t>(xStride) -
                 static_cast<ptrdiff_t>(window.min.y) * static_cast<ptrdiff_t>(yStride);
    for (int c = 0; c < image.channels; ++c)
      frame.insert(image.channelNames[static_cast<size_t>(c)],
                   Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    image.values.assign(pixels.begin(), pixels.end());
  } catch (const IoError &) {
    throw;
  } catch (const std::exception &e) {
    throw IoError("cannot read " + path + ": " + e.what());
  }
  return image;
}

namespace {

// The unsigned integer in `text` after "name = ", or -1.
long ConstantAfter(const std::string &text, const std::string &name) {
  const size_t at = text.find(name + " = ");
  if (at == std::string::npos) return -1;
  char *end = nullptr;
  const char *p = text.c_str() + at + name.size() + 3;
  const long v = std::strtol(p, &end, 10);
  return end == p ? -1 : v;
}

}  // namespace

HeaderValues ReadHeaderValues(const std::string &path) {
  std::ifstream file(path);
  if (!file) throw IoError("cannot open " + path);
  std::stringstream buffer;
  buffer << file.rdbuf();
  const std::string text = buffer.str();
  HeaderValues out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("//", 0) != 0 || line == "//") break;  // the metadata block ends
    if (line.rfind("//   ", 0) != 0) continue;
    const size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;
    out.metadata.emplace_back(line.substr(5, colon - 5), line.substr(colon + 2));
  }
  const long width = ConstantAfter(text, "kWidth"), height = ConstantAfter(text, "kHeight"),
             channels = ConstantAfter(text, "kChannels");
  if (width < 1 || height < 1 || channels < 1 || width > (1 << 16) || height > (1 << 16) ||
      channels > kMaxTableChannels)
    throw IoError(path + ": kWidth, kHeight or kChannels missing or out of range");
  // kDepth: a 3D table's slice count (absent: 1).
  const long depth =
      text.find("kDepth = ") == std::string::npos ? 1 : ConstantAfter(text, "kDepth");
  if (depth < 1 || depth > (1 << 16)) throw IoError(path + ": kDepth out of range");
  out.depth = static_cast<int>(depth);
  out.width = static_cast<int>(width);
  out.height = static_cast<int>(height);
  out.channels = static_cast<int>(channels);
  // kValues is float literals ("0.5f") or, with half storage, binary16 bit
  // patterns ("0x3800").
  size_t start = text.find("constexpr float kValues[");
  if (start == std::string::npos) {
    start = text.find("constexpr std::uint16_t kValues[");
    out.half = start != std::string::npos;
  }
  if (start == std::string::npos)
    throw IoError(path +
                  ": no 'constexpr float kValues[' or 'constexpr std::uint16_t kValues[' array");
  const size_t open = text.find('{', start), close = text.find("};", start);
  if (open == std::string::npos || close == std::string::npos || close < open)
    throw IoError(path + ": kValues has no initialiser");
  const size_t expected = static_cast<size_t>(width) * height * depth * channels;
  // Each value takes at least one character of the initialiser: a header
  // whose sizes claim more values than that is refused before anything is
  // reserved for them (the sizes alone allow 2^49 values).
  if (expected > close - open)
    throw IoError(path + ": kValues's initialiser has " + std::to_string(close - open) +
                  " characters, too few for the " + std::to_string(expected) +
                  " values its sizes say");
  out.values.reserve(expected);
  const char *p = text.c_str() + open + 1;
  const char *last = text.c_str() + close;
  while (p < last) {
    while (p < last && (*p == ' ' || *p == '\n' || *p == ',')) ++p;
    if (p >= last) break;
    char *end = nullptr;
    if (out.half) {
      const unsigned long bits = std::strtoul(p, &end, 16);
      if (end == p || bits > 0xffffu) throw IoError(path + ": kValues holds something not a half");
      Imath::half h;
      h.setBits(static_cast<unsigned short>(bits));
      out.values.push_back(static_cast<float>(h));
      p = end;
    } else {
      const float v = std::strtof(p, &end);
      if (end == p || *end != 'f') throw IoError(path + ": kValues holds something not a float");
      out.values.push_back(v);
      p = end + 1;
    }
  }
  if (out.values.size() != expected)
    throw IoError(path + ": kValues has " + std::to_string(out.values.size()) + " values, " +
                  std::to_string(expected) + " expected");
  return out;
}

}  // namespace lutbake
