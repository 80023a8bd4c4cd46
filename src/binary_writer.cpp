#include <cstring>
#include <fstream>
#include <sstream>

#include "lutbake/binary_format.h"
#include "lutbake/writer.h"

namespace lutbake {

namespace {

constexpr size_t kAxisNameBytes = 24;
constexpr size_t kFixedHeaderBytes = 140;

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
  PutU32(out, 0);  // mapping: linear, texel centres
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

class BinaryWriter final : public TableWriter {
 public:
  const char *formatName() const override { return "bin"; }
  const char *extension() const override { return ".bin"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    std::string metadata;
    for (const auto &[key, value] : table.metadata) metadata += key + "=" + value + "\n";
    const size_t dataOffset = (kFixedHeaderBytes + metadata.size() + 7) / 8 * 8;
    std::string out;
    out.append(kBinaryMagic, sizeof kBinaryMagic);
    PutU32(out, kBinaryVersion);
    PutU32(out, static_cast<uint32_t>(dataOffset));
    PutU32(out, table.is2D() ? 2 : 1);
    PutU32(out, static_cast<uint32_t>(table.width()));
    PutU32(out, static_cast<uint32_t>(table.height()));
    PutU32(out, static_cast<uint32_t>(table.channels));
    PutU32(out, 1);  // float32
    PutU32(out, 1);  // error block present
    PutAxis(out, table.x, true);
    PutAxis(out, table.y, table.is2D());
    PutU32(out, static_cast<uint32_t>(metadata.size()));
    out += metadata;
    out.resize(dataOffset, '\0');
    for (double v : table.values) PutF32(out, static_cast<float>(v));
    for (double e : table.errors) PutF32(out, static_cast<float>(e));
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(out.data(), static_cast<std::streamsize>(out.size()));
    file.close();
    if (!file) throw IoError("cannot write " + path);
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
  if (in.size() < kFixedHeaderBytes || std::memcmp(in.data(), kBinaryMagic, 8) != 0)
    throw IoError(path + ": not a lutbake .bin file (bad magic)");
  if (GetU32(in, 8) != kBinaryVersion) throw IoError(path + ": unsupported .bin version");
  const size_t dataOffset = GetU32(in, 12);
  Table table;
  const uint32_t dims = GetU32(in, 16);
  table.channels = static_cast<int>(GetU32(in, 28));
  const uint32_t flags = GetU32(in, 36);
  table.x = GetAxis(in, 40);
  table.y = GetAxis(in, 88);
  if (dims == 1) table.y.name.clear();
  const size_t metadataLength = GetU32(in, 136);
  if (kFixedHeaderBytes + metadataLength > dataOffset)
    throw IoError(path + ": bad metadata length");
  std::istringstream lines(in.substr(kFixedHeaderBytes, metadataLength));
  for (std::string line; std::getline(lines, line);) {
    const size_t eq = line.find('=');
    if (eq != std::string::npos)
      table.metadata.emplace_back(line.substr(0, eq), line.substr(eq + 1));
  }
  const size_t count = static_cast<size_t>(table.width()) * table.height() * table.channels;
  const size_t blocks = (flags & 1u) ? 2 : 1;
  if (in.size() != dataOffset + blocks * 4 * count)
    throw IoError(path + ": truncated or oversized");
  table.values.resize(count);
  for (size_t i = 0; i < count; ++i) table.values[i] = GetF32(in, dataOffset + 4 * i);
  if (flags & 1u) {
    table.errors.resize(count);
    for (size_t i = 0; i < count; ++i) table.errors[i] = GetF32(in, dataOffset + 4 * (count + i));
  }
  return table;
}

}  // namespace lutbake
