// Little-endian bytes for the hand-written GPU texture files (KTX2, DDS):
// the integers of their headers, and a table's values as float32 or IEEE
// binary16 (rounded to nearest even, as StoredValue(v, kHalf) says), texel
// by texel with the channels interleaved, x fastest, then y, then z.
#pragma once

#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table.h"

namespace lutbake {
namespace texel_bytes {

inline void Put(std::vector<uint8_t> &out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}
inline void Put16(std::vector<uint8_t> &out, uint32_t v) { Put(out, v, 2); }
inline void Put32(std::vector<uint8_t> &out, uint32_t v) { Put(out, v, 4); }
inline void Put64(std::vector<uint8_t> &out, uint64_t v) { Put(out, v, 8); }
inline void PadTo(std::vector<uint8_t> &out, size_t alignment) {
  while (out.size() % alignment != 0) out.push_back(0);
}

// The value's bytes: 2 (half) or 4 (float32) per channel.
inline void PutValues(std::vector<uint8_t> &out, const Table &table, ValueType storage) {
  for (double v : table.values) {
    if (storage == ValueType::kHalf) {
      Put16(out, Imath::half(static_cast<float>(v)).bits());
    } else {
      const float f = static_cast<float>(v);
      uint32_t bits = 0;
      std::memcpy(&bits, &f, 4);
      Put32(out, bits);
    }
  }
}

inline void WriteFileBytes(const std::string &path, const std::vector<uint8_t> &bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char *>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw IoError("cannot write " + path);
}

inline std::vector<uint8_t> ReadFileBytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

// A reader over a file's bytes that throws IoError naming the file when it
// would read past the end.
class Reader {
 public:
  Reader(const std::vector<uint8_t> &bytes, std::string path)
      : bytes_(bytes), path_(std::move(path)) {}
  uint64_t Get(size_t offset, int bytes) const {
    Need(offset, static_cast<size_t>(bytes));
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<uint64_t>(bytes_[offset + i]) << (8 * i);
    return v;
  }
  uint32_t Get32(size_t offset) const { return static_cast<uint32_t>(Get(offset, 4)); }
  void Need(size_t offset, size_t size) const {
    if (offset > bytes_.size() || size > bytes_.size() - offset)
      throw IoError(path_ + ": truncated (needs " + std::to_string(size) + " bytes at offset " +
                    std::to_string(offset) + ", the file has " + std::to_string(bytes_.size()) +
                    ")");
  }
  // `count` values of 2 (half) or 4 (float32) bytes from `offset`, widened.
  std::vector<double> Values(size_t offset, size_t count, ValueType storage) const {
    const size_t size = storage == ValueType::kHalf ? 2 : 4;
    if (count > bytes_.size() / size) Need(offset, bytes_.size() + 1);
    Need(offset, count * size);
    std::vector<double> values(count);
    for (size_t i = 0; i < count; ++i) {
      if (storage == ValueType::kHalf) {
        Imath::half h;
        h.setBits(static_cast<unsigned short>(Get(offset + 2 * i, 2)));
        values[i] = static_cast<float>(h);
      } else {
        const uint32_t bits = Get32(offset + 4 * i);
        float f;
        std::memcpy(&f, &bits, 4);
        values[i] = f;
      }
    }
    return values;
  }
  const std::string &path() const { return path_; }

 private:
  const std::vector<uint8_t> &bytes_;
  std::string path_;
};

}  // namespace texel_bytes
}  // namespace lutbake
