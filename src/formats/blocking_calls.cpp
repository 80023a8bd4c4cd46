#include "blocking_calls.h"

#include <atomic>
#include <system_error>
#include <thread>
#include <vector>

namespace lutbake {

void RunBlockingCalls(size_t count, const std::function<void(size_t)> &call) {
  std::atomic<size_t> next{0};
  const auto work = [&] {
    for (size_t k; (k = next.fetch_add(1)) < count;) call(k);
  };
  std::vector<std::thread> threads;
  // A thread only while calls are left for it (one that starts late would
  // find none).
  for (size_t t = 1; t < kBlockingThreads && t < count && next.load() + t < count; ++t) {
    try {
      threads.emplace_back(work);
    } catch (const std::system_error &) {
      break;
    }
  }
  work();
  for (std::thread &thread : threads) thread.join();
}

}  // namespace lutbake
