#include "lutbake/formats/output_transaction.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>  // renameat2
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "blocking_calls.h"
#include "lutbake/core/error.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace fs = std::filesystem;

std::string PrepareOutputDirectory(const std::string &dir, bool *created, bool *usageError) {
  std::error_code ec;
  *created = false;
  *usageError = false;
  if (dir.empty()) {
    *usageError = true;
    return "is empty; accepted: a directory, created if missing";
  }
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) {
      *usageError = true;
      return "exists and is not a directory; accepted: a directory, created if missing";
    }
  } else {
    *created = fs::create_directories(dir, ec);
    if (ec) return "cannot create the directory: " + ec.message();
  }
  // Probe by creating a file, which also catches read-only file systems.
  // An anonymous one (O_TMPFILE) where the file system has them: the kernel
  // frees it however the process ends, so a kill never leaves a probe
  // behind. Elsewhere a named probe, removed at once; a probe left by a
  // killed run (its pid no longer exists) is removed here.
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
    for (const auto &entry : fs::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      const std::string prefix = ".lutbake-probe-";
      if (file.rfind(prefix, 0) != 0) continue;
      const long pid = std::strtol(file.c_str() + prefix.size(), nullptr, 10);
      if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
        fs::remove(entry.path(), ec);
    }
    const std::string probe =
        (fs::path(dir) / (".lutbake-probe-" + std::to_string(::getpid()))).string();
    fd = ::open(probe.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0600);
    if (fd >= 0) ::unlink(probe.c_str());
  }
  if (fd < 0) {
    const std::string reason = std::strerror(errno);
    if (*created) fs::remove(dir, ec);
    return "is not writable: " + reason;
  }
  ::close(fd);
  return {};
}

void RemoveCreatedDirectory(const std::string &dir, bool created) {
  if (!created) return;
  std::error_code ec;
  fs::remove(dir, ec);  // only succeeds if still empty
}

namespace {

std::atomic<unsigned long> siblingCounter{0};

bool PlainName(const std::string &name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

std::string SiblingPrefix(const fs::path &directory) {
  return "." + directory.filename().string() + ".lutbake-set-";
}

// The directory as an absolute path without "." or ".." or a trailing slash.
fs::path Canonical(const std::string &directory) {
  std::error_code ec;
  fs::path path = fs::weakly_canonical(fs::absolute(directory), ec);
  if (ec) path = fs::absolute(directory);
  if (path.filename().empty()) path = path.parent_path();
  return path;
}

bool SameInode(const fs::path &a, const fs::path &b) {
  struct stat sa, sb;
  return ::lstat(a.c_str(), &sa) == 0 && ::lstat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// Empties and removes a set sibling `sibling` of `directory`: what its own
// lutbake-set.json lists, and hard links to files `directory` holds too, are
// removed; anything else (a file made in the directory while the two were
// being exchanged) moves back into `directory` when its name is free there,
// and otherwise stays, with the sibling, for a person to see.
void RetireSibling(const fs::path &sibling, const fs::path &directory) {
  const std::vector<std::string> listed = ReadSetManifest(sibling.string());
  std::error_code ec;
  bool kept = false;
  std::vector<fs::path> entries, unlinked;
  for (const auto &entry : fs::directory_iterator(sibling, ec)) entries.push_back(entry.path());
  for (const fs::path &entry : entries) {
    const std::string name = entry.filename().string();
    // The list goes last: a retirement killed half-way leaves it beside
    // the files it names, for the next one.
    if (name == kSetManifestName) continue;
    const fs::path there = directory / name;
    const bool ours =
        std::find(listed.begin(), listed.end(), name) != listed.end() || IsTemporaryName(name);
    // Ours, a link to a file the directory holds, or a file the directory
    // now holds a newer one of.
    if (ours || SameInode(entry, there) || fs::exists(fs::symlink_status(there, ec))) {
      unlinked.push_back(entry);
    } else if (::renameat2(AT_FDCWD, entry.c_str(), AT_FDCWD, there.c_str(), RENAME_NOREPLACE) !=
               0) {
      kept = true;
    }
  }
  // All at once (blocking_calls.h: on a file system that discards freed
  // blocks, each unlink of a written file waits ~4 ms).
  RunBlockingCalls(unlinked.size(), [&](size_t k) { ::unlink(unlinked[k].c_str()); });
  ::unlink((sibling / kSetManifestName).c_str());
  if (!kept) ::rmdir(sibling.c_str());
}

// Siblings of `directory` that killed runs left: those whose lock (held by
// a living owner) can be taken.
void RetireStaleSiblings(const fs::path &directory) {
  const std::string prefix = SiblingPrefix(directory);
  const fs::path parent = directory.parent_path();
  // The names alone, compared before any path is made: the parent may be a
  // /tmp of thousands of entries, of which a sibling is rarely one.
  std::vector<fs::path> siblings;
  if (DIR *listing = ::opendir(parent.c_str())) {
    while (const dirent *entry = ::readdir(listing))
      if (std::strncmp(entry->d_name, prefix.c_str(), prefix.size()) == 0)
        siblings.push_back(parent / entry->d_name);
    ::closedir(listing);
  }
  for (const fs::path &sibling : siblings) {
    // O_DIRECTORY: a sibling is a directory; anything else of that name is not ours.
    const int fd = ::open(sibling.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) RetireSibling(sibling, directory);
    ::close(fd);
  }
}

}  // namespace

std::vector<std::string> ReadSetManifest(const std::string &directory) {
  const fs::path path = fs::path(directory) / kSetManifestName;
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec || bytes > (std::uintmax_t{16} << 20)) return {};
  std::vector<std::string> names;
  try {
    std::ifstream in(path, std::ios::binary);
    const nlohmann::json manifest = nlohmann::json::parse(in);
    for (const nlohmann::json &file : manifest.at("files"))
      if (file.is_string() && PlainName(file.get<std::string>()))
        names.push_back(file.get<std::string>());
  } catch (const std::exception &) {
    return {};  // not lutbake's: nothing in the directory counts as its set
  }
  return names;
}

OutputTransaction::OutputTransaction(const std::string &directory, const std::string &optionName,
                                     OutputMode mode, const std::string &description)
    : directory_(directory), mode_(mode), description_(description) {
  bool usageError = false;
  const std::string problem = PrepareOutputDirectory(directory_, &created_, &usageError);
  if (!problem.empty()) {
    const std::string message = optionName + " " + directory_ + ": " + problem;
    if (usageError) throw UsageError(message);
    throw IoError(message);
  }
  // What earlier runs killed here left: temporaries no live process owns.
  RemoveStaleTemporaries(directory_);
  if (mode_ == OutputMode::kSet) {
    RetireStaleSiblings(Canonical(directory_));
    previousSet_ = ReadSetManifest(directory_);
  }
}

OutputTransaction::~OutputTransaction() {
  if (!committed_) Discard();
}

std::string OutputTransaction::PathOf(const std::string &fileName) const {
  return (fs::path(directory_) / fileName).string();
}

std::string OutputTransaction::Write(const std::string &fileName,
                                     const std::function<void(const std::string &)> &write) {
  const std::string path = PathOf(fileName);
  output_.Write(path, write);
  files_.push_back(path);
  return path;
}

std::vector<std::string> OutputTransaction::WriteEach(
    const std::vector<std::pair<std::string, std::function<void(const std::string &)>>> &files) {
  std::vector<AtomicOutputSet::FileWrite> writes;
  std::vector<std::string> paths;
  for (const auto &[fileName, write] : files) {
    paths.push_back(PathOf(fileName));
    writes.push_back({paths.back(), write});
  }
  output_.WriteEach(writes);
  files_.insert(files_.end(), paths.begin(), paths.end());
  return paths;
}

std::string OutputTransaction::WriteText(const std::string &fileName, const std::string &text) {
  const std::string path = PathOf(fileName);
  return Write(fileName, [&](const std::string &temporary) {
    std::FILE *file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw IoError(path + ": cannot write: " + std::strerror(errno));
    const bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    if (std::fclose(file) != 0 || !ok)
      throw IoError(path + ": cannot write: " + std::strerror(errno));
  });
}

void OutputTransaction::Commit(const CancellationToken *cancellation) {
  // The last moment a cancellation stops the run; one that arrives during
  // the commit (milliseconds: renames) lets it finish.
  if (cancellation) cancellation->ThrowIfCancelled();
  if (mode_ == OutputMode::kSet) {
    CommitSet();
  } else {
    output_.Commit();
  }
  committed_ = true;
}

void OutputTransaction::CommitSet() {
  std::vector<std::string> newNames;
  for (const std::string &path : files_) newNames.push_back(fs::path(path).filename().string());
  nlohmann::ordered_json manifest;
  manifest["lutbakeSet"] = 1;
  manifest["lutbakeVersion"] = LutbakeVersion();
  manifest["commandLine"] = description_;
  manifest["files"] = newNames;
  const std::string manifestText = manifest.dump(2) + "\n";
  const auto isNew = [&](const std::string &n) {
    return n == kSetManifestName ||
           std::find(newNames.begin(), newNames.end(), n) != newNames.end();
  };
  // What the directory holds besides the new set: the previous set's other
  // files (to go) and everything else (to stay, untouched).
  std::vector<std::string> oldSetNames;
  bool anyEntry = false;
  std::error_code ec;
  for (const auto &entry : fs::directory_iterator(directory_, ec)) {
    const std::string name = entry.path().filename().string();
    if (IsTemporaryName(name) || name.rfind(".lutbake-probe-", 0) == 0) continue;
    anyEntry = true;
    if (isNew(name)) continue;
    if (std::find(previousSet_.begin(), previousSet_.end(), name) != previousSet_.end())
      oldSetNames.push_back(name);
    else
      foreign_.push_back(name);
  }
  std::sort(foreign_.begin(), foreign_.end());
  std::sort(oldSetNames.begin(), oldSetNames.end());
  removed_ = oldSetNames;
  // An empty directory cannot mix two sets: the files go in one by one.
  if (anyEntry && TryExchange(oldSetNames, manifestText)) return;
  WriteText(kSetManifestName, manifestText);
  output_.Commit();
  for (const std::string &name : oldSetNames) ::unlink((fs::path(directory_) / name).c_str());
}

bool OutputTransaction::TryExchange(const std::vector<std::string> &oldSetNames,
                                    const std::string &manifestText) {
  const fs::path directory = Canonical(directory_);
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const std::string relative = fs::relative(cwd, directory, ec).string();
  if (ec || relative == "." || relative.rfind("..", 0) != 0) return false;  // cwd inside
  for (const std::string &name : foreign_)
    if (fs::is_directory(fs::symlink_status(directory / name, ec))) return false;
  struct stat dirStat;
  if (::stat(directory.c_str(), &dirStat) != 0) return false;
  const fs::path sibling =
      directory.parent_path() / (SiblingPrefix(directory) + std::to_string(::getpid()) + "-" +
                                 std::to_string(siblingCounter.fetch_add(1)));
  if (::mkdir(sibling.c_str(), 0700) != 0) return false;  // a read-only parent, say
  const int lock = ::open(sibling.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock >= 0) ::flock(lock, LOCK_EX);
  const auto abandon = [&] {
    RetireSibling(sibling, directory);
    ::rmdir(sibling.c_str());
    if (lock >= 0) ::close(lock);
    return false;
  };
  // The sibling looks like the directory: its mode, and (as root) its owner.
  ::chmod(sibling.c_str(), dirStat.st_mode & 07777);
  if (::geteuid() == 0) (void)!::chown(sibling.c_str(), dirStat.st_uid, dirStat.st_gid);
  // The foreign files, as hard links (the same files, not copies).
  for (const std::string &name : foreign_)
    if (::linkat(AT_FDCWD, (directory / name).c_str(), AT_FDCWD, (sibling / name).c_str(), 0) != 0)
      return abandon();
  // The list first, durable (fsync'ed together with the set's files, before
  // any of them is linked): whatever a kill leaves in the sibling from here
  // on is named by it (RetireSibling).
  {
    std::FILE *file = std::fopen((sibling / kSetManifestName).c_str(), "wb");
    bool ok = file &&
              std::fwrite(manifestText.data(), 1, manifestText.size(), file) == manifestText.size();
    ok = ok && std::fflush(file) == 0;
    try {
      if (ok) output_.Sync(::fileno(file), (sibling / kSetManifestName).string());
    } catch (const IoError &) {
      ok = false;
    }
    if (file && std::fclose(file) != 0) ok = false;
    if (!ok) return abandon();
  }
  try {
    output_.LinkInto(sibling.string());
  } catch (const IoError &) {
    return abandon();
  }
  files_.push_back(PathOf(kSetManifestName));
  // From here the new set lives only in the sibling.
  const int siblingFd = ::open(sibling.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (siblingFd >= 0) {
    ::fsync(siblingFd);
    ::close(siblingFd);
  }
  if (::renameat2(AT_FDCWD, sibling.c_str(), AT_FDCWD, directory.c_str(), RENAME_EXCHANGE) != 0) {
    // No exchange here: install the new files one by one from the sibling.
    const std::vector<std::string> installed = ReadSetManifest(sibling.string());
    for (const std::string &name : installed)
      if (::rename((sibling / name).c_str(), (directory / name).c_str()) != 0)
        throw IoError("cannot write " + (fs::path(directory_) / name).string() + ": " +
                      std::strerror(errno));
    ::rename((sibling / kSetManifestName).c_str(), (directory / kSetManifestName).c_str());
    for (const std::string &name : oldSetNames) ::unlink((directory / name).c_str());
    abandon();
    return true;
  }
  const int parentFd = ::open(directory.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (parentFd >= 0) {
    ::fsync(parentFd);
    ::close(parentFd);
  }
  exchanged_ = true;
  // The sibling now holds the previous set and links to the foreign files.
  RetireSibling(sibling, directory);
  if (lock >= 0) ::close(lock);
  return true;
}

void OutputTransaction::Discard() {
  output_.Discard();
  RemoveCreatedDirectory(directory_, created_);
}

}  // namespace lutbake
