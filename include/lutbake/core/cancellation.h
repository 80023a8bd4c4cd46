// Cooperative cancellation of long work (a bake). The owner of the work keeps
// a CancellationToken and hands the library a pointer to it; the library
// polls it between units of work (texels) and, once it is set, stops by
// throwing Cancelled. Nothing is killed mid-texel, so whatever the caller
// holds (temporary files, AtomicOutputSet) is released by ordinary unwinding.
#pragma once

#include <atomic>

#include "lutbake/core/error.h"

namespace lutbake {

// Thrown by work that found its token cancelled; carries the token's reason.
class Cancelled : public Error {
 public:
  explicit Cancelled(int reason) : Error(Kind::kCancelled, "cancelled"), reason_(reason) {}
  int reason() const noexcept { return reason_; }

 private:
  int reason_;
};

class CancellationToken {
 public:
  // Async-signal-safe: one store to a lock-free atomic, so a signal handler
  // may call it. `reason` must be non-zero (the CLI passes the signal number).
  void Cancel(int reason) noexcept { reason_.store(reason, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return reason_.load(std::memory_order_relaxed) != 0; }
  // 0 while not cancelled.
  int reason() const noexcept { return reason_.load(std::memory_order_relaxed); }
  void ThrowIfCancelled() const {
    if (const int r = reason()) throw Cancelled(r);
  }

 private:
  // A signal handler may only touch lock-free atomics.
  static_assert(std::atomic<int>::is_always_lock_free);
  std::atomic<int> reason_{0};
};

}  // namespace lutbake
