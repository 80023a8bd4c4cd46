// Blocking system calls on many files at once (fsync, unlink): each call
// mostly waits on the disk, and on a journalling file system those waits
// overlap when the calls are made together. Measured on the 2-core
// development machine (ext4 on a virtual disk, mounted with discard): 13
// fsyncs of a bake's files, 63 ms one after another, 3.6 ms from one
// thread each; 14 unlinks of written files, 4 ms each (the blocks are
// freed and discarded), 60 ms in a row, 3 to 30 ms together.
#pragma once

#include <cstddef>
#include <functional>

namespace lutbake {

// Calls call(k) for every k in [0, count), each exactly once, from up to
// kBlockingThreads threads (this one included) that take the next k in
// turn; returns when every call has returned. A thread that cannot be
// started leaves its calls to the others. `call` must not throw.
inline constexpr size_t kBlockingThreads = 16;
void RunBlockingCalls(size_t count, const std::function<void(size_t)> &call);

}  // namespace lutbake
