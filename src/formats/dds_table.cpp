// Tables as DirectDraw Surface files with the DX10 header, written by hand
// to Microsoft's "DDS file layout" documentation (--format dds: float32,
// dds-half: binary16), and their reader for `lutbake check`. A 3D table is
// a volume texture (DDSCAPS2_VOLUME, D3D10_RESOURCE_DIMENSION_TEXTURE3D,
// depth = the eta slices), so that a trilinear fetch interpolates across eta
// too; a texture array would not. The layout, integers little-endian:
//
//   0    "DDS " (0x20534444)
//   4    DDS_HEADER: dwSize 124; dwFlags CAPS | HEIGHT | WIDTH | PITCH |
//        PIXELFORMAT (0x100F), | DEPTH (0x800000) for a volume; dwHeight,
//        dwWidth; dwPitchOrLinearSize = width x bytes per texel; dwDepth
//        (slices, 0 for 2D); dwMipMapCount 0; dwReserved1[11] 0
//   76   DDS_PIXELFORMAT: dwSize 32, dwFlags DDPF_FOURCC (4), dwFourCC
//        "DX10", bit count and masks 0
//   108  dwCaps DDSCAPS_TEXTURE (0x1000), | COMPLEX (0x8) for a volume;
//        dwCaps2 DDSCAPS2_VOLUME (0x200000) for a volume, else 0; dwCaps3,
//        dwCaps4, dwReserved2 0
//   128  DDS_HEADER_DXT10: dxgiFormat R32_FLOAT 41, R32G32_FLOAT 16,
//        R16_FLOAT 54, R16G16_FLOAT 34, and for three channels (a preset's
//        texture) R32G32B32A32_FLOAT 2 or R16G16B16A16_FLOAT 10 with A = 1
//        (Babylon.js's DDS loader takes only the four-channel float
//        formats); resourceDimension TEXTURE2D 3 or
//        TEXTURE3D 4; miscFlag 0; arraySize 1; miscFlags2 0
//   148  the texels: x fastest, then y (row 0 first), then z; channels
//        interleaved
//   then lutbake's metadata, which DDS has no place for: "LBMD", a u32
//        byte count, and a JSON object of every metadata pair (errorMax /
//        errorRms / errorStorage those of the stored values). DDS readers
//        stop after the texels; this trailer is lutbake's, not Microsoft's.
#include <nlohmann/json.hpp>

#include "format_list.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "texel_bytes.h"

namespace lutbake {

namespace {

using namespace texel_bytes;

uint32_t DxgiFormat(int channels, ValueType storage) {
  if (storage == ValueType::kHalf) return channels == 1 ? 54u : channels == 2 ? 34u : 10u;
  return channels == 1 ? 41u : channels == 2 ? 16u : 2u;
}

// The channels a texel has in the file: three are padded to RGBA.
int FileChannels(int channels) { return channels == 3 ? 4 : channels; }

constexpr uint32_t kVolumeCaps2 = 0x200000u;
constexpr size_t kDataOffset = 148;

class DdsWriter final : public TableWriter {
 public:
  explicit DdsWriter(ValueType storage) : storage_(storage) {}
  const char *formatName() const override {
    return storage_ == ValueType::kHalf ? "dds-half" : "dds";
  }
  const char *extension() const override { return ".dds"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    if (table.channels > 3)
      throw IoError("cannot write " + path + ": DDS here holds one to three channels");
    const uint32_t typeSize = storage_ == ValueType::kHalf ? 2 : 4;
    const bool volume = table.is3D();
    std::vector<uint8_t> file{'D', 'D', 'S', ' '};
    Put32(file, 124);
    Put32(file, 0x100Fu | (volume ? 0x800000u : 0u));
    Put32(file, static_cast<uint32_t>(table.height()));
    Put32(file, static_cast<uint32_t>(table.width()));
    Put32(file, static_cast<uint32_t>(table.width()) * typeSize *
                    static_cast<uint32_t>(FileChannels(table.channels)));
    Put32(file, volume ? static_cast<uint32_t>(table.depth()) : 0u);
    Put32(file, 0);                               // dwMipMapCount
    for (int i = 0; i < 11; ++i) Put32(file, 0);  // dwReserved1
    Put32(file, 32);
    Put32(file, 0x4);  // DDPF_FOURCC
    file.insert(file.end(), {'D', 'X', '1', '0'});
    for (int i = 0; i < 5; ++i) Put32(file, 0);  // bit count, R, G, B, A masks
    Put32(file, 0x1000u | (volume ? 0x8u : 0u));
    Put32(file, volume ? kVolumeCaps2 : 0u);
    for (int i = 0; i < 3; ++i) Put32(file, 0);  // dwCaps3, dwCaps4, dwReserved2
    Put32(file, DxgiFormat(table.channels, storage_));
    Put32(file, volume ? 4u : 3u);
    Put32(file, 0);  // miscFlag
    Put32(file, 1);  // arraySize
    Put32(file, 0);  // miscFlags2
    if (table.channels == 3) {
      Table rgba = table;
      rgba.channels = 4;
      rgba.values.clear();
      for (size_t t = 0; t < table.values.size(); t += 3) {
        rgba.values.insert(rgba.values.end(), table.values.begin() + static_cast<long>(t),
                           table.values.begin() + static_cast<long>(t) + 3);
        rgba.values.push_back(1.0);
      }
      PutValues(file, rgba, storage_);
    } else {
      PutValues(file, table, storage_);
    }
    nlohmann::ordered_json meta = nlohmann::ordered_json::object();
    for (const auto &[key, value] : MetadataForStorage(table, storage_)) meta[key] = value;
    const std::string json = meta.dump();
    file.insert(file.end(), {'L', 'B', 'M', 'D'});
    Put32(file, static_cast<uint32_t>(json.size()));
    file.insert(file.end(), json.begin(), json.end());
    WriteFileBytes(path, file);
  }

 private:
  ValueType storage_;
};

}  // namespace

std::unique_ptr<TableWriter> MakeDdsWriter(ValueType storage) {
  return std::make_unique<DdsWriter>(storage);
}

Table ReadDdsTable(const std::string &path) {
  const std::vector<uint8_t> bytes = ReadFileBytes(path);
  const Reader r(bytes, path);
  r.Need(0, kDataOffset);
  if (r.Get32(0) != 0x20534444u || r.Get32(4) != 124 || r.Get32(84) != 0x30315844u)
    throw IoError(path + ": not a DDS file with the DX10 header");
  const uint32_t height = r.Get32(12), width = r.Get32(16);
  const bool volume = (r.Get32(112) & kVolumeCaps2) != 0;
  const uint32_t slices = volume ? r.Get32(24) : 1;
  const uint32_t dxgi = r.Get32(128);
  Table table;
  ValueType storage;
  if (dxgi == 41 || dxgi == 16 || dxgi == 2) {
    storage = ValueType::kFloat32;
  } else if (dxgi == 54 || dxgi == 34 || dxgi == 10) {
    storage = ValueType::kHalf;
  } else {
    throw IoError(path + ": dxgiFormat " + std::to_string(dxgi) +
                  " is not R32_FLOAT, R32G32_FLOAT, R32G32B32A32_FLOAT, R16_FLOAT, "
                  "R16G16_FLOAT or R16G16B16A16_FLOAT");
  }
  table.channels = dxgi == 41 || dxgi == 54 ? 1 : dxgi == 2 || dxgi == 10 ? 3 : 2;
  const int fileChannels = FileChannels(table.channels);
  if (r.Get32(132) != (volume ? 4u : 3u) || r.Get32(140) != 1)
    throw IoError(path + ": resourceDimension or arraySize is not that of one 2D or 3D texture");
  if (width < 1 || height < 1 || slices < 1 || width > (1u << 16) || height > (1u << 16) ||
      slices > (1u << 16))
    throw IoError(path + ": size out of range");
  const size_t count = static_cast<size_t>(width) * height * slices * fileChannels;
  table.values = r.Values(kDataOffset, count, storage);
  if (fileChannels == 4) {  // RGBA: A is padding
    std::vector<double> rgb;
    rgb.reserve(count / 4 * 3);
    for (size_t t = 0; t < count; t += 4)
      rgb.insert(rgb.end(), table.values.begin() + static_cast<long>(t),
                 table.values.begin() + static_cast<long>(t) + 3);
    table.values = std::move(rgb);
  }
  const size_t trailer = kDataOffset + count * (storage == ValueType::kHalf ? 2 : 4);
  r.Need(trailer, 8);
  if (r.Get32(trailer) != 0x444D424Cu) throw IoError(path + ": no lutbake metadata (LBMD)");
  const uint32_t length = r.Get32(trailer + 4);
  r.Need(trailer + 8, length);
  try {
    const auto meta = nlohmann::ordered_json::parse(bytes.begin() + trailer + 8,
                                                    bytes.begin() + trailer + 8 + length);
    for (const auto &item : meta.items())
      table.metadata.emplace_back(item.key(), item.value().get<std::string>());
  } catch (const nlohmann::json::exception &e) {
    throw IoError(path + ": its LBMD metadata is not a JSON object of strings: " + e.what());
  }
  const std::string *stated = table.FindMetadata("errorStorage");
  if (!stated || *stated != ToString(storage))
    throw IoError(path + ": metadata errorStorage is not " + std::string(ToString(storage)) +
                  " for dxgiFormat " + std::to_string(dxgi));
  table.channelNames = table.channels == 1   ? std::vector<std::string>{"Y"}
                       : table.channels == 2 ? std::vector<std::string>{"R", "G"}
                                             : std::vector<std::string>{"R", "G", "B"};
  ShapeFromMetadata(path, width, static_cast<long>(height) * slices, &table);
  if (table.is3D() != volume) throw IoError(path + ": volume flag does not match axisZ");
  return table;
}

std::vector<TableFormat> DdsFormats() {
  std::vector<TableFormat> records;
  for (const auto &[name, storage] :
       {std::pair{"dds", ValueType::kFloat32}, std::pair{"dds-half", ValueType::kHalf}}) {
    const ValueType type = storage;
    records.push_back({name, ".dds", FixedStorage(type), [type] { return MakeDdsWriter(type); },
                       ReadDdsTable, true});
  }
  return records;
}

}  // namespace lutbake
