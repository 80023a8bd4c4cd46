// Replays the fuzzers' corpora (tests/fuzz/corpus/, grown by
// scripts/fuzz.sh) through the readers on every test run, so that an input
// that once crashed or escaped stays fixed without a fuzzer: each file is
// read or refused with InputError, and what is read plans.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "lutbake/plans/manifest.h"
#include "lutbake/plans/plan.h"
#include "lutbake/plans/scene.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(LUTBAKE_TEST_DATA).parent_path() / "fuzz" / "corpus";

std::vector<std::string> Inputs(const std::string &folder) {
  std::vector<std::string> inputs;
  for (const auto &entry : fs::directory_iterator(kCorpus / folder)) {
    std::ifstream in(entry.path(), std::ios::binary);
    inputs.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return inputs;
}

TEST(FuzzCorpus, SceneInputsAreReadOrRefused) {
  const auto inputs = Inputs("scene");
  ASSERT_GE(inputs.size(), 20u);  // the seeds alone are more
  size_t read = 0;
  for (const std::string &bytes : inputs)
    for (const char *name : {"corpus.gltf", "corpus.glb"}) {
      try {
        MakePlan(ParseSceneMaterials(bytes, name), {});
        ++read;
      } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
    }
  EXPECT_GT(read, 0u);  // the corpus holds valid scenes too
}

TEST(FuzzCorpus, ManifestInputsAreReadOrRefused) {
  const auto inputs = Inputs("manifest");
  ASSERT_GE(inputs.size(), 5u);
  size_t read = 0;
  for (const std::string &text : inputs) {
    try {
      MakePlan(ParseManifest(text, "corpus.json").materials, {});
      ++read;
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find("corpus.json"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(read, 0u);
}

}  // namespace
}  // namespace lutbake
