// The fuzz input as a file, for the readers that take a path: an anonymous
// in-memory file (memfd_create, nothing on disk, gone with the process),
// rewritten for every input and opened by its name /proc/self/fd/N.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace lutbake::fuzz {

class InputFile {
 public:
  InputFile() : fd_(memfd_create("lutbake-fuzz-input", MFD_CLOEXEC)) {
    if (fd_ < 0) std::abort();
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  InputFile(const InputFile &) = delete;
  InputFile &operator=(const InputFile &) = delete;

  // Replaces the file's contents with `data` and returns its path.
  const std::string &Hold(const uint8_t *data, size_t size) {
    if (ftruncate(fd_, 0) != 0) std::abort();
    for (size_t done = 0; done < size;) {
      const ssize_t n = pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
      if (n <= 0) std::abort();
      done += static_cast<size_t>(n);
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

}  // namespace lutbake::fuzz
