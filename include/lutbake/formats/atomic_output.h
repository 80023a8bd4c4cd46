// All-or-nothing output of several files. Each file is first written under a
// temporary name in its destination directory ("<name>.tmp-<pid>-<n>"); Commit
// renames them all to their final names. If anything throws before Commit,
// the destructor removes every temporary file, so a failed bake leaves no
// partial table and no temporary behind.
#pragma once

#include <string>
#include <vector>

namespace lutbake {

class AtomicOutputSet {
 public:
  AtomicOutputSet() = default;
  AtomicOutputSet(const AtomicOutputSet &) = delete;
  AtomicOutputSet &operator=(const AtomicOutputSet &) = delete;
  ~AtomicOutputSet();

  // Registers a final path and returns the temporary path to write instead.
  std::string Add(const std::string &finalPath);
  // Renames every temporary file to its final path; throws IoError on failure
  // (after removing what is left of the temporaries).
  void Commit();
  void Discard();

 private:
  struct Entry {
    std::string finalPath, temporaryPath;
  };
  std::vector<Entry> entries_;
  bool committed_ = false;
};

}  // namespace lutbake
