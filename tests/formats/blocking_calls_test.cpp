// RunBlockingCalls: every call made exactly once, several of them in
// flight together, and all of them over when it returns.
#include "formats/blocking_calls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace lutbake {
namespace {

TEST(BlockingCalls, MakesEveryCallOnceAndReturnsWhenAllHaveReturned) {
  for (const size_t count : {size_t{0}, size_t{1}, size_t{2}, size_t{15}, size_t{100}}) {
    std::vector<std::atomic<int>> calls(count);
    std::atomic<size_t> finished{0};
    RunBlockingCalls(count, [&](size_t k) {
      ++calls[k];
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      ++finished;
    });
    EXPECT_EQ(finished.load(), count);
    for (size_t k = 0; k < count; ++k)
      EXPECT_EQ(calls[k].load(), 1) << "call " << k << " of " << count;
  }
}

TEST(BlockingCalls, CallsAreInFlightTogether) {
  // Each call waits (up to 10 s) until another is in flight beside it: made
  // one after another, none would see that.
  std::mutex mutex;
  std::condition_variable changed;
  int inFlight = 0, most = 0;
  RunBlockingCalls(8, [&](size_t) {
    std::unique_lock<std::mutex> lock(mutex);
    most = std::max(most, ++inFlight);
    changed.notify_all();
    changed.wait_for(lock, std::chrono::seconds(10), [&] { return inFlight >= 2 || most >= 2; });
    --inFlight;
  });
  EXPECT_GE(most, 2);
}

}  // namespace
}  // namespace lutbake
