#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "file_io.h"
#include "format_list.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

namespace {

constexpr size_t kAxisNameBytes = 24;
constexpr size_t kFixedHeaderBytes = 140;
// Version 2 (3D tables) has axis z after axis y, so everything after moves
// by one axis block.
constexpr size_t kAxisBytes = 48;
constexpr size_t kFixedHeaderBytes3D = kFixedHeaderBytes + kAxisBytes;

void PutU32(std::string &out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}
void PutF64(std::string &out, double v) {
  uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xffu));
}
void PutF32(std::string &out, float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  PutU32(out, bits);
}
void PutAxis(std::string &out, const Axis &axis, bool present) {
  std::string name = present ? axis.name : "";
  name.resize(kAxisNameBytes, '\0');
  out += name;
  PutF64(out, present ? axis.min : 0.0);
  PutF64(out, present ? axis.max : 0.0);
  PutU32(out, static_cast<uint32_t>(axis.count));
  PutU32(out, present && axis.listed() ? 1 : 0);  // mapping: 0 linear, 1 listed nodes
}

uint32_t GetU32(const std::string &in, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<uint32_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}
double GetF64(const std::string &in, size_t at) {
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i)
    bits |= static_cast<uint64_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}
float GetF32(const std::string &in, size_t at) {
  const uint32_t bits = GetU32(in, at);
  float v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}
Axis GetAxis(const std::string &in, size_t at) {
  Axis axis;
  axis.name = std::string(in.c_str() + at, strnlen(in.c_str() + at, kAxisNameBytes));
  axis.min = GetF64(in, at + 24);
  axis.max = GetF64(in, at + 32);
  axis.count = static_cast<int>(GetU32(in, at + 40));
  return axis;
}

uint32_t GetMapping(const std::string &in, size_t at) { return GetU32(in, at + 44); }

class BinaryWriter final : public TableWriter {
 public:
  const char *formatName() const override { return "bin"; }
  const char *extension() const override { return ".bin"; }
  void Write(const Table &table, const std::string &path,
             const WriteOptions &options) const override {
    const ValueType type = options.binaryValues;
    const bool wide = type == ValueType::kFloat64;
    std::string metadata;
    for (const auto &[key, value] : MetadataForStorage(table, type))
      metadata += key + "=" + value + "\n";
    const bool threeD = table.is3D();
    std::string nodes;  // the node values of listed axes, x first, then y, z
    for (const Axis *axis : {&table.x, &table.y, &table.z})
      if (axis->listed() &&
          (axis == &table.x || (axis == &table.y && table.is2D()) || (axis == &table.z && threeD)))
        for (double v : axis->nodes) PutF64(nodes, v);
    const size_t fixed = threeD ? kFixedHeaderBytes3D : kFixedHeaderBytes;
    const size_t dataOffset = (fixed + metadata.size() + nodes.size() + 7) / 8 * 8;
    std::string out;
    out.append(kBinaryMagic, sizeof kBinaryMagic);
    PutU32(out, threeD ? kBinaryVersion3D : kBinaryVersion);
    PutU32(out, static_cast<uint32_t>(dataOffset));
    PutU32(out, threeD ? 3 : table.is2D() ? 2 : 1);
    PutU32(out, static_cast<uint32_t>(table.width()));
    PutU32(out, static_cast<uint32_t>(table.height()));
    PutU32(out, static_cast<uint32_t>(table.channels));
    PutU32(out, wide ? kBinaryFloat64 : kBinaryFloat32);
    PutU32(out, 1);  // error block present
    PutAxis(out, table.x, true);
    PutAxis(out, table.y, table.is2D());
    if (threeD) PutAxis(out, table.z, true);
    PutU32(out, static_cast<uint32_t>(metadata.size()));
    out += metadata;
    out += nodes;
    out.resize(dataOffset, '\0');
    // The bounds of the stored values (storage.h): exact in float64, rounded
    // up to float32 otherwise, so that the float32 written is the bound itself.
    const std::vector<double> bounds = StoredBounds(table, type);
    for (double v : table.values) wide ? PutF64(out, v) : PutF32(out, static_cast<float>(v));
    for (double e : bounds) wide ? PutF64(out, e) : PutF32(out, static_cast<float>(e));
    WriteWholeFile(path, out);
  }
};

}  // namespace

std::unique_ptr<TableWriter> MakeBinaryWriter() { return std::make_unique<BinaryWriter>(); }

Table ReadBinaryTable(const std::string &path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw IoError("cannot open " + path);
  std::ostringstream buffer;
  buffer << file.rdbuf();
  const std::string in = buffer.str();
  // Every field is validated before it is used: the file may come from
  // anywhere (lutbake check reads files it did not write).
  if (in.size() < kFixedHeaderBytes || std::memcmp(in.data(), kBinaryMagic, 8) != 0)
    throw IoError(path + ": not a lutbake .bin file (bad magic)");
  const uint32_t version = GetU32(in, 8);
  if (version != kBinaryVersion && version != kBinaryVersion3D)
    throw IoError(path + ": .bin version " + std::to_string(version) +
                  " (this lutbake reads versions " + std::to_string(kBinaryVersion) + " and " +
                  std::to_string(kBinaryVersion3D) + ")");
  const bool threeD = version == kBinaryVersion3D;
  const size_t fixed = threeD ? kFixedHeaderBytes3D : kFixedHeaderBytes;
  if (in.size() < fixed) throw IoError(path + ": truncated header");
  const size_t dataOffset = GetU32(in, 12);
  Table table;
  const uint32_t dims = GetU32(in, 16);
  const uint32_t width = GetU32(in, 20), height = GetU32(in, 24), channels = GetU32(in, 28);
  const uint32_t valueType = GetU32(in, 32), flags = GetU32(in, 36);
  if (threeD ? dims != 3 : (dims != 1 && dims != 2))
    throw IoError(path + (threeD ? ": a version 2 file has 3 dimensions"
                                 : ": dimensions must be 1 or 2 (version 1)"));
  if (channels < 1 || channels > static_cast<uint32_t>(kMaxTableChannels))
    throw IoError(path + ": channels must be 1 to " + std::to_string(kMaxTableChannels));
  if (valueType != kBinaryFloat32 && valueType != kBinaryFloat64)
    throw IoError(path + ": value type must be 1 (float32) or 2 (float64)");
  const size_t valueBytes = valueType == kBinaryFloat64 ? 8 : 4;
  table.channels = static_cast<int>(channels);
  table.channelNames =
      channels == 2 ? std::vector<std::string>{"R", "G"} : std::vector<std::string>{"Y"};
  table.x = GetAxis(in, 40);
  table.y = GetAxis(in, 88);
  if (dims == 1) {
    table.y = LinearAxis("", 0.0, 1.0, 1);
  }
  if (threeD) {
    table.z = GetAxis(in, 136);
    if (table.z.name.empty()) throw IoError(path + ": axis z has no name");
  }
  constexpr uint32_t kMaxCount = 1u << 16;
  if (width == 0 || height == 0 || width > kMaxCount || height > kMaxCount ||
      static_cast<uint32_t>(table.x.count) != width ||
      static_cast<uint32_t>(table.y.count) != height || (dims == 1 && height != 1) ||
      (threeD && (table.z.count < 1 || table.z.count > static_cast<int>(kMaxCount))))
    throw IoError(path + ": texel counts disagree with the axes or exceed 65536");
  const size_t metadataLength = GetU32(in, fixed - 4);
  if (dataOffset % 8 != 0 || dataOffset > in.size() || fixed + metadataLength > dataOffset)
    throw IoError(path + ": bad data offset or metadata length");
  // Listed axes: their node values follow the metadata, x's first.
  size_t nodesAt = fixed + metadataLength;
  const auto readAxis = [&](Axis *axis, size_t headerAt, const char *which) {
    const uint32_t mapping = GetMapping(in, headerAt);
    if (mapping == 0) {
      // A range whose width overflows (an infinite end, or -1e308 to 1e308)
      // would give every lookup a NaN coordinate.
      if (!(axis->max > axis->min) || !std::isfinite(axis->max - axis->min))
        throw IoError(path + ": axis " + which +
                      " has an empty or infinite range, or one that is not a number");
      return;
    }
    if (mapping != 1) throw IoError(path + ": axis " + which + " has an unknown mapping");
    const size_t bytes = 8 * static_cast<size_t>(axis->count);
    if (nodesAt + bytes > dataOffset)
      throw IoError(path + ": the node values of axis " + which + " run past the data offset");
    std::vector<double> nodes;
    for (int i = 0; i < axis->count; ++i) {
      nodes.push_back(GetF64(in, nodesAt + 8 * static_cast<size_t>(i)));
      if (!std::isfinite(nodes.back()) || (i > 0 && !(nodes[i] > nodes[i - 1])))
        throw IoError(path + ": the node values of axis " + which + " are not increasing");
    }
    nodesAt += bytes;
    *axis = ListedAxis(axis->name, std::move(nodes));
  };
  readAxis(&table.x, 40, "x");
  if (dims >= 2) readAxis(&table.y, 88, "y");
  if (threeD) readAxis(&table.z, 136, "z");
  std::istringstream lines(in.substr(fixed, metadataLength));
  for (std::string line; std::getline(lines, line);) {
    const size_t eq = line.find('=');
    if (eq != std::string::npos)
      table.metadata.emplace_back(line.substr(0, eq), line.substr(eq + 1));
  }
  if (const std::string *name = table.FindMetadata("table")) table.definition = FindTable(*name);
  // More than two channels (ltc_ggx): named by the definition.
  if (channels > 2) {
    if (!table.definition || table.definition->Channels() != static_cast<int>(channels))
      throw IoError(path + ": " + std::to_string(channels) +
                    " channels, but the metadata names no table that has them");
    table.channelNames = table.definition->ChannelNames();
  }
  const size_t count = static_cast<size_t>(width) * height * table.z.count * channels;
  const size_t blocks = (flags & 1u) ? 2 : 1;
  if (in.size() != dataOffset + blocks * valueBytes * count)
    throw IoError(path + ": " + std::to_string(in.size()) + " bytes, expected " +
                  std::to_string(dataOffset + blocks * valueBytes * count) +
                  " (truncated or oversized)");
  const auto get = [&](size_t at) {
    return valueBytes == 8 ? GetF64(in, at) : static_cast<double>(GetF32(in, at));
  };
  table.values.resize(count);
  for (size_t i = 0; i < count; ++i) table.values[i] = get(dataOffset + valueBytes * i);
  if (flags & 1u) {
    table.errors.resize(count);
    for (size_t i = 0; i < count; ++i) table.errors[i] = get(dataOffset + valueBytes * (count + i));
  }
  return table;
}

std::vector<TableFormat> BinaryFormats() {
  return {{"bin", ".bin", [](const WriteOptions &o) { return o.binaryValues; }, MakeBinaryWriter,
           ReadBinaryTable, true, false, kMaxTableChannels}};
}

}  // namespace lutbake
