// World edits and frames for voxel mode.
#include "renderer_voxel.h"

#include "luxel/core/timer.h"
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
    state.edits.clear();
    state_ = std::move(state);
    dirty_ = true;
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
    auto radiance = source_->render(world_, *camera, state_.shading, frame.passes);
    if (!radiance) {
        frame.note = radiance.error().message();
        return frame;
    }
    Stopwatch toneClock;
    frame.picture = toneMap(*radiance, {state_.exposure, ToneCurve::Aces});
    frame.passes.push_back({"tone map", toneClock.milliseconds()});
    frame.renderMilliseconds = total.milliseconds();
    return frame;
}

}  // namespace luxel::viewer
