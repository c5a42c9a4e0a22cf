// World edits and frames for voxel mode.
#include "renderer_voxel.h"

#include "luxel/core/timer.h"
#include "luxel/post/finish.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/voxel/camera.h"

namespace luxel::viewer {

bool applyVoxelEdit(voxel::VoxelWorld& world, const VoxelEdit& edit, Int3* changed) {
    const voxel::Hit hit = voxel::castRay(world, edit.ray);
    if (!hit.hit) return false;
    Int3 target = hit.voxel;
    if (edit.add) {
        target = hit.voxel + hit.normal;
        if (!world.inside(target.x, target.y, target.z) ||
            world.solid(target.x, target.y, target.z))
            return false;
        world.set(target.x, target.y, target.z, edit.colour);
    } else {
        world.set(target.x, target.y, target.z, voxel::Voxel{});
    }
    if (changed) *changed = target;
    return true;
}

RendererVoxel::RendererVoxel(voxel::VoxelWorld world, std::unique_ptr<VoxelFrameSource> source)
    : world_(std::move(world)), source_(std::move(source)) {}

void RendererVoxel::setState(VoxelState&& state) {
    bool edited = false;
    for (const VoxelEdit& edit : state.edits) {
        Int3 v;
        if (applyVoxelEdit(world_, edit, &v)) {
            source_->worldEdited(world_, v, v + Int3{1, 1, 1});
            edited = true;
        }
    }
    // A voxel added to an empty brick makes the empty-space distances stale; the ray caster is
    // still exact without them but slower, so bring them up to date before the next frame.
    if (edited) world_.refreshEmptySpace();
    // History of an edited world or of other options would be clamped away slowly; start over.
    if (temporal_ &&
        (edited || !state.temporal || state.width != state_.width ||
         state.height != state_.height || state.post.internalScale != state_.post.internalScale)) {
        temporal_.reset();
    }
    state.edits.clear();
    state_ = std::move(state);
    dirty_ = true;
}

// Frames a still view keeps accumulating before the worker rests.
constexpr int kTemporalFrames = 32;

bool RendererVoxel::hasMoreWork() const {
    return dirty_ || (state_.temporal && temporal_ && temporal_->frames() < kTemporalFrames);
}

Frame RendererVoxel::step() {
    dirty_ = false;
    Stopwatch total;
    Frame frame;
    frame.backend = source_->backend();
    frame.device = source_->device();
    const FlyCamera& c = state_.camera;
    auto camera = voxel::Camera::create(c.position, c.yawDegrees, c.pitchDegrees, c.fovYDegrees,
                                        state_.width, state_.height);
    if (!camera) {
        frame.note = camera.error().message();
        return frame;
    }
    const post::PostOptions& p = state_.post;
    const bool scaled = p.internalScale < 1.0f;
    const voxel::Camera internal =
        scaled ? post::resizedCamera(*camera, post::internalSide(state_.width, p.internalScale),
                                     post::internalSide(state_.height, p.internalScale))
               : *camera;
    Result<Image> radiance = Error("");
    if (state_.temporal) {
        if (!temporal_) temporal_.emplace(state_.width, state_.height);
        const Vec2d jitter = temporal_->nextJitter();
        radiance = source_->renderJittered(world_, internal, state_.shading, jitter, frame.passes);
        if (radiance) {
            Stopwatch clock;
            const Image depth = post::primaryDepth(world_, internal, jitter);
            frame.passes.push_back({"depth", clock.milliseconds()});
            Stopwatch blend;
            radiance = temporal_->accumulate(*radiance, depth, post::viewOf(*camera), jitter);
            frame.passes.push_back({"temporal upscale", blend.milliseconds()});
        }
    } else {
        radiance = source_->render(world_, internal, state_.shading, frame.passes);
        if (radiance && scaled) {
            Stopwatch clock;
            radiance = post::upscale(*radiance, state_.width, state_.height, p.upscaler);
            frame.passes.push_back(
                {std::string("upscale ") + post::upscalerName(p.upscaler), clock.milliseconds()});
        }
    }
    if (!radiance) {
        frame.note = radiance.error().message();
        return frame;
    }
    if (p.sharpness > 0.0f) radiance = post::sharpen(*radiance, p.sharpness);
    Stopwatch toneClock;
    post::PostOptions finishing = p;
    finishing.tone.exposureStops = state_.exposure;
    frame.picture = post::finish(*radiance, finishing);
    frame.passes.push_back(
        {p.bloom.strength > 0 ? "bloom + tone map" : "tone map", toneClock.milliseconds()});
    frame.renderMilliseconds = total.milliseconds();
    return frame;
}

}  // namespace luxel::viewer
