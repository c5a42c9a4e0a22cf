// Running mean of reference-solver passes.
#include "progressive_reference.h"

#include "luxel/gi2d/reference_solver.h"

namespace luxel::viewer {

void ProgressiveReference::reset() {
    passes_ = 0;
    sum_ = Image();
}

Status ProgressiveReference::addPass(const gi2d::Medium2D& medium) {
    gi2d::ReferenceOptions options;
    options.rays = raysPerPass_;
    options.seed = static_cast<std::uint64_t>(passes_) + 1;
    auto pass = gi2d::solveReference(medium, options);
    if (!pass) return pass.error();
    if (sum_.width() != pass->width() || sum_.height() != pass->height()) {
        sum_ = Image(pass->width(), pass->height(), 3);
        passes_ = 0;
    }
    float* s = sum_.data();
    const float* p = pass->data();
    for (std::size_t i = 0; i < sum_.size(); ++i) s[i] += p[i];
    ++passes_;
    return Ok{};
}

Image ProgressiveReference::mean() const {
    if (passes_ == 0) return Image();
    Image m = sum_;
    const float scale = 1.0f / static_cast<float>(passes_);
    float* d = m.data();
    for (std::size_t i = 0; i < m.size(); ++i) d[i] *= scale;
    return m;
}

}  // namespace luxel::viewer
