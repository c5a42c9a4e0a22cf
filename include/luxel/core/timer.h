// Wall-clock stopwatch for timings printed by the tools.
#pragma once

#include <chrono>

namespace luxel {

class Stopwatch {
  public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    double milliseconds() const { return seconds() * 1e3; }

  private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace luxel
