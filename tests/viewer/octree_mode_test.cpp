// luxel-view's octree mode: the orbit/fly camera math, the controls that reach the renderer (with
// a recording frame source, and the real CPU renderer on a phantom), slow-frame previews, and an
// end-to-end run under Xvfb that drags, toggles the render mode and records frames.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/volume_generators.h"
#include "octree_camera.h"
#include "octree_controls.h"
#include "renderer_octree.h"
#include "viewer_xvfb.h"

namespace luxel::viewer {
namespace {

namespace fs = std::filesystem;

voxel::Camera cameraAt(Vec3d position, Vec3d target, int width = 64, int height = 48) {
    auto camera = voxel::Camera::lookAt(position, target, 45, width, height);
    EXPECT_TRUE(camera) << camera.error().message();
    return *camera;
}

void expectNear(Vec3d a, Vec3d b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(OctreeOrbitCamera, DragChangesYawAndKeepsTheDistanceToTheTarget) {
    const Vec3d target{16, 16, 16};
    OrbitFlyCamera camera(cameraAt({60, 40, -30}, target), target);
    ASSERT_TRUE(camera.orbiting());
    const double distance = length(Vec3d{60, 40, -30} - target);
    EXPECT_NEAR(camera.distance(), distance, 1e-9);
    expectNear(camera.position(), {60, 40, -30}, 1e-9);  // starting from the scene camera
    const double yaw = camera.yawDegrees(), pitch = camera.pitchDegrees();

    camera.orbitDrag(40, 0);
    EXPECT_GT(std::fabs(camera.yawDegrees() - yaw), 5.0);
    EXPECT_DOUBLE_EQ(camera.pitchDegrees(), pitch);  // a horizontal drag keeps the height
    EXPECT_NEAR(length(camera.position() - target), distance, 1e-9);
    EXPECT_NEAR(camera.position().y, 40, 1e-9);
    // Still aimed at the target: the view ray through the image centre passes through it.
    expectNear(normalize(target - camera.position()), camera.forward(), 1e-12);
    EXPECT_GT(length(camera.position() - Vec3d{60, 40, -30}), 5.0);  // the camera moved

    // A vertical drag changes pitch, the distance still holds, and pitch stops short of the pole.
    camera.orbitDrag(0, 10000);
    EXPECT_NEAR(camera.pitchDegrees(), -89.0, 1e-9);
    EXPECT_NEAR(length(camera.position() - target), distance, 1e-9);
    auto rendered = camera.camera(64, 48);
    ASSERT_TRUE(rendered) << rendered.error().message();
    expectNear(rendered->position(), camera.position(), 1e-12);

    // Dragging back horizontally restores the yaw: the rotation follows the drag, no drift.
    camera.orbitDrag(-40, 0);
    EXPECT_NEAR(camera.yawDegrees(), yaw, 1e-9);
}

TEST(OctreeOrbitCamera, WheelZoomsTowardsTheTargetAndFlyKeepsTheView) {
    const Vec3d target{16, 16, 16};
    OrbitFlyCamera camera(cameraAt({16, 16, -24}, target), target);
    camera.zoom(2);
    EXPECT_LT(camera.distance(), 40.0 * 0.8);
    EXPECT_GT(camera.distance(), 1.0);
    expectNear(camera.target(), target, 1e-12);
    const Vec3d orbitPosition = camera.position();
    // Fly keeps where the camera is and where it looks; moving and looking leave the target.
    camera.setOrbiting(false);
    expectNear(camera.position(), orbitPosition, 1e-12);
    camera.move({0, 0, 5});
    expectNear(camera.position(), orbitPosition + Vec3d{0, 0, 5}, 1e-12);
    camera.look(50, 0);
    expectNear(camera.position(), orbitPosition + Vec3d{0, 0, 5}, 1e-12);
    // Back to orbit: the target is ahead at the orbit distance, the camera does not jump.
    const Vec3d before = camera.position();
    camera.setOrbiting(true);
    expectNear(camera.position(), before, 1e-9);
    expectNear(camera.target(), before + camera.forward() * camera.distance(), 1e-9);
}

TEST(OctreeOrbitCamera, TargetIsTheLookAtPointOfACameraAimedAtTheVolume) {
    expectNear(orbitTarget(cameraAt({60, 40, -30}, {16, 16, 16}), {32, 32, 32}), {16, 16, 16},
               1e-9);
    // Aimed elsewhere: the point of the view ray nearest the centre.
    const voxel::Camera aside = cameraAt({0, 10, -20}, {0, 10, 0});
    expectNear(orbitTarget(aside, {32, 32, 32}), {0, 10, 16}, 1e-9);
}

// Records what reached it, and can be slow on demand.
class RecordingSource final : public OctreeFrameSource {
  public:
    std::string backend() const override { return "cpu"; }
    std::string device() const override { return "recording"; }
    bool hardwareGpu() const override { return false; }
    Result<Image> render(const octree::Octree&, const voxel::Camera& camera,
                         const octree::OctreeRenderOptions& options,
                         std::vector<PassTime>&) override {
        cameras.push_back(camera);
        received.push_back(options);
        if (sleepMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(sleepMs));
        return Image(camera.width(), camera.height(), 3);
    }
    std::vector<voxel::Camera> cameras;
    std::vector<octree::OctreeRenderOptions> received;
    int sleepMs = 0;
};

struct Rig {
    RecordingSource* source = nullptr;
    std::unique_ptr<RendererOctree> renderer;
    std::unique_ptr<OctreeControls> controls;

    Rig() {
        auto recording = std::make_unique<RecordingSource>();
        source = recording.get();
        renderer = std::make_unique<RendererOctree>(std::make_shared<const octree::Octree>(),
                                                    std::move(recording));
        octree::OctreeRenderOptions options;
        options.opacityScale = 0.5f;
        controls = std::make_unique<OctreeControls>(cameraAt({60, 40, -30}, {16, 16, 16}),
                                                    Int3{32, 32, 32}, options, 40, 30, 0.0f);
    }
    // What the renderer hands to the frame source for the controls' current state.
    const octree::OctreeRenderOptions& rendered() {
        renderer->setState(controls->state());
        const Frame frame = renderer->step();
        EXPECT_EQ(frame.picture.width(), 40);
        return source->received.back();
    }
};

TEST(OctreeModeControls, ModeTogglesAndTransferControlsReachTheRenderer) {
    Rig rig;
    OctreeControls& c = *rig.controls;
    EXPECT_TRUE(c.takeChanged());  // the first state is always posted
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Surface);
    c.apply(OctreeAction::CycleMode);
    EXPECT_TRUE(c.takeChanged());
    EXPECT_FALSE(c.takeChanged());
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Volume);
    c.apply(OctreeAction::CycleMode);
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Additive);
    c.apply(OctreeAction::CycleMode);
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Tiles);
    c.apply(OctreeAction::CycleMode);
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Surface);
    c.setMode(octree::OctreeMode::Volume);  // the panel's combo box
    EXPECT_EQ(rig.rendered().mode, octree::OctreeMode::Volume);

    c.apply(OctreeAction::OpacityUp);
    EXPECT_NEAR(rig.rendered().opacityScale, 0.5f * std::sqrt(2.0f), 1e-6f);
    c.setOpacityScale(0.01f);
    EXPECT_FLOAT_EQ(rig.rendered().opacityScale, 0.01f);
    c.setOpacityWindow(60, 200);
    EXPECT_EQ(rig.rendered().windowLow, 60);
    EXPECT_EQ(rig.rendered().windowHigh, 200);
    c.setOpacityWindow(230, 200);  // the low end dragged past the high end pushes it up
    EXPECT_EQ(rig.rendered().windowLow, 230);
    EXPECT_EQ(rig.rendered().windowHigh, 231);
    c.setOpacityWindow(230, 100);  // the high end dragged below the low end pushes it down
    EXPECT_EQ(rig.rendered().windowLow, 99);
    EXPECT_EQ(rig.rendered().windowHigh, 100);
    c.setOpacityWindow(0, 255);
    c.setThreshold(100);
    c.apply(OctreeAction::ThresholdUp);
    EXPECT_EQ(rig.rendered().threshold, 108);
    c.apply(OctreeAction::ToggleShadows);
    EXPECT_FALSE(rig.rendered().shadows);
    c.apply(OctreeAction::ToggleScattering);
    EXPECT_FALSE(rig.rendered().scattering);
    c.setScattering(true);
    c.setAlbedo(0.4f);
    c.setPhaseG(-0.5f);
    c.setSunRadius(3.0f);
    const octree::OctreeRenderOptions& o = rig.rendered();
    EXPECT_TRUE(o.scattering);
    EXPECT_FLOAT_EQ(o.albedo, 0.4f);
    EXPECT_FLOAT_EQ(o.phaseG, -0.5f);
    EXPECT_FLOAT_EQ(o.sunRadiusDegrees, 3.0f);
    EXPECT_GE(o.shadowSamples, 4);  // one sample would make the radius invisible
    c.setSun(90.0, 0.0);
    const Vec3 sun = rig.rendered().sunDirection;
    EXPECT_NEAR(sun.x, 1.0f, 1e-6f);
    EXPECT_NEAR(sun.y, 0.0f, 1e-6f);
    EXPECT_NEAR(sun.z, 0.0f, 1e-6f);
    c.apply(OctreeAction::SunElevationUp);
    EXPECT_NEAR(rig.rendered().sunDirection.y, std::sin(10.0 * 3.14159265358979 / 180), 1e-6);

    // Extremes are clamped to what the renderer accepts.
    c.setOpacityScale(1e9f);
    c.setThreshold(-5);
    c.setAlbedo(2.0f);
    c.setPhaseG(1.0f);
    c.setSunRadius(1000.0f);
    c.setOpacityScale(std::nanf(""));  // ignored
    const octree::OctreeRenderOptions& clamped = rig.rendered();
    EXPECT_FLOAT_EQ(clamped.opacityScale, kMaxOpacityScale);
    EXPECT_EQ(clamped.threshold, 1);
    EXPECT_FLOAT_EQ(clamped.albedo, 1.0f);
    EXPECT_LT(clamped.phaseG, 1.0f);
    EXPECT_TRUE(octree::validateRenderOptions(clamped)) << "clamped options must render";
}

TEST(OctreeModeControls, DragsAndTheCameraToggleReachTheRendererCamera) {
    Rig rig;
    OctreeControls& c = *rig.controls;
    rig.rendered();
    const voxel::Camera start = rig.source->cameras.back();
    c.drag(30, 0);  // orbit
    rig.rendered();
    const voxel::Camera orbited = rig.source->cameras.back();
    EXPECT_GT(length(orbited.position() - start.position()), 1.0);
    EXPECT_NEAR(length(orbited.position() - Vec3d{16, 16, 16}),
                length(start.position() - Vec3d{16, 16, 16}), 1e-9);
    c.apply(OctreeAction::ToggleCamera);  // fly: a drag looks around from where the camera is
    EXPECT_FALSE(c.camera().orbiting());
    c.drag(100, 0);  // 20 degrees of mouse look
    rig.rendered();
    const voxel::Camera looked = rig.source->cameras.back();
    expectNear(looked.position(), orbited.position(), 1e-9);
    EXPECT_NEAR(dot(looked.forward(), orbited.forward()), std::cos(20.0 * 3.14159265358979 / 180),
                0.02);
    c.travel(2, 0, 0);
    rig.rendered();
    expectNear(rig.source->cameras.back().position(), looked.position() + looked.forward() * 2.0,
               1e-9);
    c.apply(OctreeAction::ResetView);
    rig.rendered();
    expectNear(rig.source->cameras.back().position(), start.position(), 1e-9);
}

TEST(RendererOctree, SlowFramesArePreviewedThenRefined) {
    Rig rig;
    rig.source->sleepMs = static_cast<int>(kOctreePreviewAboveMs) + 30;
    rig.renderer->setState(rig.controls->state());
    const Frame first = rig.renderer->step();  // nothing timed yet: straight to full size
    EXPECT_TRUE(first.converged);
    EXPECT_FALSE(rig.renderer->hasMoreWork());
    rig.source->sleepMs = 0;
    rig.controls->drag(10, 0);
    rig.renderer->setState(rig.controls->state());
    const Frame preview = rig.renderer->step();
    EXPECT_FALSE(preview.converged);
    EXPECT_EQ(rig.source->cameras.back().width(), 40 / kOctreePreviewDivisor);
    EXPECT_EQ(preview.picture.width(), 40);  // shown at the internal size
    ASSERT_TRUE(rig.renderer->hasMoreWork());
    const Frame full = rig.renderer->step();
    EXPECT_TRUE(full.converged);
    EXPECT_EQ(rig.source->cameras.back().width(), 40);
    EXPECT_FALSE(rig.renderer->hasMoreWork());
    // Fast frames (the last one was) are never previewed.
    rig.renderer->setState(rig.controls->state());
    rig.renderer->step();
    EXPECT_EQ(rig.source->cameras.back().width(), 40);
    EXPECT_FALSE(rig.renderer->hasMoreWork());
}

double meanOf(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return sum / static_cast<double>(image.size());
}

TEST(RendererOctree, CpuSourceRendersThePhantomAndModesDiffer) {
    auto volume = octree::makePhantom(32);
    ASSERT_TRUE(volume) << volume.error().message();
    auto tree = octree::buildOctree(*volume);
    ASSERT_TRUE(tree) << tree.error().message();
    RendererOctree renderer(std::make_shared<const octree::Octree>(std::move(*tree)),
                            makeCpuOctreeFrameSource());
    octree::OctreeRenderOptions options;
    options.opacityScale = 0.3f;
    OctreeControls controls(cameraAt({60, 40, -30}, {16, 16, 16}), {32, 32, 32}, options, 48, 36,
                            0.0f);
    renderer.setState(controls.state());
    const Frame surface = renderer.step();
    ASSERT_TRUE(surface.note.empty()) << surface.note;
    ASSERT_EQ(surface.picture.width(), 48);
    controls.apply(OctreeAction::CycleMode);
    renderer.setState(controls.state());
    const Frame volumeFrame = renderer.step();
    ASSERT_TRUE(volumeFrame.note.empty()) << volumeFrame.note;
    double diff = 0;
    for (std::size_t i = 0; i < surface.picture.size(); ++i) {
        diff += std::fabs(surface.picture.data()[i] - volumeFrame.picture.data()[i]);
    }
    EXPECT_GT(diff / static_cast<double>(surface.picture.size()), 0.01);
    EXPECT_GT(meanOf(surface.picture), 0.05);
    EXPECT_EQ(surface.backend, "cpu");
    EXPECT_FALSE(surface.passes.empty());
}

// A 32^3 voxel terrain with a white sphere, as an octree seen from above a corner.
const char* kOctreeScene = R"({
  "type": "octree",
  "octree": {"source": "world", "world": {"source": "terrain", "size": [32, 32, 32], "seed": 3,
             "height": 0.35, "amplitude": 0.3, "frequency": 0.06, "water": 0.25,
             "shapes": [{"type": "sphere", "center": [16, 20, 16], "radius": 5,
                         "color": [230, 230, 240]}]}},
  "camera": {"position": [56, 44, -22], "look_at": [16, 12, 16], "fov": 50, "size": [320, 240]},
  "render": {"mode": "surface", "sun_direction": [0.4, 1.0, 0.3], "opacity_scale": 0.3}
})";

// Screenshots: the first three rendered frames are recorded too.
const char* kOctreeScript =
    "wait_converged\n"
    "screenshot surface.png\n"
    "mouse_down 160 120\n"
    "mouse_move 200 120\n"
    "wait_frames 2\n"
    "mouse_move 240 120\n"
    "mouse_up 240 120\n"
    "wait_converged\n"
    "screenshot orbit.png\n"
    "key V\n"
    "wait_converged\n"
    "screenshot volume.png\n"
    "key V\n"
    "wait_converged\n"
    "screenshot additive.png\n"
    "wheel 3\n"
    "wait_converged\n"
    "screenshot zoom.png\n"
    "quit\n";

using OctreeViewXvfb = test::ViewerXvfb;

TEST_F(OctreeViewXvfb, DragOrbitsAndVTogglesSurfaceVolumeAdditive) {
    const std::string scene = write("world32.json", kOctreeScene);
    write("octree.txt", kOctreeScript);
    const test::RunResult r =
        view(scene +
             " --size 320x240 --internal-size 160x120 --backend cpu --record 3 "
             "--record-dir rec --script octree.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("octree mode, 160x120 internal, backend cpu"), std::string::npos)
        << r.output;
    const Image surface = png("surface.png"), orbit = png("orbit.png"), volume = png("volume.png"),
                additive = png("additive.png"), zoom = png("zoom.png");
    ASSERT_EQ(surface.width(), 160);
    ASSERT_EQ(surface.height(), 120);
    // Not blank: the lit terrain block against the sky, with structure.
    EXPECT_GT(test::stddev(surface), 0.05);
    EXPECT_GT(test::stddev(volume), 0.02);
    EXPECT_GT(test::stddev(additive), 0.05);
    // The block fills the middle; the top corners are sky.
    const double sky = test::regionMean(surface, 5, 5, 4);
    EXPECT_GT(sky, 0.5);
    EXPECT_GT(std::fabs(test::regionMean(surface, 80, 70, 10) - sky), 0.1);
    // Each step changes the picture: the drag turned the view, V the render mode, the wheel zoomed.
    EXPECT_GT(test::meanAbsDiff(surface, orbit), 0.01);
    EXPECT_GT(test::meanAbsDiff(orbit, volume), 0.01);
    EXPECT_GT(test::meanAbsDiff(volume, additive), 0.01);
    EXPECT_GT(test::meanAbsDiff(additive, zoom), 0.01);
    // Additive has no background: the corners go black.
    EXPECT_LT(test::regionMean(additive, 5, 5, 4), 0.05);
    // Zooming in brings the block closer: less of the black background is left.
    auto darkPixels = [](const Image& image) {
        int dark = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const Rgb c = image.rgb(x, y);
                if (c.r + c.g + c.b < 0.05f) ++dark;
            }
        }
        return dark;
    };
    EXPECT_LT(darkPixels(zoom), darkPixels(additive));
    // --record 3 wrote the first rendered frames.
    EXPECT_TRUE(fs::exists(path("rec/frame_00002.png")));
    EXPECT_EQ(png("rec/frame_00000.png").width(), 160);
}

TEST_F(OctreeViewXvfb, BadOctreeSceneIsOneClearLine) {
    const std::string scene =
        write("bad.json", R"({"type": "octree", "octree": {"source": "phantom", "size": 3}})");
    const test::RunResult r = view(scene);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
}

TEST_F(OctreeViewXvfb, GpuBackendMatchesTheCpuPicture) {
    auto devices = gpu::listDevices();
    if (!devices || devices->empty()) GTEST_SKIP() << "no Vulkan device";
    const std::string scene = write("world32.json", kOctreeScene);
    write("shot.txt",
          "wait_converged\nscreenshot shot.png\nkey V\nwait_converged\n"
          "screenshot volume.png\nquit\n");
    const std::string args = " --size 320x240 --internal-size 160x120 --script shot.txt";
    test::RunResult r = view(scene + args + " --backend gpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend gpu"), std::string::npos) << r.output;
    fs::rename(path("shot.png"), path("gpu.png"));
    fs::rename(path("volume.png"), path("gpu-volume.png"));
    r = view(scene + args + " --backend cpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The same kernel in float on the GPU, in double on the CPU.
    EXPECT_LT(test::meanAbsDiff(png("gpu.png"), png("shot.png")), 0.01);
    EXPECT_LT(test::meanAbsDiff(png("gpu-volume.png"), png("volume.png")), 0.01);
}

}  // namespace
}  // namespace luxel::viewer
