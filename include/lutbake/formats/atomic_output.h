// All-or-nothing output of a set of files (the tables of one bake).
//
// Writing. Each file is written through a temporary: an anonymous file in
// its destination directory (O_TMPFILE, written through "/proc/self/fd/N")
// where the file system has them, which the kernel frees whenever the
// process ends; otherwise a named file "<final>.lutbake-tmp-<pid>-<n>". Every
// temporary is held under an exclusive flock(2) for as long as its owner
// lives. Before any of them gets a name, every one is fsync'ed, all at once
// (one thread each: the file system then commits them in one journal
// transaction or a few, where one after another would take one each, 5 ms
// apiece on a busy disk).
//
// Commit, in four steps, each file by file:
//   1. link: the temporaries are fsync'ed (above); each anonymous one gets a
//      name, "<final>.lutbake-new-<pid>-<n>" (still locked), and the
//      directory is fsync'ed;
//   2. backup: each final name that exists is renamed away to
//      "<final>.lutbake-old-<pid>-<n>";
//   3. install: each temporary is renamed to its final name; the directory
//      is fsync'ed;
//   4. remove: the old files of step 2 are deleted.
// So at every moment the final names of the set hold complete, durable files
// of ONE run: until step 2 those of the previous run (all, then fewer), from
// step 3 on those of this run (more, then all). A process killed in steps
// 2-3 leaves a subset of one run's files and some temporaries; a process
// killed at any other moment leaves the previous run's set or this run's,
// whole. An error in steps 1-3 (a directory made read-only, a full disk)
// undoes what was done and throws IoError; what a run with a read-only
// directory cannot remove, and what a killed run leaves, is removed by
// RemoveStaleTemporaries at the start of the next run in that directory.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace lutbake {

class AtomicOutputSet {
 public:
  AtomicOutputSet() = default;
  AtomicOutputSet(const AtomicOutputSet &) = delete;
  AtomicOutputSet &operator=(const AtomicOutputSet &) = delete;
  // Discards every temporary unless Commit succeeded.
  ~AtomicOutputSet();

  // Registers a final path and returns the path to write it through (see
  // above). Throws IoError, naming finalPath and the reason, if no temporary
  // can be created (a missing or read-only directory, no space).
  std::string Add(const std::string &finalPath);
  // Add, then write(path) (fsync'ed by Commit or LinkInto): an exception of
  // write (IoError or another std::exception, such as OpenEXR's) is rethrown
  // as IoError whose message names finalPath where it named the temporary.
  void Write(const std::string &finalPath, const std::function<void(const std::string &)> &write);
  // Write for each file, the writes run at once (TBB, at most its allowed
  // parallelism); the temporaries are added in the files' order. When
  // writes fail, the first of them in that order is thrown, after all have
  // ended.
  struct FileWrite {
    std::string finalPath;
    std::function<void(const std::string &)> write;
  };
  void WriteEach(const std::vector<FileWrite> &files);
  // Steps 1-4 above; throws IoError on failure, after undoing steps 1-3 and
  // removing the temporaries.
  void Commit();
  // Removes every temporary (nothing under a final name is touched).
  void Discard();
  // Makes every file written so far durable: fsync, all at once, together
  // with alsoSync (an open file of the caller's, named alsoSyncName in a
  // message) when >= 0. Commit and LinkInto call it first. Throws IoError
  // naming the first file (in order) whose fsync failed.
  void Sync(int alsoSync = -1, const std::string &alsoSyncName = "");
  // Instead of Commit: Sync, then links every file written into `directory`
  // (on the same file system) under its final file name, then forgets the
  // temporaries. The caller installs `directory` as a whole
  // (OutputTransaction's exchange). Throws IoError, having linked nothing
  // it keeps, when an fsync or a link fails.
  void LinkInto(const std::string &directory);

  // For tests: called after every rename, link or removal that Commit makes,
  // with its step ("link", "backup", "install", "remove") and the file's
  // index; a test kills the process there to see what each moment leaves.
  using CommitObserver = std::function<void(const char *step, size_t index)>;
  void SetCommitObserver(CommitObserver observer) { observer_ = std::move(observer); }

 private:
  struct Entry {
    std::string finalPath;
    std::string writePath;   // what Add returned
    std::string namedPath;   // the temporary's name in the directory, once it has one
    std::string backupPath;  // where step 2 moved the previous final file
    int fd = -1;             // the temporary, open and flock'ed
    int backupFd = -1;       // the previous final file, flock'ed once moved away
    bool installed = false;
    bool synced = false;  // fsync'ed since it was written
  };
  void Undo();
  void Observe(const char *step, size_t index) const;
  std::vector<Entry> entries_;
  bool committed_ = false;
  CommitObserver observer_;
};

// Removes the temporaries in `directory` that lutbake runs left behind and
// that no live process owns: names "<final>.lutbake-{tmp,new,old}-<pid>-<n>"
// whose flock can be taken (a running owner holds it). Returns their paths.
// A missing directory has none.
std::vector<std::string> RemoveStaleTemporaries(const std::string &directory);

// True for a name that RemoveStaleTemporaries would consider (a lutbake
// temporary, alive or not).
bool IsTemporaryName(const std::string &fileName);

}  // namespace lutbake
