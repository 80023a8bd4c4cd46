#include "lutbake/formats/atomic_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "lutbake/formats/writer.h"

namespace lutbake {

AtomicOutputSet::~AtomicOutputSet() {
  if (!committed_) Discard();
}

std::string AtomicOutputSet::Add(const std::string &finalPath) {
  const std::string temporary =
      finalPath + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(entries_.size());
  entries_.push_back({finalPath, temporary});
  return temporary;
}

void AtomicOutputSet::Discard() {
  for (const Entry &e : entries_) std::remove(e.temporaryPath.c_str());
  entries_.clear();
}

void AtomicOutputSet::Commit() {
  for (const Entry &e : entries_) {
    if (std::rename(e.temporaryPath.c_str(), e.finalPath.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      Discard();
      throw IoError("cannot rename " + e.temporaryPath + " to " + e.finalPath + ": " + reason);
    }
  }
  committed_ = true;
}

}  // namespace lutbake
