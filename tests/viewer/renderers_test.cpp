// The render-thread side of the viewer without a window: the 2D renderer (GI toggle, caching,
// progressive reference), the render worker, and voxel edits.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "luxel/gi2d/rasterize.h"
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

State2D stateFor(Solver2D solver, bool gi = true) {
    State2D s;
    s.scene = lampScene();
    s.sceneVersion = 1;
    s.view.solver = solver;
    s.view.backend = "cpu";
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
    renderer.setState(stateFor(Solver2D::Hrc));
    ASSERT_TRUE(renderer.hasMoreWork());
    const Frame lit = renderer.step();
    EXPECT_FALSE(renderer.hasMoreWork());
    ASSERT_EQ(lit.picture.width(), 64);
    EXPECT_EQ(lit.backend, "cpu");
    EXPECT_TRUE(lit.note.empty()) << lit.note;
    renderer.setState(stateFor(Solver2D::Hrc, /*gi=*/false));
    const Frame dark = renderer.step();
    // Away from the lamp only the fluence lights the picture.
    EXPECT_GT(lit.picture.at(45, 32, 0), 0.05f);
    EXPECT_LT(dark.picture.at(45, 32, 0), 1e-4f);
    EXPECT_GT(meanOf(lit.picture), 2 * meanOf(dark.picture));
}

TEST(Renderer2D, ReferenceAccumulatesProgressively) {
    Renderer2D renderer;
    renderer.setState(stateFor(Solver2D::Reference));
    const Frame first = renderer.step();
    EXPECT_FALSE(first.converged);
    EXPECT_EQ(first.samples, 4);
    EXPECT_TRUE(renderer.hasMoreWork());
    const Frame second = renderer.step();
    EXPECT_EQ(second.samples, 8);
    // A new state starts over.
    renderer.setState(stateFor(Solver2D::Reference));
    EXPECT_EQ(renderer.step().samples, 4);
}

TEST(ProgressiveReference, MeanOfPassesMatchesOneLongSolve) {
    gi2d::Scene2D scene = *lampScene();
    auto medium = gi2d::rasterize(scene);
    ASSERT_TRUE(medium);
    ProgressiveReference progressive(8);
    for (int i = 0; i < 16; ++i) ASSERT_TRUE(progressive.addPass(*medium));
    EXPECT_EQ(progressive.raysPerPixel(), 128);
    gi2d::ReferenceOptions options;
    options.rays = 128;
    auto full = gi2d::solveReference(*medium, options);
    ASSERT_TRUE(full);
    const Image mean = progressive.mean();
    double diff = 0;
    for (std::size_t i = 0; i < mean.size(); ++i)
        diff += std::fabs(mean.data()[i] - full->data()[i]);
    const double relative = diff / (meanOf(*full) * static_cast<double>(mean.size()));
    EXPECT_LT(relative, 0.05) << "relative L1 between 16x8 rays and 128 rays: " << relative;
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
