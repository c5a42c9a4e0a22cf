// The render-thread side of the viewer without a window: the 2D renderer (GI toggle, caching,
// progressive reference), the render worker, and voxel edits.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "luxel/core/tonemap.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/voxel/voxel_world.h"
#include "progressive_reference.h"
#include "render_worker.h"
#include "renderer_2d.h"
#include "renderer_voxel.h"

namespace luxel::viewer {
namespace {

std::shared_ptr<const gi2d::Scene2D> lampScene() {
    auto scene = std::make_shared<gi2d::Scene2D>();
    scene->width = scene->height = 64;
    gi2d::Shape lamp{
        "lamp", gi2d::Circle{{20, 32}, 5}, {Rgb(1, 1, 1), Rgb(gi2d::kOpaqueAbsorption), 4}};
    scene->shapes.push_back(lamp);
    return scene;
}

State2D stateFor(gi2d::Solver2D solver, bool gi = true) {
    State2D s;
    s.scene = lampScene();
    s.sceneVersion = 1;
    s.view.solver = solver;
    s.view.backend = gpu::Backend::Cpu;
    s.view.gi = gi;
    s.view.width = s.view.height = 64;
    return s;
}

double meanOf(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return sum / static_cast<double>(image.size());
}

TEST(Renderer2D, GiToggleChangesThePictureAndTheWorkSettles) {
    Renderer2D renderer;
    renderer.setState(stateFor(gi2d::Solver2D::Hrc));
    ASSERT_TRUE(renderer.hasMoreWork());
    const Frame lit = renderer.step();
    EXPECT_FALSE(renderer.hasMoreWork());
    ASSERT_EQ(lit.picture.width(), 64);
    EXPECT_EQ(lit.backend, "cpu");
    EXPECT_TRUE(lit.note.empty()) << lit.note;
    renderer.setState(stateFor(gi2d::Solver2D::Hrc, /*gi=*/false));
    const Frame dark = renderer.step();
    // Away from the lamp only the fluence lights the picture.
    EXPECT_GT(lit.picture.at(45, 32, 0), 0.05f);
    EXPECT_LT(dark.picture.at(45, 32, 0), 1e-4f);
    EXPECT_GT(meanOf(lit.picture), 2 * meanOf(dark.picture));
}

// The panel's exact direct light re-solves: a small lamp's light is HRC's cascades' without it and
// the exact direct light's with it (docs/algorithms/holographic-radiance-cascades.md §12.5), so
// the pictures differ.
TEST(Renderer2D, DirectLightToggleResolves) {
    State2D state = stateFor(gi2d::Solver2D::Hrc);
    auto small = std::make_shared<gi2d::Scene2D>(*state.scene);
    std::get<gi2d::Circle>(small->shapes[0].geometry).radius = 1.5;
    state.scene = small;
    Renderer2D renderer;
    renderer.setState(State2D(state));
    const Frame exact = renderer.step();
    EXPECT_FALSE(renderer.hasMoreWork());
    state.view.exactDirectLight = false;
    renderer.setState(State2D(state));
    ASSERT_TRUE(renderer.hasMoreWork());
    const Frame cascades = renderer.step();
    double largest = 0;
    for (std::size_t i = 0; i < exact.picture.size(); ++i) {
        largest = std::max(largest, static_cast<double>(std::abs(exact.picture.data()[i] -
                                                                 cascades.picture.data()[i])));
    }
    EXPECT_GT(largest, 1e-3);
}

// In fog with albedo, each frame adds one bounce until the panel's count, then the work settles.
TEST(Renderer2D, BounceLightAddsOneBouncePerFrame) {
    State2D state = stateFor(gi2d::Solver2D::Hrc);
    auto fog = std::make_shared<gi2d::Scene2D>(*state.scene);
    fog->background.absorption = Rgb(0.05f);
    fog->background.albedo = Rgb(0.8f);
    state.scene = fog;
    state.view.bounces = 3;
    Renderer2D renderer;
    renderer.setState(std::move(state));
    const Frame first = renderer.step();
    double previous = meanOf(first.picture);
    for (int k = 1; k <= 3; ++k) {
        ASSERT_TRUE(renderer.hasMoreWork()) << "bounce " << k;
        const Frame frame = renderer.step();
        EXPECT_NE(frame.note.find("bounce " + std::to_string(k) + "/3"), std::string::npos)
            << frame.note;
        EXPECT_GT(meanOf(frame.picture), previous) << "bounce " << k;
        previous = meanOf(frame.picture);
    }
    EXPECT_FALSE(renderer.hasMoreWork());
}

// RC adds one jittered probe grid per frame to a running mean, which ends as solveRc's average
// of the same shifts; a change starts over.
TEST(Renderer2D, RcAveragesJitteredProbeGridsOverFrames) {
    State2D state = stateFor(gi2d::Solver2D::Rc);
    state.view.rcJitters = 4;
    const State2D again = state;
    Renderer2D renderer;
    renderer.setState(std::move(state));
    Frame frame;
    for (int k = 1; k <= 4; ++k) {
        frame = renderer.step();
        EXPECT_NE(frame.note.find("probe grids " + std::to_string(k) + "/4"), std::string::npos)
            << frame.note;
        EXPECT_EQ(renderer.hasMoreWork(), k < 4) << "frame " << k;
    }
    const gi2d::Medium2D medium = gi2d::rasterize(*again.scene, {64, 64, 4}).value();
    gi2d::RcOptions options;
    options.jitters = 4;
    const Image expected = gi2d::displayImage(medium, gi2d::solveRc(medium, options).value(),
                                              {again.view.exposure, ToneCurve::Aces});
    double worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        worst = std::max<double>(worst, std::abs(expected.data()[i] - frame.picture.data()[i]));
    }
    EXPECT_LT(worst, 1e-5);
    State2D changed = again;
    changed.view.exposure = 1.0f;  // display only: the mean is kept
    renderer.setState(std::move(changed));
    EXPECT_EQ(renderer.step().note.find("probe grids 1/"), std::string::npos);
    State2D edited = again;
    edited.sceneVersion = 2;  // an edit starts over
    renderer.setState(std::move(edited));
    EXPECT_NE(renderer.step().note.find("probe grids 1/4"), std::string::npos);
}

TEST(Renderer2D, ReferenceAccumulatesProgressively) {
    Renderer2D renderer;
    renderer.setState(stateFor(gi2d::Solver2D::Reference));
    const Frame first = renderer.step();
    EXPECT_FALSE(first.converged);
    EXPECT_EQ(first.samples, 4);
    EXPECT_TRUE(renderer.hasMoreWork());
    const Frame second = renderer.step();
    EXPECT_EQ(second.samples, 8);
    // An edited scene starts over; the same state again does not.
    renderer.setState(stateFor(gi2d::Solver2D::Reference));
    EXPECT_EQ(renderer.step().samples, 12);
    State2D edited = stateFor(gi2d::Solver2D::Reference);
    edited.sceneVersion = 2;
    renderer.setState(std::move(edited));
    EXPECT_EQ(renderer.step().samples, 4);
}

double relativeL1(const Image& a, const Image& b) {
    double diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) diff += std::fabs(a.data()[i] - b.data()[i]);
    return diff / (meanOf(b) * static_cast<double>(a.size()));
}

TEST(ProgressiveReference, PassesAreReferenceSolvesAndTheMeanConverges) {
    gi2d::Scene2D scene = *lampScene();
    auto medium = gi2d::rasterize(scene);
    ASSERT_TRUE(medium);
    ProgressiveReference progressive(8);
    ASSERT_TRUE(progressive.addPass(*medium));
    gi2d::ReferenceOptions options;
    options.rays = 8;
    options.seed = 1;
    auto firstPass = gi2d::solveReference(*medium, options);
    ASSERT_TRUE(firstPass);
    EXPECT_EQ(progressive.mean(), *firstPass);  // pass k: one solver run, seeded with k

    options.rays = 2048;
    auto truth = gi2d::solveReference(*medium, options);
    ASSERT_TRUE(truth);
    ASSERT_TRUE(progressive.addPass(*medium));
    const double early = relativeL1(progressive.mean(), *truth);
    while (progressive.passes() < 32) ASSERT_TRUE(progressive.addPass(*medium));
    const double late = relativeL1(progressive.mean(), *truth);
    EXPECT_EQ(progressive.raysPerPixel(), 256);
    EXPECT_LT(late, 0.5 * early) << "relative L1 against 2048 rays: 2 passes " << early
                                 << ", 32 passes " << late;
    progressive.reset();
    EXPECT_EQ(progressive.passes(), 0);
    EXPECT_TRUE(progressive.mean().empty());
}

// A renderer that counts its steps, for the worker.
struct CountingRenderer {
    using State = int;
    std::vector<int> seen;
    bool more = false;
    void setState(int&& s) {
        seen.push_back(s);
        more = true;
    }
    bool hasMoreWork() const { return more; }
    Frame step() {
        more = false;
        Frame f;
        f.samples = static_cast<int>(seen.size());
        return f;
    }
};

TEST(RenderWorker, HandsOverEveryStateInOrderAndReportsTheNewestGeneration) {
    auto renderer = std::make_unique<CountingRenderer>();
    CountingRenderer* r = renderer.get();
    RenderWorker<CountingRenderer> worker(std::move(renderer));
    for (int i = 1; i <= 5; ++i) worker.post(i, static_cast<std::uint64_t>(i));
    std::shared_ptr<const Frame> frame;
    for (int tries = 0; tries < 500; ++tries) {
        frame = worker.latest();
        if (frame && frame->generation == 5) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->generation, 5u);
    EXPECT_EQ(frame->samples, 5);  // all five states were set before the last step
    EXPECT_EQ(r->seen, (std::vector<int>{1, 2, 3, 4, 5}));
}

TEST(VoxelEdit, ClickRemovesTheHitVoxelAndShiftClickAddsOnItsFace) {
    auto world = voxel::VoxelWorld::create({8, 8, 8}, 4);
    ASSERT_TRUE(world);
    world->set(4, 2, 4, {100, 100, 100, 255});
    VoxelEdit edit;
    edit.ray = {{4.5, 7.5, 4.5}, {0, -1, 0}};  // straight down onto the voxel's top face
    edit.add = true;
    Int3 changed;
    ASSERT_TRUE(applyVoxelEdit(*world, edit, &changed));
    EXPECT_EQ(changed, (Int3{4, 3, 4}));
    EXPECT_TRUE(world->solid(4, 3, 4));
    edit.add = false;
    ASSERT_TRUE(applyVoxelEdit(*world, edit, &changed));  // removes the new top voxel
    EXPECT_EQ(changed, (Int3{4, 3, 4}));
    EXPECT_FALSE(world->solid(4, 3, 4));
    EXPECT_TRUE(world->solid(4, 2, 4));
    edit.ray = {{0.5, 7.5, 0.5}, {0, -1, 0}};  // misses everything
    EXPECT_FALSE(applyVoxelEdit(*world, edit));
}

}  // namespace
}  // namespace luxel::viewer
