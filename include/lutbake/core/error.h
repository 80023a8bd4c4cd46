// The errors the library throws. Every failure a caller can act on is a
// lutbake::Error: its message is the sentence the command line prints after
// "lutbake COMMAND: " (it names the input and what is accepted), and its
// kind says whose fault it was, which the command line maps to its exit
// status (2 for a request that cannot be done as asked, 1 for a failure
// while doing it, 128 + the signal for a cancelled run).
#pragma once

#include <stdexcept>
#include <string>

namespace lutbake {

class Error : public std::runtime_error {
 public:
  enum class Kind {
    kUsage,      // the request itself is wrong: an unknown name, a value out of range
    kRuntime,    // the request is right, the work failed: an unwritable directory, a bad file
    kCancelled,  // the caller's CancellationToken was cancelled
    // An input file cannot be read as what it was given as: missing,
    // unreadable, no image of a known format (check FILE --as, identify)
    kUnreadable,
  };
  Error(Kind kind, const std::string &message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const noexcept { return kind_; }

 private:
  Kind kind_;
};

// A request that cannot be done as asked (the command line's exit status 2).
class UsageError : public Error {
 public:
  explicit UsageError(const std::string &message) : Error(Kind::kUsage, message) {}
};

// A file could not be read or written: a runtime failure, not a bug (exit 1).
class IoError : public Error {
 public:
  explicit IoError(const std::string &message) : Error(Kind::kRuntime, message) {}
};

class UnreadableError : public Error {
 public:
  explicit UnreadableError(const std::string &message) : Error(Kind::kUnreadable, message) {}
};

}  // namespace lutbake
