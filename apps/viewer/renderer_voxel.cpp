// World edits and frames for voxel mode.
#include "renderer_voxel.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/core/parallel.h"
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
    // A voxel added to an empty brick makes the brick reach stale; the ray caster is still exact
    // without it but slower, so bring it up to date before the next frame.
    if (edited) world_.refreshEmptySpace();
    // History of an edited world or of other options would be clamped away slowly; start over.
    if (temporal_ &&
        (edited || !state.temporal || state.width != state_.width ||
         state.height != state_.height || state.post.internalScale != state_.post.internalScale)) {
        temporal_.reset();
    }
    // The path tracer's samples and the sky visibility image belong to one world and view.
    // The cascades belong to one world; new light keeps their irradiance as the next start.
    if (edited) {
        cascadesGpu_.reset();  // before the cascades it reads
        cascades_.reset();
        cascadesGpuRefusal_.clear();
    }
    // New light for the cascades: the sun and sky, and what passes glass (refraction, the
    // Fresnel model), which builds their faces under glass and segments again.
    const voxel::ShadeOptions &now = state.shading, &before = state_.shading;
    if (!(now.sunDirection.x == before.sunDirection.x &&
          now.sunDirection.y == before.sunDirection.y &&
          now.sunDirection.z == before.sunDirection.z &&
          now.sunIrradiance == before.sunIrradiance && now.skyTop == before.skyTop &&
          now.skyHorizon == before.skyHorizon && now.skyModel == before.skyModel &&
          now.skyTurbidity == before.skyTurbidity &&
          now.skyZenithLuminance == before.skyZenithLuminance &&
          now.sunAngularRadius == before.sunAngularRadius && now.refraction == before.refraction &&
          now.fresnel == before.fresnel)) {
        cascadesLight_ = true;
    }
    if (edited || state.restart || state.solver.kind != state_.solver.kind) {
        path_.clear();
        skyVisibility_.reset();
    } else {
        path_.setTarget(state.solver.path.samplesPerPixel);
    }
    // Path mode's sums (and its GPU tracer's) stay allocated no longer than it is shown.
    if (state.solver.kind != VoxelSolver::PathTrace) path_.release();
    state.edits.clear();
    state_ = std::move(state);
    dirty_ = true;
}

// Frames a still view keeps accumulating before the worker rests.
constexpr int kTemporalFrames = 32;

bool RendererVoxel::hasMoreWork() const {
    if (dirty_) return true;
    if (state_.solver.kind == VoxelSolver::PathTrace) return path_.active() && !path_.finished();
    if (state_.solver.kind == VoxelSolver::Cascades) {
        return !cascades_ || cascadesLight_ || cascadesChange_ >= voxel::CascadeOptions{}.tolerance;
    }
    return state_.solver.kind == VoxelSolver::RayCast && state_.temporal && temporal_ &&
           temporal_->frames() < kTemporalFrames;
}

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace

Result<Image> RendererVoxel::renderLight(const voxel::Camera& internal, Frame& frame) {
    const VoxelSolverOptions& solver = state_.solver;
    // Sky visibility runs on the CPU, whatever renders the ray caster's frames; the path tracer
    // and the cascades run on the GPU source's device.
    frame.backend = "cpu";
    frame.device = "CPU, " + std::to_string(hardwareThreads()) + " threads";
    setMetadata(frame.metadata, "luxel.solver", voxelSolverName(solver.kind));
    if (solver.kind == VoxelSolver::SkyVisibility) {
        setMetadata(frame.metadata, "luxel.ao.rays", std::to_string(solver.ao.rays));
        setMetadata(frame.metadata, "luxel.ao.radius", number(solver.ao.radius));
        setMetadata(frame.metadata, "luxel.seed", std::to_string(solver.ao.seed));
        if (!skyVisibility_) {
            Stopwatch clock;
            auto shaded = voxel::renderSkyVisibility(world_, internal, state_.shading, solver.ao,
                                                     &source_->textures());
            if (!shaded) return shaded.error();
            skyVisibility_ = std::move(shaded->radiance);
            frame.passes.push_back({"sky visibility", clock.milliseconds()});
        }
        return *skyVisibility_;
    }
    if (solver.kind == VoxelSolver::Cascades) return renderCascades(internal, frame);
    if (!path_.active()) {
        if (Status s =
                path_.restart(world_, internal, state_.shading, solver.path, &source_->textures(),
                              solver.path.samplesPerPixel, source_->gpuWorld());
            !s) {
            return s.error();
        }
    }
    if (path_.onGpu()) {
        frame.backend = source_->backend();
        frame.device = source_->device();
    }
    Stopwatch clock;
    auto traced = path_.step(kPathStepMilliseconds);
    if (!traced) return traced.error();
    frame.passes.push_back(
        {"path trace +" + std::to_string(path_.lastAdded()) + " spp", clock.milliseconds()});
    frame.samples = traced->samplesPerPixel;
    frame.converged = path_.finished();
    frame.accumulating = traced->samplesPerPixel > path_.lastAdded();
    frame.relativeError = traced->relativeError;
    setMetadata(frame.metadata, "luxel.samples", std::to_string(traced->samplesPerPixel));
    setMetadata(frame.metadata, "luxel.path.target", std::to_string(path_.target()));
    setMetadata(frame.metadata, "luxel.path.max_bounces", std::to_string(solver.path.maxBounces));
    setMetadata(frame.metadata, "luxel.seed", std::to_string(solver.path.seed));
    if (std::isfinite(traced->relativeError)) {
        setMetadata(frame.metadata, "luxel.path.relative_error", number(traced->relativeError));
    }
    return std::move(traced->radiance);
}

Result<Image> RendererVoxel::renderCascades(const voxel::Camera& internal, Frame& frame) {
    if (!cascades_) {
        cascadesGpu_.reset();  // it reads the cascades it was made from
        Stopwatch clock;
        auto built = voxel::RadianceCascades::create(world_, &source_->textures(), state_.shading);
        if (!built) return built.error();
        cascades_ = std::move(*built);
        cascadesLight_ = false;
        frame.passes.push_back({"cascades build", clock.milliseconds()});
    } else if (cascadesLight_) {
        Stopwatch clock;
        if (Status s = cascades_->setLight(state_.shading); !s) return s.error();
        // New glass materials recast the segments: the device's copy is then made anew.
        if (cascadesGpu_ && !cascadesGpu_->uploadLight()) cascadesGpu_.reset();
        cascadesLight_ = false;
        frame.passes.push_back({"cascades light", clock.milliseconds()});
    }
    // The samples per pixel (, and .) and the adaptive samples draw the picture only: the light
    // stays.
    cascades_->setPictureSamples(state_.shading.samplesPerPixel);
    cascades_->setPictureAdaptiveSamples(state_.shading.adaptiveSamples,
                                         state_.shading.adaptiveContrast);
    // On a GPU source the pass and the picture run on its device (radiance_cascades_gpu.h);
    // where the device cannot take them the CPU does, and the frame says why.
    const GpuWorld gpu = source_->gpuWorld();
    if (gpu.context && !cascadesGpu_ && cascadesGpuRefusal_.empty()) {
        auto made = voxel::RadianceCascadesGpu::create(*gpu.context, *cascades_);
        if (made) {
            cascadesGpu_.emplace(std::move(*made));
            // The picture reads the world the source's ray caster keeps on the device.
            if (gpu.renderer) cascadesGpu_->useUploadedWorld(*gpu.renderer);
        } else {
            cascadesGpuRefusal_ = made.error().message();
        }
    }
    Result<Image> image = Error("");
    if (cascadesGpu_) {
        Stopwatch pass;
        auto change = cascadesGpu_->iterateOnce();
        if (!change) return change.error();
        cascadesChange_ = *change;
        frame.passes.push_back({"cascades bounce (gpu)", pass.milliseconds()});
        Stopwatch picture;
        image = cascadesGpu_->render(internal);
        if (image) {
            frame.passes.push_back({"cascades picture (gpu)", picture.milliseconds()});
            frame.backend = source_->backend();
            frame.device = source_->device();
        } else {
            cascadesGpuRefusal_ = image.error().message();
            cascadesGpu_.reset();
        }
    } else {
        Stopwatch pass;
        cascadesChange_ = cascades_->iterate();
        frame.passes.push_back({"cascades bounce", pass.milliseconds()});
    }
    if (!cascadesGpu_) {
        // The CPU's picture, from the irradiance the device last handed back where it ran there.
        Stopwatch picture;
        image = cascades_->render(internal);
        if (!image) return image.error();
        frame.passes.push_back({"cascades picture", picture.milliseconds()});
        if (gpu.context) frame.note = "radiance cascades on the CPU: " + cascadesGpuRefusal_;
    }
    const voxel::CascadeStats stats = cascades_->stats();
    // An automatic spacing doubled for the runs through glass: which, and why.
    if (frame.note.empty()) frame.note = stats.spacingNote;
    frame.converged = cascadesChange_ < voxel::CascadeOptions{}.tolerance;
    setMetadata(frame.metadata, "luxel.rc.bounces", std::to_string(stats.bounces));
    setMetadata(frame.metadata, "luxel.rc.spacing", std::to_string(stats.spacing));
    return image;
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
    if (state_.solver.kind != VoxelSolver::RayCast) {
        temporal_.reset();  // jittered history is the ray caster's
        radiance = renderLight(internal, frame);
        if (radiance && scaled) {
            Stopwatch clock;
            radiance = post::upscale(*radiance, state_.width, state_.height, p.upscaler);
            frame.passes.push_back(
                {std::string("upscale ") + post::upscalerName(p.upscaler), clock.milliseconds()});
        }
    } else if (state_.temporal) {
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
        setMetadata(frame.metadata, "luxel.solver", voxelSolverName(VoxelSolver::RayCast));
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
