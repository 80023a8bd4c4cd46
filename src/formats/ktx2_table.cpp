// Tables as KTX 2.0 textures, written by hand to the Khronos KTX 2.0
// specification (--format ktx2: float32, ktx2-half: binary16), and their
// reader for `lutbake check`. The layout, all integers little-endian:
//
//   0    identifier  AB 4B 54 58 20 32 30 BB 0D 0A 1A 0A  ("«KTX 20»\r\n\x1A\n")
//   12   vkFormat    R32_SFLOAT 100, R32G32_SFLOAT 103, R16_SFLOAT 76,
//                    R16G16_SFLOAT 83
//   16   typeSize    4 (float32) or 2 (half)
//   20   pixelWidth, pixelHeight (the table's width and height; a 1D table
//        is a 2D texture 1 texel high), pixelDepth (the eta slices of a 3D
//        table, 0 for 2D), layerCount 0, faceCount 1, levelCount 1,
//        supercompressionScheme 0 (none)
//   48   dfdByteOffset, dfdByteLength, kvdByteOffset, kvdByteLength (u32);
//        sgdByteOffset, sgdByteLength (u64, 0: no supercompression data)
//   80   level index: byteOffset, byteLength, uncompressedByteLength (u64)
//   104  DFD: dfdTotalSize, then one basic descriptor block (Khronos Data
//        Format 1.3): vendorId 0 / descriptorType 0, versionNumber 2,
//        descriptorBlockSize 24 + 16 per channel, colorModel RGBSDA (1),
//        colorPrimaries BT709 (1), transferFunction LINEAR (1), flags 0,
//        texelBlockDimension 0 0 0 0 (1 x 1 x 1), bytesPlane0 = bytes per
//        texel; per channel a sample: bitOffset (16 or 32 times the
//        channel), bitLength - 1, channelType = channel id (R 0, G 1) |
//        FLOAT (0x80) | SIGNED (0x40), samplePosition 0, sampleLower -1.0f
//        and sampleUpper 1.0f as float32 bits (0xBF800000, 0x3F800000), as
//        the Khronos dfdutils write them for every SFLOAT format.
//   then key/value data (4-byte aligned, keys sorted by byte value): each
//        keyAndValueByteLength (u32), key NUL, value NUL, padded to 4 bytes:
//          KTXorientation   "rd" (2D) or "rdi" (3D): x right, y down, z in
//          KTXwriter        "lutbake <version>"
//          lutbake.metadata a JSON object: every metadata pair of the table,
//                           errorMax / errorRms / errorStorage those of the
//                           stored values (float32 or half), as strings
//   then the one level, aligned to lcm(bytes per texel, 4): texels x
//        fastest, then y (row 0 = texel row 0), then z; channels interleaved.
#include <nlohmann/json.hpp>

#include "format_list.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/bake.h"
#include "texel_bytes.h"

namespace lutbake {

namespace {

using namespace texel_bytes;

constexpr uint8_t kIdentifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                     0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

uint32_t VkFormat(int channels, ValueType storage) {
  if (storage == ValueType::kHalf) return channels == 1 ? 76u : 83u;
  return channels == 1 ? 100u : 103u;
}

void PutKeyValue(std::vector<uint8_t> &out, const std::string &key, const std::string &value) {
  Put32(out, static_cast<uint32_t>(key.size() + 1 + value.size() + 1));
  out.insert(out.end(), key.begin(), key.end());
  out.push_back(0);
  out.insert(out.end(), value.begin(), value.end());
  out.push_back(0);
  PadTo(out, 4);
}

class Ktx2Writer final : public TableWriter {
 public:
  explicit Ktx2Writer(ValueType storage) : storage_(storage) {}
  const char *formatName() const override {
    return storage_ == ValueType::kHalf ? "ktx2-half" : "ktx2";
  }
  const char *extension() const override { return ".ktx2"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    const uint32_t typeSize = storage_ == ValueType::kHalf ? 2 : 4;
    const uint32_t texelBytes = typeSize * static_cast<uint32_t>(table.channels);
    std::vector<uint8_t> dfd;
    const uint32_t blockSize = 24 + 16 * static_cast<uint32_t>(table.channels);
    Put32(dfd, 4 + blockSize);  // dfdTotalSize
    Put32(dfd, 0);              // vendorId 0 (Khronos), descriptorType 0 (basic)
    Put16(dfd, 2);              // versionNumber: Khronos Data Format 1.3
    Put16(dfd, blockSize);
    dfd.insert(dfd.end(), {1, 1, 1, 0});  // RGBSDA, BT709, LINEAR, flags
    Put32(dfd, 0);                        // texelBlockDimension 1 x 1 x 1 x 1
    Put32(dfd, texelBytes);               // bytesPlane0..3
    Put32(dfd, 0);                        // bytesPlane4..7
    for (int c = 0; c < table.channels; ++c) {
      Put16(dfd, static_cast<uint32_t>(c) * typeSize * 8);    // bitOffset
      dfd.push_back(static_cast<uint8_t>(typeSize * 8 - 1));  // bitLength - 1
      dfd.push_back(static_cast<uint8_t>(c | 0x80 | 0x40));   // id | FLOAT | SIGNED
      Put32(dfd, 0);                                          // samplePosition
      Put32(dfd, 0xBF800000u);                                // sampleLower -1.0f
      Put32(dfd, 0x3F800000u);                                // sampleUpper 1.0f
    }
    nlohmann::ordered_json meta = nlohmann::ordered_json::object();
    for (const auto &[key, value] : MetadataForStorage(table, storage_)) meta[key] = value;
    std::vector<uint8_t> kvd;
    PutKeyValue(kvd, "KTXorientation", table.is3D() ? "rdi" : "rd");
    PutKeyValue(kvd, "KTXwriter", std::string("lutbake ") + LutbakeVersion());
    PutKeyValue(kvd, "lutbake.metadata", meta.dump());

    std::vector<uint8_t> file(kIdentifier, kIdentifier + 12);
    Put32(file, VkFormat(table.channels, storage_));
    Put32(file, typeSize);
    Put32(file, static_cast<uint32_t>(table.width()));
    Put32(file, static_cast<uint32_t>(table.height()));
    Put32(file, table.is3D() ? static_cast<uint32_t>(table.depth()) : 0u);
    Put32(file, 0);  // layerCount: not an array
    Put32(file, 1);  // faceCount
    Put32(file, 1);  // levelCount: one level, no mipmaps
    Put32(file, 0);  // supercompressionScheme: none
    const size_t dfdOffset = 80 + 24;
    const size_t kvdOffset = dfdOffset + dfd.size();
    size_t levelOffset = kvdOffset + kvd.size();
    const size_t alignment = texelBytes % 4 == 0 ? texelBytes : 4;  // lcm(texelBytes, 4)
    levelOffset = (levelOffset + alignment - 1) / alignment * alignment;
    const uint64_t levelBytes = static_cast<uint64_t>(table.values.size()) * typeSize;
    Put32(file, static_cast<uint32_t>(dfdOffset));
    Put32(file, static_cast<uint32_t>(dfd.size()));
    Put32(file, static_cast<uint32_t>(kvdOffset));
    Put32(file, static_cast<uint32_t>(kvd.size()));
    Put64(file, 0);  // sgdByteOffset
    Put64(file, 0);  // sgdByteLength
    Put64(file, levelOffset);
    Put64(file, levelBytes);
    Put64(file, levelBytes);  // uncompressedByteLength
    file.insert(file.end(), dfd.begin(), dfd.end());
    file.insert(file.end(), kvd.begin(), kvd.end());
    PadTo(file, alignment);
    PutValues(file, table, storage_);
    WriteFileBytes(path, file);
  }

 private:
  ValueType storage_;
};

}  // namespace

std::unique_ptr<TableWriter> MakeKtx2Writer(ValueType storage) {
  return std::make_unique<Ktx2Writer>(storage);
}

Table ReadKtx2Table(const std::string &path) {
  const std::vector<uint8_t> bytes = ReadFileBytes(path);
  const Reader r(bytes, path);
  r.Need(0, 104);
  if (!std::equal(kIdentifier, kIdentifier + 12, bytes.begin()))
    throw IoError(path + ": no KTX 2.0 identifier");
  const uint32_t vkFormat = r.Get32(12), typeSize = r.Get32(16);
  Table table;
  ValueType storage;
  if (vkFormat == 100 || vkFormat == 103) {
    storage = ValueType::kFloat32;
  } else if (vkFormat == 76 || vkFormat == 83) {
    storage = ValueType::kHalf;
  } else {
    throw IoError(path + ": vkFormat " + std::to_string(vkFormat) +
                  " is not R16_SFLOAT, R16G16_SFLOAT, R32_SFLOAT or R32G32_SFLOAT");
  }
  table.channels = vkFormat == 100 || vkFormat == 76 ? 1 : 2;
  if (typeSize != (storage == ValueType::kHalf ? 2u : 4u))
    throw IoError(path + ": typeSize " + std::to_string(typeSize) + " does not match vkFormat");
  const uint32_t width = r.Get32(20), height = r.Get32(24), depth = r.Get32(28);
  if (r.Get32(32) > 1 || r.Get32(36) != 1 || r.Get32(40) != 1 || r.Get32(44) != 0)
    throw IoError(path + ": not a single-level, single-face, unsupercompressed texture");
  if (width < 1 || height < 1 || width > (1u << 16) || height > (1u << 16) || depth > (1u << 16))
    throw IoError(path + ": size out of range");
  const uint32_t kvdOffset = r.Get32(56), kvdLength = r.Get32(60);
  r.Need(kvdOffset, kvdLength);
  std::string metadata;
  for (size_t at = kvdOffset; at + 4 <= static_cast<size_t>(kvdOffset) + kvdLength;) {
    const uint32_t length = r.Get32(at);
    r.Need(at + 4, length);
    const std::string entry(bytes.begin() + at + 4, bytes.begin() + at + 4 + length);
    const size_t nul = entry.find('\0');
    if (nul != std::string::npos && entry.substr(0, nul) == "lutbake.metadata") {
      metadata = entry.substr(nul + 1);
      if (!metadata.empty() && metadata.back() == '\0') metadata.pop_back();
    }
    at += 4 + (length + 3) / 4 * 4;
  }
  if (metadata.empty()) throw IoError(path + ": no lutbake.metadata key");
  try {
    const nlohmann::ordered_json meta = nlohmann::ordered_json::parse(metadata);
    for (const auto &item : meta.items())
      table.metadata.emplace_back(item.key(), item.value().get<std::string>());
  } catch (const nlohmann::json::exception &e) {
    throw IoError(path + ": lutbake.metadata is not a JSON object of strings: " + e.what());
  }
  const std::string *stated = table.FindMetadata("errorStorage");
  if (!stated || *stated != ToString(storage))
    throw IoError(path + ": lutbake.metadata errorStorage is not " + ToString(storage) +
                  " for vkFormat " + std::to_string(vkFormat));
  table.channelNames =
      table.channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G"};
  const uint32_t slices = depth == 0 ? 1 : depth;
  ShapeFromMetadata(path, width, static_cast<long>(height) * slices, &table);
  if (table.is3D() != (depth != 0)) throw IoError(path + ": pixelDepth does not match axisZ");
  const size_t count = static_cast<size_t>(width) * height * slices * table.channels;
  const uint64_t levelOffset = r.Get(80, 8), levelLength = r.Get(88, 8);
  if (levelLength != count * typeSize)
    throw IoError(path + ": level 0 has " + std::to_string(levelLength) + " bytes, " +
                  std::to_string(count * typeSize) + " expected");
  table.values = r.Values(levelOffset, count, storage);
  return table;
}

std::vector<TableFormat> Ktx2Formats() {
  std::vector<TableFormat> records;
  for (const auto &[name, storage] :
       {std::pair{"ktx2", ValueType::kFloat32}, std::pair{"ktx2-half", ValueType::kHalf}}) {
    const ValueType type = storage;
    records.push_back({name, ".ktx2", FixedStorage(type), [type] { return MakeKtx2Writer(type); },
                       ReadKtx2Table, true});
  }
  return records;
}

}  // namespace lutbake
