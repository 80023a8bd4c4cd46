#include "lutbake/formats/atomic_output.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <set>

#include "blocking_calls.h"
#include "lutbake/formats/writer.h"

namespace lutbake {

namespace {

// Numbers the temporaries of this process, across sets, so that two sets of
// one process never pick the same name.
std::atomic<unsigned long> temporaryCounter{0};

std::string Reason() { return std::strerror(errno); }

std::string DirectoryOf(const std::string &path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

// "<final>.lutbake-<kind>-<pid>-<n>", n unique in this process.
std::string TemporaryName(const std::string &finalPath, const char *kind) {
  return finalPath + ".lutbake-" + kind + "-" + std::to_string(::getpid()) + "-" +
         std::to_string(temporaryCounter.fetch_add(1));
}

// True if `fd` is still the file at `path`: a name we created and locked
// can have been removed, between the two, by another process's
// RemoveStaleTemporaries (which saw it unlocked).
bool SameFile(int fd, const std::string &path) {
  struct stat byFd, byPath;
  return ::fstat(fd, &byFd) == 0 && ::stat(path.c_str(), &byPath) == 0 &&
         byFd.st_dev == byPath.st_dev && byFd.st_ino == byPath.st_ino;
}

void FsyncDirectory(const std::string &directory, const std::string &forFile) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot write " + forFile + ": cannot open its directory: " + Reason());
  const int status = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (status != 0 && error != EINVAL)  // EINVAL: a file system without directory sync
    throw IoError("cannot write " + forFile +
                  ": cannot sync its directory: " + std::strerror(error));
}

void CloseIfOpen(int *fd) {
  if (*fd >= 0) ::close(*fd);
  *fd = -1;
}

}  // namespace

bool IsTemporaryName(const std::string &fileName) {
  // <anything>.lutbake-(tmp|new|old)-<digits>-<digits>
  for (const char *kind : {".lutbake-tmp-", ".lutbake-new-", ".lutbake-old-"}) {
    const size_t at = fileName.rfind(kind);
    if (at == std::string::npos || at == 0) continue;
    const std::string rest = fileName.substr(at + std::strlen(kind));
    const size_t dash = rest.find('-');
    if (dash == std::string::npos || dash == 0 || dash + 1 == rest.size()) continue;
    const auto digits = [](const std::string &s) {
      return s.find_first_not_of("0123456789") == std::string::npos;
    };
    if (digits(rest.substr(0, dash)) && digits(rest.substr(dash + 1))) return true;
  }
  return false;
}

std::vector<std::string> RemoveStaleTemporaries(const std::string &directory) {
  std::vector<std::string> removed;
  std::error_code ec;
  std::filesystem::directory_iterator it(directory, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!IsTemporaryName(name)) continue;
    const std::string path = it->path().string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) continue;
    struct stat st;
    // Its owner, while it lives, holds the lock: a lock we can take is
    // that of a dead owner. Unlinked under our lock, and only if the name
    // still holds the file we locked.
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        SameFile(fd, path) && ::unlink(path.c_str()) == 0)
      removed.push_back(path);
    ::close(fd);
  }
  return removed;
}

AtomicOutputSet::~AtomicOutputSet() {
  if (!committed_) Discard();
}

std::string AtomicOutputSet::Add(const std::string &finalPath) {
  Entry e;
  e.finalPath = finalPath;
  const std::string directory = DirectoryOf(finalPath);
  // An anonymous file: nothing to clean up after any end of the process.
  e.fd = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
  if (e.fd >= 0) {
    ::flock(e.fd, LOCK_EX);  // nobody else can see it yet; held once it is linked
    e.writePath = "/proc/self/fd/" + std::to_string(e.fd);
  } else if (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL) {
    // No O_TMPFILE on this file system: a named temporary, locked. Retried
    // if another run's RemoveStaleTemporaries removed it before our lock.
    for (int attempt = 0; attempt < 100 && e.fd < 0; ++attempt) {
      const std::string name = TemporaryName(finalPath, "tmp");
      e.fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (e.fd < 0) {
        if (errno == EEXIST) continue;
        break;
      }
      if (::flock(e.fd, LOCK_EX) == 0 && SameFile(e.fd, name)) {
        e.namedPath = e.writePath = name;
      } else {
        CloseIfOpen(&e.fd);
      }
    }
  }
  if (e.fd < 0) throw IoError("cannot write " + finalPath + ": " + Reason());
  entries_.push_back(e);
  return e.writePath;
}

namespace {

// write(path), its exceptions rethrown as IoError naming finalPath where
// they named the temporary `path`.
void WriteThrough(const std::string &finalPath, const std::string &path,
                  const std::function<void(const std::string &)> &write) {
  const auto named = [&](std::string message) {
    for (size_t at = message.find(path); at != std::string::npos;
         at = message.find(path, at + finalPath.size()))
      message.replace(at, path.size(), finalPath);
    return message;
  };
  try {
    write(path);
  } catch (const IoError &e) {
    throw IoError(named(e.what()));
  } catch (const std::bad_alloc &) {
    throw;
  } catch (const std::exception &e) {
    throw IoError("cannot write " + finalPath + ": " + named(e.what()));
  }
}

}  // namespace

void AtomicOutputSet::Write(const std::string &finalPath,
                            const std::function<void(const std::string &)> &write) {
  // Made durable (Sync, from Commit and LinkInto) before it can get its
  // final name: a crash after the rename must not leave the name on an
  // empty or partial file.
  WriteThrough(finalPath, Add(finalPath), write);
}

void AtomicOutputSet::WriteEach(const std::vector<FileWrite> &files) {
  std::vector<std::string> paths;
  for (const FileWrite &file : files) paths.push_back(Add(file.finalPath));
  std::vector<std::exception_ptr> errors(files.size());
  tbb::parallel_for(size_t{0}, files.size(), [&](size_t k) {
    try {
      WriteThrough(files[k].finalPath, paths[k], files[k].write);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  for (const std::exception_ptr &error : errors)
    if (error) std::rethrow_exception(error);
}

void AtomicOutputSet::Sync(int alsoSync, const std::string &alsoSyncName) {
  std::vector<int> fds;
  std::vector<std::string> names;
  for (Entry &e : entries_)
    if (!e.synced) fds.push_back(e.fd), names.push_back(e.finalPath);
  if (alsoSync >= 0) fds.push_back(alsoSync), names.push_back(alsoSyncName);
  // All at once (blocking_calls.h): the waits overlap, and the file system
  // groups the commits.
  std::vector<int> errors(fds.size(), 0);
  RunBlockingCalls(fds.size(), [&](size_t k) {
    if (::fsync(fds[k]) != 0) errors[k] = errno;
  });
  for (size_t k = 0; k < fds.size(); ++k)
    if (errors[k] != 0) throw IoError("cannot write " + names[k] + ": " + std::strerror(errors[k]));
  for (Entry &e : entries_) e.synced = true;
}

void AtomicOutputSet::Observe(const char *step, size_t index) const {
  if (observer_) observer_(step, index);
}

void AtomicOutputSet::Commit() {
  std::set<std::string> directories;
  for (const Entry &e : entries_) directories.insert(DirectoryOf(e.finalPath));
  const auto syncDirectories = [&] {
    for (const std::string &d : directories) FsyncDirectory(d, d);
  };
  try {
    // 1. link: the temporaries made durable, then the anonymous ones get a
    // (locked) name.
    Sync();
    for (size_t i = 0; i < entries_.size(); ++i) {
      Entry &e = entries_[i];
      if (!e.namedPath.empty()) continue;
      const std::string name = TemporaryName(e.finalPath, "new");
      if (::linkat(AT_FDCWD, e.writePath.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) != 0)
        throw IoError("cannot write " + e.finalPath + ": " + Reason());
      e.namedPath = name;
      Observe("link", i);
    }
    syncDirectories();
    // 2. backup: the previous files under the final names move away.
    for (size_t i = 0; i < entries_.size(); ++i) {
      Entry &e = entries_[i];
      struct stat st;
      if (::lstat(e.finalPath.c_str(), &st) != 0) continue;
      const std::string name = TemporaryName(e.finalPath, "old");
      if (::rename(e.finalPath.c_str(), name.c_str()) != 0) {
        if (errno == ENOENT) continue;
        throw IoError("cannot replace " + e.finalPath + ": " + Reason());
      }
      e.backupPath = name;
      // Locked, so that no other run takes it for stale while we may still
      // need it to undo; another run that starts in this very instant may
      // remove it first, and then an undo cannot bring it back.
      e.backupFd = ::open(name.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
      if (e.backupFd >= 0) ::flock(e.backupFd, LOCK_EX | LOCK_NB);
      Observe("backup", i);
    }
    // 3. install.
    for (size_t i = 0; i < entries_.size(); ++i) {
      Entry &e = entries_[i];
      if (::rename(e.namedPath.c_str(), e.finalPath.c_str()) != 0)
        throw IoError("cannot write " + e.finalPath + ": " + Reason());
      e.installed = true;
      Observe("install", i);
    }
    syncDirectories();
  } catch (const IoError &) {
    Undo();
    Discard();
    throw;
  }
  committed_ = true;
  // 4. remove the previous files. One that cannot be removed now (the
  // directory turned read-only) is stale once we end: the next run removes it.
  for (size_t i = 0; i < entries_.size(); ++i) {
    Entry &e = entries_[i];
    if (!e.backupPath.empty()) ::unlink(e.backupPath.c_str());
    CloseIfOpen(&e.backupFd);
    CloseIfOpen(&e.fd);
    Observe("remove", i);
  }
  entries_.clear();
}

void AtomicOutputSet::LinkInto(const std::string &directory) {
  Sync();
  for (const Entry &e : entries_) {
    const std::string target =
        (std::filesystem::path(directory) / std::filesystem::path(e.finalPath).filename()).string();
    // The anonymous temporaries through /proc (AT_SYMLINK_FOLLOW), the named
    // ones by their name.
    const std::string &source = e.namedPath.empty() ? e.writePath : e.namedPath;
    if (::linkat(AT_FDCWD, source.c_str(), AT_FDCWD, target.c_str(), AT_SYMLINK_FOLLOW) != 0)
      throw IoError("cannot write " + e.finalPath + ": " + Reason());
  }
  Discard();  // the named temporaries' names go; the files live on in `directory`
  committed_ = true;
}

void AtomicOutputSet::Undo() {
  // Best effort, in reverse: what cannot be moved back stays under a
  // temporary name, stale once we end.
  for (size_t i = entries_.size(); i-- > 0;) {
    Entry &e = entries_[i];
    if (e.installed && ::rename(e.finalPath.c_str(), e.namedPath.c_str()) == 0) e.installed = false;
  }
  for (size_t i = entries_.size(); i-- > 0;) {
    Entry &e = entries_[i];
    if (!e.backupPath.empty() && !e.installed &&
        ::rename(e.backupPath.c_str(), e.finalPath.c_str()) == 0)
      e.backupPath.clear();
  }
}

void AtomicOutputSet::Discard() {
  for (Entry &e : entries_) {
    // An installed file is a final one (Undo could not move it back): kept.
    if (!e.namedPath.empty() && !e.installed) ::unlink(e.namedPath.c_str());
    CloseIfOpen(&e.backupFd);
    CloseIfOpen(&e.fd);
  }
  entries_.clear();
}

}  // namespace lutbake
