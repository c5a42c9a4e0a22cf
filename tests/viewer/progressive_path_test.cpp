// Voxel mode's solvers without a window: the path tracer's accumulation over frames (how many
// samples a frame adds, what restarts it, and that the mean is the one-pass render's), and sky
// visibility, through the same RendererVoxel the viewer's render thread runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "luxel/post/finish.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/voxel_gpu.h"
#include "progressive_path.h"
#include "renderer_voxel.h"
#include "support/gpu_test_context.h"
#include "voxel_solver.h"

namespace luxel::viewer {
namespace {

// A floor and a block under the default sun: sky, sunlit faces and a shadow.
voxel::VoxelWorld blockWorld() {
    auto world = voxel::VoxelWorld::create({16, 8, 16}, 8);
    EXPECT_TRUE(world.ok());
    voxel::addBox(*world, {0, 0, 0}, {16, 2, 16}, {90, 160, 70, 255});
    voxel::addBox(*world, {6, 2, 6}, {10, 6, 10}, {200, 120, 90, 255});
    return std::move(*world);
}

VoxelState pathState(int target) {
    VoxelState state;
    state.camera.position = {8, 7, -6};
    state.camera.pitchDegrees = -20;
    state.width = 24;
    state.height = 16;
    state.solver.kind = VoxelSolver::PathTrace;
    state.solver.path.samplesPerPixel = target;
    state.solver.path.maxBounces = 3;
    return state;
}

voxel::Camera cameraOf(const VoxelState& s) {
    const FlyCamera& c = s.camera;
    auto camera = voxel::Camera::create(c.position, c.yawDegrees, c.pitchDegrees, c.fovYDegrees,
                                        s.width, s.height);
    EXPECT_TRUE(camera.ok());
    return *camera;
}

// The picture the viewer shows of linear radiance (no bloom, the state's exposure).
Image displayed(const Image& radiance, const VoxelState& s) {
    post::PostOptions finishing = s.post;
    finishing.tone.exposureStops = s.exposure;
    return post::finish(radiance, finishing);
}

void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    ASSERT_EQ(a.size(), b.size());
    int different = 0;
    for (std::size_t i = 0; i < a.size(); ++i) different += a.data()[i] != b.data()[i];
    EXPECT_EQ(different, 0) << "of " << a.size() << " values";
}

// `got` within `relative` of `want` in summed absolute difference over the summed values.
void expectCloseImage(const Image& got, const Image& want, double relative) {
    ASSERT_EQ(got.size(), want.size());
    double difference = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < want.size(); ++i) {
        difference += std::abs(got.data()[i] - want.data()[i]);
        sum += want.data()[i];
    }
    EXPECT_GT(sum, 0.0);
    EXPECT_LT(difference, relative * sum);
}

const std::string* metadataOf(const Frame& frame, const char* key) {
    return findMetadata(frame.metadata, key);
}

TEST(VoxelSolverNames, AreTheCliNamesAndCycle) {
    for (const char* name : {"raycast", "ao", "path", "rc"}) {
        auto solver = parseVoxelSolver(name);
        ASSERT_TRUE(solver) << name;
        EXPECT_STREQ(voxelSolverName(*solver), name);
    }
    auto bad = parseVoxelSolver("hrc", "--solver");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message(),
              "--solver 'hrc' is not a voxel solver: raycast, ao, path or rc");
    EXPECT_EQ(nextVoxelSolver(VoxelSolver::RayCast), VoxelSolver::SkyVisibility);
    EXPECT_EQ(nextVoxelSolver(VoxelSolver::SkyVisibility), VoxelSolver::PathTrace);
    EXPECT_EQ(nextVoxelSolver(VoxelSolver::PathTrace), VoxelSolver::Cascades);
    EXPECT_EQ(nextVoxelSolver(VoxelSolver::Cascades), VoxelSolver::RayCast);
}

TEST(ProgressivePathSamples, OneAfterARestartThenWhatFitsTheBudget) {
    // Nothing measured yet: one sample, the quickest first picture.
    EXPECT_EQ(nextPathSamples(0, 100, 0, 0.0, 50.0), 1);
    // 10 ms a sample fits 5 in 50 ms; growth is at most twice the last count.
    EXPECT_EQ(nextPathSamples(10, 100, 4, 40.0, 50.0), 5);
    EXPECT_EQ(nextPathSamples(10, 100, 1, 1.0, 50.0), 2);
    // A sample slower than the budget still adds one.
    EXPECT_EQ(nextPathSamples(10, 100, 1, 200.0, 50.0), 1);
    // Never past the target; nothing once it is reached.
    EXPECT_EQ(nextPathSamples(98, 100, 64, 1.0, 50.0), 2);
    EXPECT_EQ(nextPathSamples(100, 100, 64, 1.0, 50.0), 0);
    EXPECT_EQ(nextPathSamples(120, 100, 64, 1.0, 50.0), 0);
    // A broken timing starts over at one.
    EXPECT_EQ(nextPathSamples(10, 100, 4, std::nan(""), 50.0), 1);
    EXPECT_EQ(nextPathSamples(10, 100, 4, 0.0, 50.0), 1);
}

TEST(ProgressivePath, StepsAddUpToTheOnePassRenderOfTheTarget) {
    const voxel::VoxelWorld world = blockWorld();
    const VoxelState s = pathState(7);
    const voxel::Camera camera = cameraOf(s);
    ProgressivePath progressive;
    EXPECT_FALSE(progressive.active());
    ASSERT_TRUE(progressive.restart(world, camera, s.shading, s.solver.path, nullptr, 7));
    int steps = 0, previous = 0;
    voxel::PathTraceImage last;
    while (!progressive.finished()) {
        auto image = progressive.step(steps % 2 == 0 ? 0.001 : 1000.0);  // uneven splits
        ASSERT_TRUE(image) << image.error().message();
        EXPECT_GT(image->samplesPerPixel, previous);
        EXPECT_EQ(image->samplesPerPixel - previous, progressive.lastAdded());
        previous = image->samplesPerPixel;
        last = std::move(*image);
        ASSERT_LT(++steps, 20);
    }
    EXPECT_GT(steps, 2);
    EXPECT_EQ(last.samplesPerPixel, 7);
    voxel::PathTraceOptions once = s.solver.path;
    once.samplesPerPixel = 7;
    auto reference = voxel::pathTrace(world, camera, s.shading, once);
    ASSERT_TRUE(reference);
    expectSameImage(last.radiance, reference->radiance);
    expectSameImage(last.standardError, reference->standardError);
    EXPECT_DOUBLE_EQ(last.relativeError, reference->relativeError);
    // Finished: a step only reads the mean back.
    auto again = progressive.step(50.0);
    ASSERT_TRUE(again);
    EXPECT_EQ(progressive.lastAdded(), 0);
    EXPECT_EQ(again->samplesPerPixel, 7);
    // A higher target goes on from there; clear() forgets everything.
    progressive.setTarget(9);
    EXPECT_FALSE(progressive.finished());
    auto more = progressive.step(1000.0);
    ASSERT_TRUE(more);
    EXPECT_EQ(more->samplesPerPixel, 9);
    progressive.clear();
    EXPECT_FALSE(progressive.active());
    EXPECT_EQ(progressive.samples(), 0);
}

// The block world uploaded by the ray caster on the shared GPU device, for path mode on it.
class ProgressivePathGpu : public testing::Test {
  protected:
    void SetUp() override {
        context = luxel::test::sharedGpuContext();
        if (!context) GTEST_SKIP() << "no Vulkan device";
        auto created = voxel::VoxelGpuRenderer::create(*context, world);
        ASSERT_TRUE(created) << created.error().message();
        uploaded.emplace(std::move(*created));
        gpu = {context, &*uploaded};
    }
    gpu::Context* context = nullptr;
    const voxel::VoxelWorld world = blockWorld();
    std::optional<voxel::VoxelGpuRenderer> uploaded;
    GpuWorld gpu;
};

TEST_F(ProgressivePathGpu, ANewViewSendsNoWorldAgain) {
    VoxelState s = pathState(4);
    ProgressivePath progressive;
    ASSERT_TRUE(progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 4, gpu));
    EXPECT_TRUE(progressive.onGpu());
    while (!progressive.finished()) ASSERT_TRUE(progressive.step(1000.0));
    const voxel::VoxelGpuUploads first = uploaded->uploads();
    // The camera moves: the view starts over with the same tracer, sending only its parameters.
    progressive.clear();
    EXPECT_FALSE(progressive.active());
    s.camera.position = {4, 6, -5};
    ASSERT_TRUE(progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 4, gpu));
    EXPECT_TRUE(progressive.onGpu());
    EXPECT_EQ(progressive.samples(), 0);
    voxel::PathTraceImage last;
    while (!progressive.finished()) {
        auto image = progressive.step(1000.0);
        ASSERT_TRUE(image) << image.error().message();
        last = std::move(*image);
    }
    const voxel::VoxelGpuUploads now = uploaded->uploads();
    EXPECT_EQ(now.world, first.world);
    EXPECT_EQ(now.textures, first.textures);
    EXPECT_EQ(now.materials, first.materials);
    EXPECT_GT(now.parameters, first.parameters);
    // The mean is a new GPU tracer's of the new view (to float precision: the passes split
    // differently).
    voxel::PathTraceOptions once = s.solver.path;
    once.samplesPerPixel = 4;
    auto reference = voxel::pathTraceGpu(*context, world, cameraOf(s), s.shading, once);
    ASSERT_TRUE(reference) << reference.error().message();
    ASSERT_EQ(last.samplesPerPixel, 4);
    for (std::size_t i = 0; i < last.radiance.size(); ++i) {
        const float a = last.radiance.data()[i], b = reference->radiance.data()[i];
        ASSERT_NEAR(a, b, 1e-5f * std::max(1.0f, std::abs(b))) << i;
    }
}

// Another solver shown: release() drops the GPU tracer (clear() keeps it for the next view), and
// the next restart creates a new one over the same upload.
TEST_F(ProgressivePathGpu, ReleaseDropsTheTracer) {
    VoxelState s = pathState(1);
    ProgressivePath progressive;
    ASSERT_TRUE(progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 1, gpu));
    ASSERT_TRUE(progressive.step(1000.0));
    progressive.clear();
    EXPECT_TRUE(progressive.holdsGpuTracer());
    progressive.release();
    EXPECT_FALSE(progressive.holdsGpuTracer());
    EXPECT_FALSE(progressive.active());
    const std::uint64_t worldBytes = uploaded->uploads().world;
    ASSERT_TRUE(progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 1, gpu));
    EXPECT_EQ(uploaded->uploads().world, worldBytes);
    EXPECT_TRUE(progressive.holdsGpuTracer());
    EXPECT_TRUE(progressive.onGpu());
    auto image = progressive.step(1000.0);
    ASSERT_TRUE(image) << image.error().message();
    EXPECT_EQ(image->samplesPerPixel, 1);
}

TEST(ProgressivePath, BadOptionsAndTargetsAreErrors) {
    const voxel::VoxelWorld world = blockWorld();
    VoxelState s = pathState(4);
    ProgressivePath progressive;
    EXPECT_FALSE(progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 0));
    s.shading.sunDirection = {0, 0, 0};
    auto status = progressive.restart(world, cameraOf(s), s.shading, s.solver.path, nullptr, 4);
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().message().find("sun"), std::string::npos) << status.error().message();
    EXPECT_FALSE(progressive.active());
}

TEST(RendererVoxelPath, AccumulatesUntilTheTargetAndRestartsOnChanges) {
    RendererVoxel renderer(blockWorld(), makeCpuVoxelFrameSource());
    VoxelState s = pathState(6);
    VoxelState copy = s;
    renderer.setState(std::move(copy));
    std::vector<Frame> frames;
    while (renderer.hasMoreWork()) {
        frames.push_back(renderer.step());
        ASSERT_TRUE(frames.back().note.empty()) << frames.back().note;
        ASSERT_LT(frames.size(), 20u);
    }
    ASSERT_GE(frames.size(), 2u);  // one sample first, then more a frame
    EXPECT_EQ(frames.front().samples, 1);
    EXPECT_FALSE(frames.front().accumulating);
    EXPECT_FALSE(frames.front().converged);
    for (std::size_t i = 1; i < frames.size(); ++i) {
        EXPECT_GT(frames[i].samples, frames[i - 1].samples);
        EXPECT_TRUE(frames[i].accumulating);
    }
    const Frame& done = frames.back();
    EXPECT_EQ(done.samples, 6);
    EXPECT_TRUE(done.converged);
    EXPECT_TRUE(std::isfinite(done.relativeError));
    ASSERT_NE(metadataOf(done, "luxel.solver"), nullptr);
    EXPECT_EQ(*metadataOf(done, "luxel.solver"), "path");
    ASSERT_NE(metadataOf(done, "luxel.samples"), nullptr);
    EXPECT_EQ(*metadataOf(done, "luxel.samples"), "6");
    // The picture is the one-pass render of 6 samples, tone mapped.
    voxel::PathTraceOptions once = s.solver.path;
    once.samplesPerPixel = 6;
    auto reference = voxel::pathTrace(blockWorld(), cameraOf(s), s.shading, once);
    ASSERT_TRUE(reference);
    expectSameImage(done.picture, displayed(reference->radiance, s));

    // Exposure and a higher target keep the samples.
    s.exposure = 1.0f;
    s.solver.path.samplesPerPixel = 8;
    s.restart = false;
    copy = s;
    renderer.setState(std::move(copy));
    ASSERT_TRUE(renderer.hasMoreWork());
    Frame kept = renderer.step();
    EXPECT_GT(kept.samples, 6);
    EXPECT_TRUE(kept.accumulating);

    // A moved camera starts again from one sample.
    s.camera.position.x += 1.0;
    s.restart = true;
    copy = s;
    renderer.setState(std::move(copy));
    Frame moved = renderer.step();
    EXPECT_EQ(moved.samples, 1);
    EXPECT_FALSE(moved.accumulating);
    while (renderer.hasMoreWork()) moved = renderer.step();
    EXPECT_EQ(moved.samples, 8);

    // So does an edit, even in a state that would keep the samples otherwise.
    VoxelEdit edit;
    edit.ray = {{8.5, 7.5, 8.5}, {0, -1, 0}};  // removes the block's top voxel
    s.edits = {edit};
    s.restart = false;
    copy = s;
    renderer.setState(std::move(copy));
    Frame edited = renderer.step();
    EXPECT_EQ(edited.samples, 1);
}

// On a GPU source the samples are traced on its device, over the world it uploaded: the frames
// name the device, and the picture is the CPU tracer's within its noise (the same random numbers;
// float paths that graze an edge may differ).
TEST(RendererVoxelPath, TracesOnTheGpuSourcesDevice) {
    const voxel::VoxelWorld world = blockWorld();
    auto source = makeGpuVoxelFrameSource("", /* hardwareOnly= */ false, world, {});
    if (!source) GTEST_SKIP() << "no Vulkan device: " << source.error().message();
    RendererVoxel renderer(blockWorld(), std::move(*source));
    const VoxelState s = pathState(6);
    VoxelState copy = s;
    renderer.setState(std::move(copy));
    Frame done;
    for (int frames = 0; renderer.hasMoreWork(); ++frames) {
        done = renderer.step();
        ASSERT_TRUE(done.note.empty()) << done.note;
        ASSERT_LT(frames, 20);
    }
    EXPECT_EQ(done.backend, "gpu");
    EXPECT_EQ(done.samples, 6);
    EXPECT_TRUE(done.converged);
    EXPECT_TRUE(std::isfinite(done.relativeError));
    voxel::PathTraceOptions once = s.solver.path;
    once.samplesPerPixel = 6;
    auto reference = voxel::pathTrace(world, cameraOf(s), s.shading, once);
    ASSERT_TRUE(reference);
    expectCloseImage(done.picture, displayed(reference->radiance, s), 0.02);
}

TEST(RendererVoxelSkyVisibility, IsTheLibraryRenderAndRendersOncePerView) {
    RendererVoxel renderer(blockWorld(), makeCpuVoxelFrameSource());
    VoxelState s = pathState(1);
    s.solver.kind = VoxelSolver::SkyVisibility;
    s.solver.ao.rays = 8;
    s.solver.ao.radius = 6.0;
    VoxelState copy = s;
    renderer.setState(std::move(copy));
    Frame frame = renderer.step();
    ASSERT_TRUE(frame.note.empty()) << frame.note;
    EXPECT_FALSE(renderer.hasMoreWork());
    EXPECT_TRUE(frame.converged);
    EXPECT_EQ(frame.samples, 0);
    ASSERT_NE(metadataOf(frame, "luxel.solver"), nullptr);
    EXPECT_EQ(*metadataOf(frame, "luxel.solver"), "ao");
    auto reference = voxel::renderSkyVisibility(blockWorld(), cameraOf(s), s.shading, s.solver.ao);
    ASSERT_TRUE(reference);
    expectSameImage(frame.picture, displayed(reference->radiance, s));
    // An exposure change shows the same light: no second render.
    s.exposure = -1.0f;
    s.restart = false;
    copy = s;
    renderer.setState(std::move(copy));
    frame = renderer.step();
    for (const PassTime& p : frame.passes) EXPECT_NE(p.name, "sky visibility");
    expectSameImage(frame.picture, displayed(reference->radiance, s));
    // The ray caster's frames say so too.
    s.solver.kind = VoxelSolver::RayCast;
    s.restart = true;
    copy = s;
    renderer.setState(std::move(copy));
    frame = renderer.step();
    ASSERT_NE(metadataOf(frame, "luxel.solver"), nullptr);
    EXPECT_EQ(*metadataOf(frame, "luxel.solver"), "raycast");
    EXPECT_FALSE(renderer.hasMoreWork());
}

// The block world's view in radiance cascades mode, posted to `renderer`.
VoxelState showCascades(RendererVoxel& renderer) {
    VoxelState s = pathState(1);
    s.solver.kind = VoxelSolver::Cascades;
    renderer.setState(VoxelState(s));
    return s;
}

// Radiance cascades in the viewer: one more reflection per frame, each frame the library's
// picture after as many passes; a camera move keeps the light, a new sun sets it anew.
TEST(RendererVoxelCascades, AddsAReflectionPerFrameAndKeepsTheLightWhenTheCameraMoves) {
    const voxel::VoxelWorld world = blockWorld();
    RendererVoxel renderer(blockWorld(), makeCpuVoxelFrameSource());
    VoxelState s = showCascades(renderer);
    auto library = voxel::RadianceCascades::create(world, nullptr, s.shading);
    ASSERT_TRUE(library.ok()) << library.error().message();
    for (int frameIndex = 1; frameIndex <= 3; ++frameIndex) {
        ASSERT_TRUE(renderer.hasMoreWork());
        const Frame frame = renderer.step();
        ASSERT_TRUE(frame.note.empty()) << frame.note;
        library->iterate();
        auto expected = library->render(cameraOf(s));
        ASSERT_TRUE(expected.ok());
        expectSameImage(frame.picture, displayed(*expected, s));
        ASSERT_NE(metadataOf(frame, "luxel.rc.bounces"), nullptr);
        EXPECT_EQ(*metadataOf(frame, "luxel.rc.bounces"), std::to_string(frameIndex));
        bool built = false;
        for (const PassTime& p : frame.passes) built |= p.name == "cascades build";
        EXPECT_EQ(built, frameIndex == 1);
    }
    // The camera moves: the light carries on (no new build, the fourth reflection).
    s.camera.position.x += 1.0;
    renderer.setState(VoxelState(s));
    Frame moved = renderer.step();
    EXPECT_EQ(*metadataOf(moved, "luxel.rc.bounces"), "4");
    library->iterate();
    expectSameImage(moved.picture, displayed(*library->render(cameraOf(s)), s));
    // The sun moves: new light, same cascades.
    s.shading.sunDirection = {0.5f, 0.8f, 0.1f};
    renderer.setState(VoxelState(s));
    Frame lit = renderer.step();
    bool relit = false;
    for (const PassTime& p : lit.passes) relit |= p.name == "cascades light";
    EXPECT_TRUE(relit);
    ASSERT_TRUE(library->setLight(s.shading).ok());
    library->iterate();
    expectSameImage(lit.picture, displayed(*library->render(cameraOf(s)), s));
    // Settled light needs no more frames.
    for (int i = 0; i < 200 && renderer.hasMoreWork(); ++i) renderer.step();
    EXPECT_FALSE(renderer.hasMoreWork());
}

// Samples per pixel (, and .) change the cascades' picture only: no build, no new light, the
// next reflection, and the library's picture with as many stratified rays a pixel.
TEST(RendererVoxelCascades, SamplesPerPixelRedrawThePictureAndKeepTheLight) {
    const voxel::VoxelWorld world = blockWorld();
    RendererVoxel renderer(blockWorld(), makeCpuVoxelFrameSource());
    VoxelState s = showCascades(renderer);
    const Frame first = renderer.step();
    ASSERT_TRUE(first.note.empty()) << first.note;
    s.shading.samplesPerPixel = 4;
    renderer.setState(VoxelState(s));
    const Frame sampled = renderer.step();
    for (const PassTime& p : sampled.passes) {
        EXPECT_NE(p.name, "cascades build");
        EXPECT_NE(p.name, "cascades light");
    }
    EXPECT_EQ(*metadataOf(sampled, "luxel.rc.bounces"), "2");
    voxel::ShadeOptions centres = s.shading;
    centres.samplesPerPixel = 1;
    auto library = voxel::RadianceCascades::create(world, nullptr, centres);
    ASSERT_TRUE(library.ok()) << library.error().message();
    library->iterate();
    library->iterate();
    const Image oneRay = displayed(*library->render(cameraOf(s)), s);
    library->setPictureSamples(4);
    expectSameImage(sampled.picture, displayed(*library->render(cameraOf(s)), s));
    int different = 0;
    for (std::size_t i = 0; i < oneRay.size(); ++i)
        different += oneRay.data()[i] != sampled.picture.data()[i];
    EXPECT_GT(different, 0);
}

// On a GPU source the cascades' pass and picture run on its device: the same reflections per
// frame and the library's CPU picture after as many passes, to float rounding (the GPU picture's
// parity, CascadesPictureGpu.*); settled light needs no more frames there either.
TEST(RendererVoxelCascades, RunOnTheGpuSourcesDevice) {
    const voxel::VoxelWorld world = blockWorld();
    auto source = makeGpuVoxelFrameSource("", /* hardwareOnly= */ false, world, {});
    if (!source) GTEST_SKIP() << "no Vulkan device: " << source.error().message();
    RendererVoxel renderer(blockWorld(), std::move(*source));
    VoxelState s = showCascades(renderer);
    auto library = voxel::RadianceCascades::create(world, nullptr, s.shading);
    ASSERT_TRUE(library.ok()) << library.error().message();
    for (int frameIndex = 1; frameIndex <= 3; ++frameIndex) {
        const Frame frame = renderer.step();
        ASSERT_TRUE(frame.note.empty()) << frame.note;
        EXPECT_EQ(frame.backend, "gpu");
        bool onGpu = false;
        for (const PassTime& p : frame.passes) onGpu |= p.name == "cascades picture (gpu)";
        EXPECT_TRUE(onGpu) << frameIndex;
        EXPECT_EQ(*metadataOf(frame, "luxel.rc.bounces"), std::to_string(frameIndex));
        library->iterate();
        auto expected = library->render(cameraOf(s));
        ASSERT_TRUE(expected.ok());
        SCOPED_TRACE(frameIndex);
        expectCloseImage(frame.picture, displayed(*expected, s), 1e-3);
    }
    for (int i = 0; i < 200 && renderer.hasMoreWork(); ++i) renderer.step();
    EXPECT_FALSE(renderer.hasMoreWork());
}

}  // namespace
}  // namespace luxel::viewer
