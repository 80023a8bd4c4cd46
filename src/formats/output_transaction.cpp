#include "lutbake/formats/output_transaction.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "lutbake/core/error.h"

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

OutputTransaction::OutputTransaction(const std::string &directory, const std::string &optionName)
    : directory_(directory) {
  bool usageError = false;
  const std::string problem = PrepareOutputDirectory(directory_, &created_, &usageError);
  if (!problem.empty()) {
    const std::string message = optionName + " " + directory_ + ": " + problem;
    if (usageError) throw UsageError(message);
    throw IoError(message);
  }
  // What earlier runs killed here left: temporaries no live process owns.
  RemoveStaleTemporaries(directory_);
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
  output_.Commit();
  committed_ = true;
}

void OutputTransaction::Discard() {
  output_.Discard();
  RemoveCreatedDirectory(directory_, created_);
}

}  // namespace lutbake
