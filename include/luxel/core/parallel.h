// Parallel loops on oneTBB. Work is split by index ranges, never by thread identity, so results do
// not depend on the thread count as long as each index does its own deterministic work.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <memory>

namespace luxel {

// Caps the worker threads while alive (threads <= 0 means all hardware threads).
class ThreadLimit {
  public:
    explicit ThreadLimit(int threads);
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

  private:
    std::unique_ptr<tbb::global_control> control_;
};

int hardwareThreads();

// Calls body(begin, end) on disjoint chunks of [0, count); `grain` is the smallest chunk.
template <typename Body>
void parallelForRange(int count, int grain, Body&& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, count, grain > 0 ? grain : 1),
                      [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

}  // namespace luxel
