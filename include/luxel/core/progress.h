// A progress bar with ETA on stderr, drawn only when stderr is a terminal. Thread-safe: workers
// call advance(); redraws are throttled.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace luxel {

class ProgressBar {
  public:
    // `total` units of work. enabled = false (or stderr not a terminal) draws nothing.
    ProgressBar(std::string label, std::uint64_t total, bool enabled = true);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void advance(std::uint64_t units = 1);
    // Clears the bar line.
    void finish();

  private:
    void draw(std::uint64_t done);

    std::string label_;
    std::uint64_t total_;
    bool enabled_;
    std::atomic<std::uint64_t> done_{0};
    std::chrono::steady_clock::time_point start_, lastDraw_;
    std::mutex drawMutex_;
    bool finished_ = false;
};

}  // namespace luxel
