// Progress callbacks from Python during long solves. The solve runs with the GIL released; each
// report takes the GIL, calls the Python callable with the fraction done (0..1, increasing), and
// also lets Ctrl-C through. An exception from the callable (or a pending signal) cancels the
// solve: the report throws SolveCancelled, which unwinds the solver (tbb::parallel_for cancels the
// remaining rows and rethrows on the calling thread), and the Python exception is raised again
// once the GIL is back (rethrowIfFailed).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>

#include "bindings.h"

namespace luxel::python {

struct SolveCancelled {};

class ProgressRelay {
  public:
    // `callback` may be None (then only signals are checked). The work comes in `parts` (solves
    // of a bounce loop) of `total` units each.
    ProgressRelay(py::object callback, std::uint64_t total, int parts = 1);
    ~ProgressRelay();
    ProgressRelay(const ProgressRelay&) = delete;
    ProgressRelay& operator=(const ProgressRelay&) = delete;

    // From any thread, without the GIL: `units` more of the current part are done.
    void advance(std::uint64_t units = 1);
    // From the solving thread, without the GIL: part `part` (0-based) begins.
    void beginPart(int part);
    // With the GIL: reports 1.0 (the end) unless it was reported already or the solve failed.
    void finish();
    // With the GIL: raises the callback's exception (or KeyboardInterrupt) if there was one.
    void rethrowIfFailed();
    bool failed() const { return failed_.load(); }

  private:
    void report(double fraction);  // takes the GIL

    py::object callback_;
    std::uint64_t total_;
    int parts_;
    std::atomic<int> part_{0};
    std::atomic<std::uint64_t> done_{0};
    std::atomic<bool> failed_{false};
    std::mutex reportMutex_;  // one report at a time, so the fractions seen increase
    double lastReported_ = -1.0;
    std::optional<py::error_already_set> error_;
};

// Runs `solve` (returning a Result), turning a cancellation into an Error; the caller raises the
// Python exception with rethrowIfFailed() after taking the GIL back.
template <typename Solve>
auto runCancellable(Solve&& solve) -> decltype(solve()) {
    try {
        return solve();
    } catch (const SolveCancelled&) {
        return Error("cancelled");
    }
}

}  // namespace luxel::python
