// Octree frames: preview, then full resolution when full frames are slow.
#include "renderer_octree.h"

#include <algorithm>

#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"

namespace luxel::viewer {
namespace {

// Nearest-neighbour upscale, so previews have the internal size like every other frame.
Image upscale(const Image& small, int width, int height) {
    Image out(width, height, small.channels());
    for (int y = 0; y < height; ++y) {
        const int sy = std::min(y * small.height() / height, small.height() - 1);
        for (int x = 0; x < width; ++x) {
            const int sx = std::min(x * small.width() / width, small.width() - 1);
            out.setRgb(x, y, small.rgb(sx, sy));
        }
    }
    return out;
}

}  // namespace

RendererOctree::RendererOctree(std::shared_ptr<const octree::Octree> tree,
                               std::unique_ptr<OctreeFrameSource> source)
    : tree_(std::move(tree)), source_(std::move(source)) {}

void RendererOctree::setState(OctreeViewState&& state) {
    // Slowness depends on the mode: a surface frame says nothing about a volume one.
    if (state.render.mode != state_.render.mode ||
        state.render.scattering != state_.render.scattering) {
        lastFullMs_ = 0.0;
    }
    state_ = std::move(state);
    dirty_ = true;
    previewDue_ = lastFullMs_ > kOctreePreviewAboveMs;
}

Frame RendererOctree::render(int width, int height) {
    Stopwatch total;
    Frame frame;
    frame.backend = source_->backend();
    frame.device = source_->device();
    const OctreeViewState& s = state_;
    auto camera = voxel::Camera::create(s.position, s.yawDegrees, s.pitchDegrees, s.fovYDegrees,
                                        width, height);
    if (!camera) {
        frame.note = camera.error().message();
        return frame;
    }
    auto radiance = source_->render(*tree_, *camera, s.render, frame.passes);
    if (!radiance) {
        frame.note = radiance.error().message();
        return frame;
    }
    Stopwatch toneClock;
    frame.picture = toneMap(*radiance, {s.exposure, ToneCurve::Aces});
    frame.passes.push_back({"tone map", toneClock.milliseconds()});
    frame.renderMilliseconds = total.milliseconds();
    return frame;
}

Frame RendererOctree::step() {
    const int w = state_.width, h = state_.height;
    if (previewDue_) {
        previewDue_ = false;
        Frame frame =
            render(std::max(1, w / kOctreePreviewDivisor), std::max(1, h / kOctreePreviewDivisor));
        if (!frame.picture.empty()) frame.picture = upscale(frame.picture, w, h);
        frame.converged = false;
        return frame;  // dirty_ stays: the full frame follows
    }
    dirty_ = false;
    Frame frame = render(w, h);
    if (!frame.picture.empty()) lastFullMs_ = frame.renderMilliseconds;
    return frame;
}

}  // namespace luxel::viewer
