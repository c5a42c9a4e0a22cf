// A fixed team of threads that run one body together and meet at barriers: for sweeps whose steps
// are too small for a parallel loop each (thousands of steps of microseconds), where the cost of
// starting a loop per step would exceed the step.
#pragma once

#include <atomic>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace luxel {

// A barrier that spins briefly before it sleeps. The HRC sweep meets thousands of times per solve
// (docs/performance.md, HRC): a member put to sleep in the kernel at each meeting took some 20 us
// to wake (std::barrier; 1024^2 on two threads, 296 ms a frame with it and 230 ms with this),
// while the others usually arrive within a few microseconds. Past the spin it sleeps.
class SpinBarrier {
  public:
    // A team larger than the hardware threads does not spin: a member spinning there could hold
    // the core the last one needs to arrive.
    explicit SpinBarrier(int size)
        : size_(size),
          spins_(static_cast<unsigned>(size) <= std::thread::hardware_concurrency() ? kSpins : 0) {}

    void arriveAndWait() {
        const unsigned phase = phase_.load(std::memory_order_acquire);
        if (arrived_.fetch_add(1, std::memory_order_acq_rel) == size_ - 1) {
            // The last to arrive: reset the count before the others may arrive at the next one.
            arrived_.store(0, std::memory_order_relaxed);
            phase_.store(phase + 1, std::memory_order_release);
            phase_.notify_all();
            return;
        }
        for (int spin = 0; spin < spins_; ++spin) {
            if (phase_.load(std::memory_order_acquire) != phase) return;
            pause();
        }
        while (phase_.load(std::memory_order_acquire) == phase) {
            phase_.wait(phase, std::memory_order_acquire);
        }
    }

  private:
    // About 50-100 us of pause instructions before sleeping.
    static constexpr int kSpins = 2000;

    static void pause() {
#if defined(__x86_64__) || defined(__i386__)
        _mm_pause();
#else
        std::this_thread::yield();
#endif
    }

    int size_, spins_;
    std::atomic<int> arrived_{0};
    std::atomic<unsigned> phase_{0};
};

class ThreadTeam {
  public:
    // Threads the parallel loops may use now: the hardware threads, capped by a ThreadLimit.
    static int defaultSize();

    // Runs body(index, team) on `size` threads at once, index 0 on the calling thread, and
    // returns when all have finished. The body must not throw.
    template <typename Body>
    static void run(int size, Body&& body) {
        ThreadTeam team(size < 1 ? 1 : size);
        std::vector<std::jthread> others;
        others.reserve(static_cast<std::size_t>(team.size_ - 1));
        for (int i = 1; i < team.size_; ++i) others.emplace_back([&, i] { body(i, team); });
        body(0, team);
    }

    int size() const { return size_; }

    // Every member waits here until all have arrived.
    void sync() {
        if (size_ > 1) barrier_.arriveAndWait();
    }

    // Rows [begin, end) of `rows` that member `index` owns.
    int bandBegin(int index, int rows) const {
        return static_cast<int>(static_cast<long long>(rows) * index / size_);
    }

  private:
    explicit ThreadTeam(int size) : size_(size), barrier_(size) {}

    int size_;
    SpinBarrier barrier_;
};

}  // namespace luxel
