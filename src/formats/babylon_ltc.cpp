// --format babylon-ltc (T.bin): Babylon.js's areaLightsLTC.bin, the file its
// area lights fetch (Lights/LTC/ltcTextureTool.ts, DecodeLTCTextureDataAsync)
// and split into two 64 x 64 RGBA half-float textures: a headerless array
// of IEEE binary16 (little-endian), eight per texel, texel t = row * 64 +
// column, the first four its LTC1 texel and the last four its LTC2 texel.
// An eight-channel table (the babylon-ltc preset) is written texel by
// texel, x fastest; the reader takes the side from the size (a square of
// 16 bytes a texel).
#include <cmath>
#include <string>
#include <vector>

#include "format_list.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "texel_bytes.h"

namespace lutbake {

namespace {

constexpr int kChannels = 8;

class BabylonLtcWriter final : public TableWriter {
 public:
  const char *formatName() const override { return "babylon-ltc"; }
  const char *extension() const override { return ".bin"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    if (table.channels != kChannels || table.is3D())
      throw std::invalid_argument("babylon-ltc writes a 2D table of eight channels (LTC1, LTC2)");
    std::vector<uint8_t> bytes;
    texel_bytes::PutValues(bytes, table, ValueType::kHalf);
    texel_bytes::WriteFileBytes(path, bytes);
  }
};

Table ReadBabylonLtc(const std::string &path) {
  const std::vector<uint8_t> bytes = texel_bytes::ReadFileBytes(path);
  const size_t texels = bytes.size() / (2 * kChannels);
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(texels))));
  if (texels == 0 || bytes.size() % (2 * kChannels) != 0 ||
      static_cast<size_t>(side) * side != texels)
    throw IoError(path + ": not a square of eight binary16 values a texel (" +
                  std::to_string(bytes.size()) + " bytes)");
  Table table;
  table.name = "areaLightsLTC";
  table.x = LinearAxis("u", 0.0, 1.0, side);
  table.y = LinearAxis("v", 0.0, 1.0, side);
  table.channels = kChannels;
  table.values = texel_bytes::Reader(bytes, path).Values(0, texels * kChannels, ValueType::kHalf);
  table.errors.assign(table.values.size(), 0.0);
  return table;
}

std::unique_ptr<TableWriter> MakeBabylonLtcWriter() { return std::make_unique<BabylonLtcWriter>(); }

}  // namespace

std::vector<TableFormat> BabylonLtcFormats() {
  return {{"babylon-ltc", ".bin", FixedStorage(ValueType::kHalf), MakeBabylonLtcWriter,
           ReadBabylonLtc, false, false, kChannels}};
}

}  // namespace lutbake
