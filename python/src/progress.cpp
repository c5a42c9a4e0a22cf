// Progress callbacks and cancellation (progress.h).
#include "progress.h"

#include <algorithm>

namespace luxel::python {

ProgressRelay::ProgressRelay(py::object callback, std::uint64_t total, int parts)
    : callback_(std::move(callback)),
      total_(std::max<std::uint64_t>(total, 1)),
      parts_(std::max(parts, 1)) {
    if (!callback_.is_none() && !PyCallable_Check(callback_.ptr())) {
        throw py::type_error("progress must be callable (it is called with the fraction done)");
    }
}

ProgressRelay::~ProgressRelay() {
    // The stored Python objects are released with the GIL held (the relay lives in a binding
    // function, which holds it when it returns or unwinds).
    error_.reset();
}

void ProgressRelay::beginPart(int part) {
    if (failed_) throw SolveCancelled{};
    part_ = std::min(part, parts_ - 1);
    done_ = 0;
}

void ProgressRelay::advance(std::uint64_t units) {
    if (failed_) throw SolveCancelled{};
    const std::uint64_t done = std::min(done_ += units, total_);
    const double fraction =
        (part_.load() + static_cast<double>(done) / static_cast<double>(total_)) / parts_;
    report(fraction);
}

void ProgressRelay::report(double fraction) {
    std::lock_guard<std::mutex> lock(reportMutex_);
    // Calls into Python at most every 0.5% (and at the end), so a large solve is not slowed by
    // taking the GIL for every row.
    if (fraction < 1.0 && fraction - lastReported_ < 0.005) return;
    py::gil_scoped_acquire gil;
    if (failed_) throw SolveCancelled{};
    if (PyErr_CheckSignals() != 0) {  // Ctrl-C: KeyboardInterrupt is pending
        error_.emplace();
        failed_ = true;
        throw SolveCancelled{};
    }
    if (fraction <= lastReported_) return;
    lastReported_ = fraction;
    if (callback_.is_none()) return;
    try {
        callback_(fraction);
    } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
        failed_ = true;
        throw SolveCancelled{};
    }
}

void ProgressRelay::finish() {
    if (failed_ || lastReported_ >= 1.0 || callback_.is_none()) return;
    lastReported_ = 1.0;
    callback_(1.0);
}

void ProgressRelay::rethrowIfFailed() {
    if (!error_) return;
    py::error_already_set error = std::move(*error_);
    error_.reset();
    throw error;
}

}  // namespace luxel::python
