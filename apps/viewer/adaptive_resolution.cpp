// Adaptive internal resolution: render time ~ pixels, so the scale that meets a target time t
// from a frame of time m at scale s is s * sqrt(t / m).
#include "adaptive_resolution.h"

#include <algorithm>
#include <cmath>

namespace luxel::viewer {
namespace {

constexpr double kAim = 0.8;          // aim below the target, leaving room for noise
constexpr double kGrowBelow = 0.6;    // grow when a frame takes less than this share of the target
constexpr double kShrinkAbove = 1.2;  // shrink when two frames in a row take more than this
constexpr double kMaxStep = 2.0;      // at most this factor in side length per change
constexpr double kCeilingSeconds = 10.0;

}  // namespace

AdaptiveResolution::AdaptiveResolution(ImageSize start, double targetMilliseconds)
    : current_(start), largest_(start), targetMs_(targetMilliseconds) {}

void AdaptiveResolution::setLargest(ImageSize largest) {
    if (largest.width < 1 || largest.height < 1) return;
    largest_ = largest;
}

double AdaptiveResolution::scaleOf(ImageSize size) const {
    return std::sqrt(static_cast<double>(size.width) * size.height /
                     (static_cast<double>(largest_.width) * largest_.height));
}

ImageSize AdaptiveResolution::sizeFor(double scale) const {
    const double shorter = std::min(largest_.width, largest_.height);
    const double smallest = std::min(1.0, kSmallestSide / shorter);
    scale = std::clamp(scale, smallest, 1.0);
    return {std::max(1, static_cast<int>(std::lround(largest_.width * scale))),
            std::max(1, static_cast<int>(std::lround(largest_.height * scale)))};
}

std::optional<ImageSize> AdaptiveResolution::frameRendered(ImageSize size, double milliseconds,
                                                           double seconds) {
    if (size != current_) return std::nullopt;
    if (!(milliseconds > 0.0) || !std::isfinite(milliseconds)) return std::nullopt;
    const double scale = scaleOf(size);
    double wanted = scale * std::sqrt(kAim * targetMs_ / milliseconds);
    wanted = std::clamp(wanted, scale / kMaxStep, scale * kMaxStep);
    if (milliseconds > kShrinkAbove * targetMs_) {
        if (++slowFrames_ < 2) return std::nullopt;
        ceilingScale_ = scale;
        ceilingUntil_ = seconds + kCeilingSeconds;
    } else {
        slowFrames_ = 0;
        // Grow only when clearly fast, or to follow a window that became smaller or larger.
        const bool fast = milliseconds < kGrowBelow * targetMs_;
        if (!fast) wanted = std::min(scale, 1.0);
        if (fast && seconds < ceilingUntil_) wanted = std::min(wanted, ceilingScale_ / 1.1);
        if (wanted <= scale && scale <= 1.0) return std::nullopt;
    }
    const ImageSize next = sizeFor(wanted);
    slowFrames_ = 0;
    if (next == current_) return std::nullopt;
    // Changes of under 10% in pixel count are not worth a new frame.
    const double ratio =
        static_cast<double>(next.width) * next.height / (double(current_.width) * current_.height);
    if (std::abs(ratio - 1.0) < 0.1 && scaleOf(current_) <= 1.0) return std::nullopt;
    current_ = next;
    return next;
}

}  // namespace luxel::viewer
