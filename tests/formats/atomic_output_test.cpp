// AtomicOutputSet: a set of files appears under its final names whole or
// not at all; a process killed at every step of the commit leaves only files
// of one run under final names, and the temporaries it leaves are removed by
// RemoveStaleTemporaries (and only those: a live owner's are kept).
#include "lutbake/formats/atomic_output.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "lutbake/formats/writer.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

fs::path ScratchDirectory(const std::string &name) {
  const fs::path dir =
      fs::temp_directory_path() / ("lutbake_atomic_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string ReadAll(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The directory's files by name, with their contents.
std::map<std::string, std::string> Contents(const fs::path &dir) {
  std::map<std::string, std::string> files;
  for (const auto &entry : fs::directory_iterator(dir))
    files[entry.path().filename().string()] = ReadAll(entry.path());
  return files;
}

const std::vector<std::string> kNames = {"a.exr", "a.bin", "a.h", "b.exr", "b.bin"};

// A file of run `run`: long enough that a torn one is seen (its size).
std::string Payload(const std::string &run, const std::string &name) {
  return "run " + run + " file " + name + " " + std::string(4096, 'x') + " end";
}

void WriteSet(const fs::path &dir, const std::string &run,
              AtomicOutputSet::CommitObserver observer = {}) {
  AtomicOutputSet set;
  set.SetCommitObserver(std::move(observer));
  for (const std::string &name : kNames)
    set.Write((dir / name).string(), [&](const std::string &path) {
      std::ofstream(path, std::ios::binary | std::ios::trunc) << Payload(run, name);
    });
  set.Commit();
}

TEST(AtomicOutput, NothingUnderFinalNamesBeforeCommitAndNoTemporaryAfter) {
  const fs::path dir = ScratchDirectory("commit");
  {
    AtomicOutputSet set;
    for (const std::string &name : kNames)
      set.Write((dir / name).string(), [&](const std::string &path) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << Payload("1", name);
      });
    for (const auto &[name, content] : Contents(dir))
      EXPECT_TRUE(IsTemporaryName(name)) << name << " appeared before Commit";
    set.Commit();
  }
  const auto files = Contents(dir);
  ASSERT_EQ(files.size(), kNames.size());
  for (const std::string &name : kNames) EXPECT_EQ(files.at(name), Payload("1", name));
  // A second set replaces the first whole; a discarded third leaves it.
  WriteSet(dir, "2");
  {
    AtomicOutputSet set;
    set.Write((dir / "a.exr").string(), [](const std::string &path) {
      std::ofstream(path, std::ios::binary | std::ios::trunc) << "third";
    });
  }  // not committed
  const auto second = Contents(dir);
  ASSERT_EQ(second.size(), kNames.size());
  for (const std::string &name : kNames) EXPECT_EQ(second.at(name), Payload("2", name));
  fs::remove_all(dir);
}

TEST(AtomicOutput, ErrorsNameTheFinalFileAndTheReason) {
  const fs::path dir = ScratchDirectory("errors");
  const std::string missing = (dir / "nope" / "a.exr").string();
  AtomicOutputSet set;
  try {
    set.Add(missing);
    ADD_FAILURE() << "Add in a missing directory succeeded";
  } catch (const IoError &e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
  // A writer's message about its temporary is rewritten to the final name.
  const std::string path = (dir / "a.bin").string();
  try {
    set.Write(path, [](const std::string &temporary) {
      throw IoError("cannot write " + temporary + ": Disk quota exceeded");
    });
    ADD_FAILURE() << "a failed write was not reported";
  } catch (const IoError &e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + path + ": Disk quota exceeded");
  }
  set.Discard();
  EXPECT_TRUE(Contents(dir).empty());
  fs::remove_all(dir);
}

TEST(AtomicOutput, OnlyTemporariesOfDeadOwnersAreStale) {
  const fs::path dir = ScratchDirectory("stale");
  // Not lutbake's, or not of the form: never touched.
  for (const char *name : {"a.exr", "a.exr.tmp-1-2", "notes.lutbake-tmp-x-1", ".lutbake-tmp-1-2",
                           "a.exr.lutbake-tmp-12-"})
    std::ofstream(dir / name) << "keep";
  // Of the form, with no owner (nothing holds its lock): stale.
  std::ofstream(dir / "a.exr.lutbake-old-999999-3") << "stale";
  // A live owner's (this process holds the lock): kept.
  AtomicOutputSet live;
  live.Write((dir / "b.exr").string(), [](const std::string &path) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << "live";
  });
  const std::vector<std::string> removed = RemoveStaleTemporaries(dir.string());
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(fs::path(removed[0]).filename(), "a.exr.lutbake-old-999999-3");
  EXPECT_EQ(Contents(dir).size(), 5u);
  live.Commit();
  EXPECT_EQ(ReadAll(dir / "b.exr"), "live");
  EXPECT_TRUE(RemoveStaleTemporaries(dir.string()).empty());
  fs::remove_all(dir);
}

// Kills a child process at the k-th step of its commit of run "new" over a
// complete set of run "old", for every k, and checks what it leaves.
TEST(AtomicOutput, KilledAtEveryCommitStepLeavesFilesOfOneRunOnly) {
  const fs::path dir = ScratchDirectory("kill");
  const size_t steps = 4 * kNames.size();  // link, backup, install, remove
  std::map<std::string, int> outcomes;     // which run's files, at how many steps
  for (size_t kill = 0; kill < steps; ++kill) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    WriteSet(dir, "old");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      size_t step = 0;
      WriteSet(dir, "new", [&](const char *, size_t) {
        if (step++ == kill) ::raise(SIGKILL);
      });
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "step " << kill;
    // Under final names: complete files, all of one run.
    std::string run;
    size_t finals = 0;
    for (const auto &[name, content] : Contents(dir)) {
      if (IsTemporaryName(name)) continue;
      ++finals;
      const std::string of = content.substr(4, content.find(' ', 4) - 4);
      EXPECT_EQ(content, Payload(of, name)) << "step " << kill << ": " << name << " is torn";
      if (run.empty()) run = of;
      EXPECT_EQ(of, run) << "step " << kill << ": " << name << " is of another run";
    }
    ++outcomes[run + (finals == kNames.size() ? " whole" : " part")];
    // The next run finds the dead child's temporaries stale, and writes a
    // whole set beside nothing else.
    RemoveStaleTemporaries(dir.string());
    for (const auto &[name, content] : Contents(dir))
      EXPECT_FALSE(IsTemporaryName(name)) << "step " << kill << ": " << name << " left";
    WriteSet(dir, "next");
    const auto after = Contents(dir);
    EXPECT_EQ(after.size(), kNames.size()) << "step " << kill;
    for (const std::string &name : kNames)
      EXPECT_EQ(after.count(name) ? after.at(name) : "", Payload("next", name));
  }
  // The steps cover every state the protocol has: the old set whole (after
  // each link), part of it and then nothing (after each backup), part of the
  // new one and then all (after each install), the new set whole (after each
  // remove).
  const int n = static_cast<int>(kNames.size());
  EXPECT_EQ(outcomes["old whole"], n);
  EXPECT_EQ(outcomes["old part"], n - 1);
  EXPECT_EQ(outcomes[" part"], 1);
  EXPECT_EQ(outcomes["new part"], n - 1);
  EXPECT_EQ(outcomes["new whole"], n + 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
