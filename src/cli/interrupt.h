// SIGINT and SIGTERM during a long command (bake): the handler only cancels
// a CancellationToken, which the library polls between texels; the command
// then unwinds, removes its temporaries and exits 128 + the signal (130,
// 143). A second signal of either kind ends the process at once (the
// handlers are reset to the default when the first arrives); even then no
// partial file can appear under a final name (atomic_output.h).
#pragma once

#include <string>

#include "lutbake/core/cancellation.h"

namespace lutbake::cli {

class InterruptGuard {
 public:
  // Installs the handlers; the destructor restores the previous ones.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard &) = delete;
  InterruptGuard &operator=(const InterruptGuard &) = delete;

  // Cancelled with the signal's number when one arrives.
  const CancellationToken &token() const;
};

// "SIGINT", "SIGTERM", or "signal N".
std::string SignalName(int signal);

// Makes a file size limit (ulimit -f) an error that write(2) returns
// (EFBIG), reported with the file's name, instead of a SIGXFSZ that kills
// the process without a word.
void IgnoreFileSizeSignal();

}  // namespace lutbake::cli
