// EXR output through OpenEXR: 32-bit float channels, y = 0 the first
// scanline (INCREASING_Y; a 3D table's slices of constant z follow one
// another down the image, each height rows, as attribute axisZ says), channel Y for single-channel
// tables and R = A, G = B for dfg; every metadata pair becomes a string attribute, and the error
// summary also numeric (errorMax, errorRms as double attributes). The error summary is that of the
// stored float32 values (storage.h). OpenEXR itself stamps no date, so equal tables give equal
// files.
#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include "format_list.h"
#include "lutbake/formats/writer.h"

namespace lutbake {

namespace {

class ExrWriter final : public TableWriter {
 public:
  const char *formatName() const override { return "exr"; }
  const char *extension() const override { return ".exr"; }
  void Write(const Table &table, const std::string &path, const WriteOptions &) const override {
    // A 3D table's slices are stacked along the image's y (slice 0 on top).
    const int width = table.width(), height = table.height() * table.depth();
    const int channels = table.channels;
    std::vector<float> pixels(table.values.size());
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<float>(table.values[i]);
    try {
      Imf::Header header(width, height);
      header.compression() = Imf::ZIP_COMPRESSION;
      header.lineOrder() = Imf::INCREASING_Y;
      for (const std::string &name : table.channelNames)
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      for (const auto &[key, value] : MetadataForStorage(table, ValueType::kFloat32)) {
        if (key == "errorMax" || key == "errorRms") continue;
        header.insert(key, Imf::StringAttribute(value));
      }
      const BoundSummary bounds = SummarizeStoredBounds(table, ValueType::kFloat32);
      header.insert("errorMax", Imf::DoubleAttribute(bounds.max));
      header.insert("errorRms", Imf::DoubleAttribute(bounds.rms));
      Imf::FrameBuffer frame;
      const size_t xStride = sizeof(float) * channels;
      const size_t yStride = xStride * width;
      for (int c = 0; c < channels; ++c)
        frame.insert(
            table.channelNames[c],
            Imf::Slice(Imf::FLOAT, reinterpret_cast<char *>(pixels.data() + c), xStride, yStride));
      Imf::OutputFile file(path.c_str(), header);
      file.setFrameBuffer(frame);
      file.writePixels(height);
    } catch (const std::exception &e) {
      throw IoError("cannot write " + path + ": " + e.what());
    }
  }
};

}  // namespace

std::unique_ptr<TableWriter> MakeExrWriter() { return std::make_unique<ExrWriter>(); }

std::vector<TableFormat> ExrFormats() {
  return {{"exr", ".exr", FixedStorage(ValueType::kFloat32), MakeExrWriter, ReadExrTable, true,
           false, kMaxTableChannels}};
}

}  // namespace lutbake
