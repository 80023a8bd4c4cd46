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
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lutbake/core/cancellation.h"
#include "lutbake/formats/atomic_output.h"

namespace lutbake {

class OutputTransaction {
 public:
  // Steps 1 and 2 for `directory`; `optionName` names it in messages
  // ("--out").
  explicit OutputTransaction(const std::string &directory, const std::string &optionName = "--out");
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

 private:
  std::string directory_;
  bool created_ = false;
  bool committed_ = false;
  AtomicOutputSet output_;
  std::vector<std::string> files_;
};

// Step 1 alone: "" when `dir` is (or has become) a writable directory, else
// the reason ("is empty; accepted: ..."); *usageError when the value itself
// is wrong, *created when this call made the directory.
std::string PrepareOutputDirectory(const std::string &dir, bool *created, bool *usageError);

// Removes `dir` if `created` and it is still empty.
void RemoveCreatedDirectory(const std::string &dir, bool created);

}  // namespace lutbake
