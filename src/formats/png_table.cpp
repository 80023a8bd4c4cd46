// Tables as 8- or 16-bit PNG through OpenImageIO (--format png8, png16),
// and their reader for `lutbake check`.
//
// A texel value v in [0, 1] is stored as q = floor(v (2^b - 1) + 0.5)
// (QuantizeUnorm, storage.h) and read back as q / (2^b - 1): at most half a
// step, 0.5 / (2^b - 1), from v. Values outside [0, 1] (sheen E reaches
// 1.05) or NaN are refused, not clamped or scaled: PNG would state a bound
// that does not hold, and a scale is one more thing an engine could forget.
// One channel is grey; two channels (dfg's A, B) are RGB with R = channel 0,
// G = channel 1, B = 0 (grey + alpha would invite readers to premultiply).
// A 3D table's slices are stacked along y, as in the EXR. Every metadata
// pair, errorMax and errorRms included (those of the quantised values,
// errorStorage unorm8 / unorm16), is a tEXt chunk; so are quantisationStep
// and channelMapping. No gAMA, sRGB or tIME chunk: the values are data, and
// equal tables give equal files.
#include <OpenImageIO/imageio.h>

#include <cmath>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"

namespace lutbake {

namespace {

std::string ChannelMapping(int channels) {
  return channels == 1 ? "grey = channel 0 (Y)" : "R = channel 0, G = channel 1, B = 0 (unused)";
}

class PngWriter final : public TableWriter {
 public:
  explicit PngWriter(int bits) : bits_(bits) {}
  const char *formatName() const override { return bits_ == 8 ? "png8" : "png16"; }
  const char *extension() const override { return ".png"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    RequireUnitRange(table, path, "PNG");
    const ValueType type = bits_ == 8 ? ValueType::kUnorm8 : ValueType::kUnorm16;
    const int width = table.width(), height = table.height() * table.depth();
    const int fileChannels = table.channels == 1 ? 1 : 3;
    OIIO::ImageSpec spec(width, height, fileChannels,
                         bits_ == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
    for (const auto &[key, value] : MetadataForStorage(table, type)) spec.attribute(key, value);
    spec.attribute("quantisationStep", "1/" + std::to_string((1u << bits_) - 1u));
    spec.attribute("channelMapping", ChannelMapping(table.channels));
    const size_t texels = static_cast<size_t>(width) * height;
    std::vector<uint16_t> wide(bits_ == 16 ? texels * fileChannels : 0);
    std::vector<uint8_t> narrow(bits_ == 8 ? texels * fileChannels : 0);
    for (size_t t = 0; t < texels; ++t)
      for (int c = 0; c < fileChannels; ++c) {
        const unsigned q =
            c < table.channels ? QuantizeUnorm(table.values[t * table.channels + c], bits_) : 0u;
        if (bits_ == 16)
          wide[t * fileChannels + c] = static_cast<uint16_t>(q);
        else
          narrow[t * fileChannels + c] = static_cast<uint8_t>(q);
      }
    auto out = OIIO::ImageOutput::create("png");
    if (!out) throw IoError("cannot write " + path + ": " + OIIO::geterror());
    const bool ok = out->open(path, spec) &&
                    (bits_ == 16 ? out->write_image(OIIO::TypeDesc::UINT16, wide.data())
                                 : out->write_image(OIIO::TypeDesc::UINT8, narrow.data())) &&
                    out->close();
    if (!ok) throw IoError("cannot write " + path + ": " + out->geterror());
  }

 private:
  int bits_;
};

}  // namespace

std::unique_ptr<TableWriter> MakePngWriter(int bits) { return std::make_unique<PngWriter>(bits); }

Table ReadPngTable(const std::string &path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw IoError("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  Table table;
  for (const OIIO::ParamValue &p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING && p.name().string().find(':') == std::string::npos)
      table.metadata.emplace_back(p.name().string(), p.get_string());
  int bits = 0;
  if (spec.format == OIIO::TypeDesc::UINT8) bits = 8;
  if (spec.format == OIIO::TypeDesc::UINT16) bits = 16;
  if (bits == 0 || (spec.nchannels != 1 && spec.nchannels != 3))
    throw IoError(path + ": not an 8- or 16-bit grey or RGB PNG as lutbake writes them");
  const std::string *storage = table.FindMetadata("errorStorage");
  const std::string expected = bits == 8 ? "unorm8" : "unorm16";
  if (!storage || *storage != expected)
    throw IoError(path + ": tEXt errorStorage is not " + expected + " for a " +
                  std::to_string(bits) + "-bit PNG");
  table.channels = spec.nchannels == 1 ? 1 : 2;
  table.channelNames =
      table.channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G"};
  ShapeFromMetadata(path, spec.width, spec.height, &table);
  std::vector<uint16_t> q(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, q.data()))
    throw IoError("cannot read " + path + ": " + in->geterror());
  // OpenImageIO widens 8 bits to 16 as q * 257, exactly.
  const double top = 65535.0;
  table.values.reserve(q.size() / spec.nchannels * table.channels);
  for (size_t t = 0; t < q.size() / spec.nchannels; ++t)
    for (int c = 0; c < table.channels; ++c)
      table.values.push_back(q[t * spec.nchannels + c] / top);
  return table;
}

}  // namespace lutbake
