// OutputTransaction in set mode: a directory holds one lutbake set. The
// previous set's files the new one does not write go, files no set lists
// stay, lutbake-set.json lists the set; the two sets are swapped whole
// (RENAME_EXCHANGE), so a child killed at any moment of a commit leaves
// exactly one of the two sets; a sibling a killed run left is retired by
// the next commit, and what it holds that the directory lacks moves back.
#include "lutbake/formats/output_transaction.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace lutbake {
namespace {

namespace fs = std::filesystem;

fs::path Scratch(const std::string &name) {
  const fs::path dir =
      fs::temp_directory_path() / ("lutbake_set_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::map<std::string, std::string> Contents(const fs::path &dir) {
  std::map<std::string, std::string> files;
  for (const auto &entry : fs::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    files[entry.path().filename().string()] = std::string((std::istreambuf_iterator<char>(in)), {});
  }
  return files;
}

// A set of `names`, each file holding `tag`, committed into `dir`.
void CommitSet(const fs::path &dir, const std::vector<std::string> &names, const std::string &tag,
               bool *exchanged = nullptr) {
  OutputTransaction output(dir.string(), "--out", OutputMode::kSet, tag);
  for (const std::string &name : names) output.WriteText(name, tag);
  output.Commit();
  if (exchanged) *exchanged = output.exchanged();
}

TEST(OutputSet, ReplacesThePreviousSetAndKeepsForeignFiles) {
  const fs::path dir = Scratch("replace");
  CommitSet(dir, {"a.exr", "b.exr", "c.h"}, "run1");
  EXPECT_EQ(ReadSetManifest(dir.string()), (std::vector<std::string>{"a.exr", "b.exr", "c.h"}));
  std::ofstream(dir / "notes.txt") << "mine";
  bool exchanged = false;
  OutputTransaction output(dir.string(), "--out", OutputMode::kSet, "run2");
  output.WriteText("a.exr", "run2");
  output.WriteText("d.bin", "run2");
  output.Commit();
  exchanged = output.exchanged();
  const auto files = Contents(dir);
  EXPECT_EQ(files.size(), 4u);  // a.exr, d.bin, lutbake-set.json, notes.txt
  EXPECT_EQ(files.at("a.exr"), "run2");
  EXPECT_EQ(files.at("d.bin"), "run2");
  EXPECT_EQ(files.at("notes.txt"), "mine");
  EXPECT_EQ(files.count("b.exr"), 0u);
  EXPECT_EQ(output.foreignFiles(), std::vector<std::string>{"notes.txt"});
  EXPECT_EQ(output.removedFiles(), (std::vector<std::string>{"b.exr", "c.h"}));
  EXPECT_EQ(ReadSetManifest(dir.string()), (std::vector<std::string>{"a.exr", "d.bin"}));
  // Where the file system has RENAME_EXCHANGE (ext4, tmpfs, xfs, btrfs,
  // overlayfs) the set was swapped whole; nothing is left beside the
  // directory either way.
  std::printf("exchanged: %s\n", exchanged ? "yes" : "no (file by file)");
  for (const auto &entry : fs::directory_iterator(dir.parent_path()))
    EXPECT_EQ(
        entry.path().filename().string().find("." + dir.filename().string() + ".lutbake-set-"),
        std::string::npos);
  fs::remove_all(dir);
}

TEST(OutputSet, AStaleSiblingIsRetiredAndUnknownFilesMoveBack) {
  const fs::path dir = Scratch("stale");
  CommitSet(dir, {"a.exr"}, "run1");
  // What a run killed after its exchange leaves: the previous set beside
  // the directory, with a file made in the directory during the exchange.
  const fs::path sibling =
      dir.parent_path() / ("." + dir.filename().string() + ".lutbake-set-999999-0");
  fs::create_directories(sibling);
  std::ofstream(sibling / "old.exr") << "old";
  std::ofstream(sibling / "lutbake-set.json") << R"({"files": ["old.exr"]})";
  std::ofstream(sibling / "late.txt") << "made during the exchange";
  CommitSet(dir, {"a.exr"}, "run2");
  EXPECT_FALSE(fs::exists(sibling));
  const auto files = Contents(dir);
  EXPECT_EQ(files.at("late.txt"), "made during the exchange");
  EXPECT_EQ(files.count("old.exr"), 0u);
  EXPECT_EQ(files.at("a.exr"), "run2");
  fs::remove_all(dir);
}

// Children commit a set of 40 files ("runN" in every file) over a previous
// set of other names and are killed at random moments: every time, the
// directory holds all files of exactly one run and its lutbake-set.json
// names exactly them (no mixed set, no partial one).
TEST(OutputSet, KillsNeverLeaveAMixedOrPartialSet) {
  const fs::path dir = Scratch("kills");
  const auto namesOf = [](int run) {
    std::vector<std::string> names;
    for (int k = 0; k < 40; ++k) names.push_back("t" + std::to_string(k + (run % 2) * 20) + ".bin");
    return names;
  };
  CommitSet(dir, namesOf(0), "run0");
  std::mt19937 random(7);
  std::uniform_int_distribution<int> microseconds(0, 30000);
  int whole = 0, exchangedRuns = 0;
  for (int run = 1; run <= 40; ++run) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      bool exchanged = false;
      CommitSet(dir, namesOf(run), "run" + std::to_string(run), &exchanged);
      ::_exit(exchanged ? 10 : 11);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(microseconds(random)));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 10) ++exchangedRuns;
    const auto files = Contents(dir);
    const std::vector<std::string> listed = ReadSetManifest(dir.string());
    ASSERT_EQ(listed.size(), 40u) << "run " << run;
    std::string tag;
    for (const std::string &name : listed) {
      ASSERT_EQ(files.count(name), 1u) << "run " << run << ": " << name << " missing";
      if (tag.empty()) tag = files.at(name);
      EXPECT_EQ(files.at(name), tag) << "run " << run << ": " << name << " of another run";
    }
    // Only the set, its list, and (a kill in the fallback's renames)
    // temporaries the next run removes.
    for (const auto &[name, content] : files) {
      if (name == kSetManifestName || IsTemporaryName(name)) continue;
      EXPECT_NE(std::find(listed.begin(), listed.end(), name), listed.end())
          << "run " << run << ": " << name << " belongs to no set";
    }
    ++whole;
  }
  CommitSet(dir, namesOf(0), "final");
  EXPECT_EQ(Contents(dir).size(), 41u);
  std::printf("%d kills, each left one whole set; %d runs finished by exchange\n", whole,
              exchangedRuns);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
