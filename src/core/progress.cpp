// Terminal progress bar with elapsed time and ETA.
#include "luxel/core/progress.h"

#include <unistd.h>

#include <cstdio>

namespace luxel {

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      enabled_(enabled && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

ProgressBar::~ProgressBar() {
    finish();
}

void ProgressBar::advance(std::uint64_t units) {
    const std::uint64_t done = done_.fetch_add(units, std::memory_order_relaxed) + units;
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - lastDraw_ < std::chrono::milliseconds(100) && done < total_) return;
    std::unique_lock lock(drawMutex_, std::try_to_lock);
    if (!lock.owns_lock() || finished_) return;
    lastDraw_ = now;
    draw(done);
}

void ProgressBar::draw(std::uint64_t done) {
    const double fraction = static_cast<double>(done) / static_cast<double>(total_);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\r%s [%s] %3.0f%%  %.1fs elapsed, ETA %.1fs ", label_.c_str(), bar,
                 fraction * 100.0, elapsed, eta);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    std::lock_guard lock(drawMutex_);
    if (finished_) return;
    finished_ = true;
    if (enabled_) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }
}

}  // namespace luxel
