// Replays the table readers' fuzz corpora (tests/fuzz/corpus/{bin,exr,
// header,png,ktx2,dds,source}, grown by scripts/fuzz.sh and kept minimal with
// -merge=1) on every test run, without clang or libFuzzer: each kept input,
// the once-crashing ones included, is read or refused with an IoError that
// names the file, and what is read has the shape its axes say. The scene and
// manifest corpora are replayed by tests/plans/fuzz_corpus_test.cpp, the
// option parsing's and preset.json's by tests/cli/option_corpus_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(LUTBAKE_TEST_DATA).parent_path() / "fuzz" / "corpus";

std::vector<std::string> CorpusFiles(const std::string &reader) {
  std::vector<std::string> files;
  for (const auto &entry : fs::directory_iterator(kCorpus / reader))
    files.push_back(entry.path().string());
  return files;
}

// Reads every kept input of `reader`'s corpus with `read`; `shapeHolds`
// checks what was read. Returns how many were read (the rest were refused).
template <typename Read, typename ShapeHolds>
size_t Replay(const std::string &reader, Read read, ShapeHolds shapeHolds) {
  const std::vector<std::string> files = CorpusFiles(reader);
  EXPECT_GE(files.size(), 5u) << reader;  // the seeds alone are more
  size_t read_ = 0;
  for (const std::string &path : files) {
    try {
      EXPECT_TRUE(shapeHolds(read(path))) << path;
      ++read_;
    } catch (const IoError &e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  return read_;
}

bool TableShapeHolds(const Table &t) {
  return (t.channels == 1 || t.channels == 2) &&
         t.channelNames.size() == static_cast<size_t>(t.channels) &&
         t.values.size() == t.texelCount() * t.channels &&
         (t.errors.empty() || t.errors.size() == t.values.size());
}

TEST(FuzzCorpus, BinaryInputsAreReadOrRefused) {
  EXPECT_GT(Replay("bin", ReadBinaryTable, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, ExrInputsAreReadOrRefused) {
  EXPECT_GT(Replay("exr", ReadExrTable, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, PngInputsAreReadOrRefused) {
  EXPECT_GT(Replay("png", ReadPngTable, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, Ktx2InputsAreReadOrRefused) {
  EXPECT_GT(Replay("ktx2", ReadKtx2Table, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, DdsInputsAreReadOrRefused) {
  EXPECT_GT(Replay("dds", ReadDdsTable, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, SourceEmbeddingInputsAreReadOrRefused) {
  EXPECT_GT(Replay("source", ReadSourceTable, TableShapeHolds), 0u);
}

TEST(FuzzCorpus, HeaderInputsAreReadOrRefused) {
  const auto shapeHolds = [](const HeaderValues &h) {
    return h.values.size() ==
           static_cast<size_t>(h.width) * h.height * h.depth * static_cast<size_t>(h.channels);
  };
  EXPECT_GT(Replay("header", ReadHeaderValues, shapeHolds), 0u);
}

}  // namespace
}  // namespace lutbake
