// Replays the option fuzzer's corpus (tests/fuzz/corpus/cli: command lines,
// one argument per line, grown by scripts/fuzz.sh) through the app that
// main() builds (src/cli/app.h), parsing only: each parses or is refused with
// CLI11's ParseError, on every test run and without libFuzzer. And the
// preset.json fuzzer's corpus (tests/fuzz/corpus/preset) through
// ReadPresetListing: each is read or refused with an IoError naming it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli/app.h"
#include "lutbake/api/presets.h"
#include "fuzz/cli_input.h"
#include "lutbake/formats/writer.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

TEST(FuzzCorpus, CommandLinesParseOrAreRefused) {
  const fs::path corpus = fs::path(LUTBAKE_TEST_DATA).parent_path() / "fuzz" / "corpus" / "cli";
  size_t inputs = 0, parsed = 0, refused = 0;
  for (const auto &entry : fs::directory_iterator(corpus)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::vector<std::string> args = fuzz::CommandLineOf(bytes.data(), bytes.size());
    std::vector<const char *> argv;
    for (const std::string &arg : args) argv.push_back(arg.c_str());
    const auto cli = cli::MakeLutbakeApp();
    ++inputs;
    try {
      cli->app.parse(static_cast<int>(argv.size()), argv.data());
      ++parsed;
    } catch (const CLI::ParseError &) {
      ++refused;
    }
  }
  EXPECT_GE(inputs, 60u);  // the bad-input corpus and the docs' examples
  EXPECT_GT(parsed, 0u);   // the docs' examples parse
  EXPECT_GT(refused, 0u);  // the bad inputs are refused (some only when run)
}

TEST(FuzzCorpus, PresetListingsAreReadOrRefused) {
  const fs::path corpus = fs::path(LUTBAKE_TEST_DATA).parent_path() / "fuzz" / "corpus" / "preset";
  size_t inputs = 0, read = 0;
  for (const auto &entry : fs::directory_iterator(corpus)) {
    ++inputs;
    const std::string path = entry.path().string();
    try {
      const PresetListing listing = ReadPresetListing(path);
      EXPECT_NE(listing.preset, nullptr) << path;
      for (const auto &[file, errorMax] : listing.errorMaxByFile)
        EXPECT_TRUE(errorMax >= 0.0 && errorMax <= 1.0) << path << ": " << file;
      ++read;
    } catch (const IoError &e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  EXPECT_GE(inputs, 5u);  // the seeds: preset.json of several presets
  EXPECT_GT(read, 0u);    // the seeds are read
}

}  // namespace
}  // namespace lutbake
