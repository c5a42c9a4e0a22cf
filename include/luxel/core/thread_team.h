// A fixed team of threads that run one body together and meet at barriers: for sweeps whose steps
// are too small for a parallel loop each (thousands of steps of microseconds), where the cost of
// starting a loop per step would exceed the step.
#pragma once

#include <barrier>
#include <thread>
#include <vector>

namespace luxel {

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
        if (size_ > 1) barrier_.arrive_and_wait();
    }

    // Rows [begin, end) of `rows` that member `index` owns.
    int bandBegin(int index, int rows) const {
        return static_cast<int>(static_cast<long long>(rows) * index / size_);
    }

  private:
    explicit ThreadTeam(int size) : size_(size), barrier_(size) {}

    int size_;
    std::barrier<> barrier_;
};

}  // namespace luxel
