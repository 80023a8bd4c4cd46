// The one way lutbake writes a set of files into a directory: every command
// that writes (bake, bake --preset, report, furnace) opens an
// OutputTransaction, writes each file through it and commits once.
//
//   1. prepare: the directory is created if missing and probed for
//      writability; an empty path or a path that is not a directory is a
//      UsageError ("--out DIR: ..."), an unwritable one an IoError;
//   2. stale temporaries that killed runs left there are removed;
//   3. each Write goes to a temporary (AtomicOutputSet, atomic_output.h);
//   4. Commit checks the cancellation token one last time and installs
//      the whole set;
//   5. a transaction destroyed without a successful Commit (an exception, a
//      cancellation) removes its temporaries and, if it created the
//      directory and the directory is still empty, the directory.
// So a failed or cancelled run leaves the directory as it found it.
//
// A set (OutputMode::kSet: bake and bake --preset). The directory holds one
// lutbake set at a time: the commit also writes lutbake-set.json, the list
// of the set's files, and replaces the previous set as a whole. Files of the
// previous set that the new one does not write go; files that no lutbake set
// lists (foreignFiles) are never touched. The replacement is one
// renameat2(RENAME_EXCHANGE) of the directory with a sibling that holds the
// new set and hard links to the foreign files ("." NAME ".lutbake-set-PID-N"
// beside it), so a kill at any moment leaves either the whole previous set
// or the whole new one. Where that cannot be done (the directory is a mount
// point or this process's working directory, its parent is not writable, it
// holds a subdirectory, or the file system has no RENAME_EXCHANGE) the set
// is installed file by file as AtomicOutputSet does and the previous set's
// other files are removed after it: a kill in those milliseconds can leave
// both sets' files (exchanged() says which way was taken). A sibling left by
// a killed run is cleaned up by the next set committed beside it; what it
// holds that its set does not list and the directory lacks is moved back.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/core/cancellation.h"
#include "lutbake/formats/atomic_output.h"

namespace lutbake {

// The file that lists a directory's lutbake set.
inline constexpr const char *kSetManifestName = "lutbake-set.json";

enum class OutputMode {
  kFiles,  // the files written replace those of the same names; nothing else changes
  kSet,    // the files written, and lutbake-set.json, replace the previous set
};

class OutputTransaction {
 public:
  // Steps 1 and 2 for `directory`; `optionName` names it in messages
  // ("--out"). In kSet mode `description` (the command line) goes into
  // lutbake-set.json.
  explicit OutputTransaction(const std::string &directory, const std::string &optionName = "--out",
                             OutputMode mode = OutputMode::kFiles,
                             const std::string &description = "");
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction &) = delete;
  OutputTransaction &operator=(const OutputTransaction &) = delete;

  const std::string &directory() const { return directory_; }
  // directory / fileName.
  std::string PathOf(const std::string &fileName) const;
  // Writes fileName through a temporary: write(temporaryPath) must create it.
  // Returns the final path. Throws IoError naming the final path.
  std::string Write(const std::string &fileName,
                    const std::function<void(const std::string &temporaryPath)> &write);
  // Write for several files, their writes run at once (AtomicOutputSet::
  // WriteEach); `files` holds (fileName, write). Returns the final paths, in
  // that order.
  std::vector<std::string> WriteEach(
      const std::vector<std::pair<std::string, std::function<void(const std::string &)>>> &files);
  // Writes `text` as fileName's whole content.
  std::string WriteText(const std::string &fileName, const std::string &text);
  // Throws Cancelled if `cancellation` is cancelled, else installs every file
  // written (AtomicOutputSet::Commit). After it, the destructor leaves all.
  void Commit(const CancellationToken *cancellation = nullptr);
  // Abandons the set: temporaries removed, the directory too if this
  // transaction created it and it is empty (as the destructor does).
  void Discard();
  // The final paths written so far, in order.
  const std::vector<std::string> &files() const { return files_; }
  bool createdDirectory() const { return created_; }
  // kSet, after Commit: the names in the directory that no lutbake set
  // lists (left as they were), the previous set's files the new one
  // dropped, and whether the set was installed by exchanging directories.
  const std::vector<std::string> &foreignFiles() const { return foreign_; }
  const std::vector<std::string> &removedFiles() const { return removed_; }
  bool exchanged() const { return exchanged_; }

 private:
  void CommitSet();
  bool TryExchange(const std::vector<std::string> &oldSetNames, const std::string &manifestText);
  std::string directory_;
  OutputMode mode_ = OutputMode::kFiles;
  std::string description_;
  bool created_ = false;
  bool committed_ = false;
  bool exchanged_ = false;
  AtomicOutputSet output_;
  std::vector<std::string> files_;
  std::vector<std::string> previousSet_;  // lutbake-set.json's list when we started
  std::vector<std::string> foreign_, removed_;
};

// The files a directory's lutbake-set.json lists (empty when it has none or
// cannot be read: then no file there counts as lutbake's).
std::vector<std::string> ReadSetManifest(const std::string &directory);

// Step 1 alone: "" when `dir` is (or has become) a writable directory, else
// the reason ("is empty; accepted: ..."); *usageError when the value itself
// is wrong, *created when this call made the directory.
std::string PrepareOutputDirectory(const std::string &dir, bool *created, bool *usageError);

// Removes `dir` if `created` and it is still empty.
void RemoveCreatedDirectory(const std::string &dir, bool created);

}  // namespace lutbake
