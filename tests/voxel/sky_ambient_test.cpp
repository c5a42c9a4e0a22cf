// Sky ambient with occlusion (render.sky_ambient_rays; src/voxel/sky_ambient.h,
// docs/algorithms/voxel-surfaces.md "Sky ambient with occlusion"): a sealed box is black inside,
// an open plane receives the sky's analytic irradiance, a wall takes its share, and the scene
// field is read and checked.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_scene.h"
#include "voxel/sky_ambient.h"

namespace luxel::voxel {
namespace {

const Voxel kStone{180, 170, 160, 255};

VoxelWorld emptyWorld(Int3 size) {
    auto world = VoxelWorld::create(size, 8);
    EXPECT_TRUE(world.ok()) << world.error().message();
    return std::move(*world);
}

void fill(VoxelWorld& w, Int3 lo, Int3 hi) {
    for (int z = lo.z; z < hi.z; ++z) {
        for (int y = lo.y; y < hi.y; ++y) {
            for (int x = lo.x; x < hi.x; ++x) w.set(x, y, z, kStone);
        }
    }
}

ShadeOptions physical(int rays) {
    ShadeOptions o;
    o.lighting = ShadeOptions::Lighting::Physical;
    o.skyAmbientRays = rays;
    return o;
}

// A closed shell one voxel thick, 2..13 on every axis, in full sun and sky.
VoxelWorld sealedBox() {
    VoxelWorld w = emptyWorld({16, 16, 16});
    fill(w, {2, 2, 2}, {14, 14, 14});
    for (int z = 3; z < 13; ++z) {
        for (int y = 3; y < 13; ++y) {
            for (int x = 3; x < 13; ++x) w.set(x, y, z, Voxel{});
        }
    }
    return w;
}

TEST(SkyAmbient, SealedBoxIsBlackInsideWithRays) {
    const VoxelWorld world = sealedBox();
    const Ray down{{7.3, 10.5, 7.6}, {0.1, -1.0, 0.2}};
    // The constant share lights the floor through the walls.
    const Rgb constant = shadeRay(world, down, physical(0));
    EXPECT_GT(constant.maxComponent(), 0.05f);
    // Traced, no ray leaves the box: no ambient, no rough sky reflection, no sun.
    EXPECT_EQ(shadeRay(world, down, physical(16)).maxComponent(), 0.0f);
    // A whole picture from inside the box, every pixel with its own rays.
    const Camera camera = Camera::lookAt({7.5, 8.5, 3.5}, {7.5, 6.0, 12.0}, 80, 24, 16).value();
    const Image inside = render(world, camera, physical(8));
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            ASSERT_EQ(inside.rgb(x, y).maxComponent(), 0.0f) << x << ", " << y;
        }
    }
    EXPECT_GT(render(world, camera, physical(0)).rgb(12, 8).maxComponent(), 0.05f);
}

// A floor one voxel thick: every ray from its top face reaches the sky.
VoxelWorld openPlane() {
    VoxelWorld w = emptyWorld({32, 8, 32});
    fill(w, {0, 0, 0}, {32, 1, 32});
    return w;
}

TEST(SkyAmbient, OpenPlaneUnderAUniformSkySeesAllOfIt) {
    const VoxelWorld world = openPlane();
    ShadeOptions o = physical(16);
    o.skyTop = o.skyHorizon = {0.3f, 0.5f, 0.9f};
    PathRng rng(3, 0, 0);
    const SkyAmbient a = traceSkyAmbient(world, nullptr, {16.3, 1.0, 16.7}, {0, 1, 0}, o, rng);
    EXPECT_EQ(a.visible, 1.0f);
    EXPECT_NEAR(a.sky.r, 0.3f, 1e-6f);
    EXPECT_NEAR(a.sky.g, 0.5f, 1e-6f);
    EXPECT_NEAR(a.sky.b, 0.9f, 1e-6f);
    // The shaded face: exactly the constant share 1 (irradiance π L), the rough reflection too.
    ShadeOptions full = physical(0);
    full.skyTop = full.skyHorizon = o.skyTop;
    full.skyAmbient = 1.0f;
    const Ray down{{9.4, 5.0, 20.2}, {0.3, -1.0, -0.1}};
    const Rgb traced = shadeRay(world, down, o), constant = shadeRay(world, down, full);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(traced[c], constant[c], 1e-5f * constant[c]) << c;
}

TEST(SkyAmbient, OpenPlaneUnderTheGradientGetsItsAnalyticIrradiance) {
    // sky(d) = horizon + (top - horizon) d_y; over cosine-distributed directions E[d_y] = 2/3
    // and Var[d_y] = 1/2 - 4/9 = 1/18, so the mean of n rays has standard deviation
    // |top - horizon| sqrt(1/18 / n).
    const VoxelWorld world = openPlane();
    ShadeOptions o = physical(64);
    o.skyTop = {0.1f, 0.2f, 0.8f};
    o.skyHorizon = {0.9f, 0.9f, 1.0f};
    constexpr int kPoints = 256;
    Rgb mean;
    for (int i = 0; i < kPoints; ++i) {
        PathRng rng(11, std::uint64_t(i), 0);
        const Vec3d p{2.0 + (i % 16) * 1.7, 1.0, 2.0 + (i / 16) * 1.7};
        const SkyAmbient a = traceSkyAmbient(world, nullptr, p, {0, 1, 0}, o, rng);
        ASSERT_EQ(a.visible, 1.0f);
        mean += a.sky * (1.0f / kPoints);
    }
    const double n = double(kPoints) * o.skyAmbientRays;
    for (int c = 0; c < 3; ++c) {
        const double expected = o.skyHorizon[c] + (o.skyTop[c] - o.skyHorizon[c]) * (2.0 / 3.0);
        const double sigma = std::abs(o.skyTop[c] - o.skyHorizon[c]) * std::sqrt(1.0 / 18.0 / n);
        EXPECT_NEAR(mean[c], expected, 5.0 * sigma + 1e-6) << c;
    }
}

TEST(SkyAmbient, AWallTakesItsShareOfTheSky) {
    // A wall 29 voxels tall and 32 long beside the floor points, half a voxel away: an infinitely
    // long one would hide the cosine-weighted share (1 - D / sqrt(D^2 + H^2)) / 2 = 0.491; this
    // one hides 0.488 of it at these points (integrated numerically), leaving 0.512.
    VoxelWorld walled = emptyWorld({40, 32, 32});
    fill(walled, {0, 0, 0}, {40, 1, 32});
    VoxelWorld open = emptyWorld({40, 32, 32});
    fill(open, {0, 0, 0}, {40, 1, 32});
    fill(walled, {20, 1, 0}, {21, 30, 32});
    const ShadeOptions o = physical(256);
    double visible = 0;
    constexpr int kPoints = 16;
    for (int i = 0; i < kPoints; ++i) {
        PathRng rng(5, std::uint64_t(i), 0);
        visible += traceSkyAmbient(walled, nullptr, {19.5, 1.0, 12.25 + 0.5 * i}, {0, 1, 0}, o, rng)
                       .visible;
    }
    visible /= kPoints;
    EXPECT_NEAR(visible, 0.512, 0.04);  // 4096 rays: standard deviation 0.008
    // The shaded face beside the wall is darker than the same face in the open.
    const Ray down{{19.5, 8.0, 16.5}, {0.0, -1.0, 0.05}};
    ShadeOptions skyOnly = o;
    skyOnly.sunIrradiance = {};
    const Rgb near = shadeRay(walled, down, skyOnly), far = shadeRay(open, down, skyOnly);
    EXPECT_LT(near.g, 0.7f * far.g);
    EXPECT_GT(near.g, 0.3f * far.g);
}

TEST(SkyAmbient, NumbersArePerPixelAndRendersRepeat) {
    const VoxelWorld world = sealedBox();
    VoxelWorld roofless = world;
    for (int z = 3; z < 13; ++z) {
        for (int x = 3; x < 13; ++x) roofless.set(x, 13, z, Voxel{});
    }
    const Camera camera = Camera::lookAt({7.5, 9.5, 3.5}, {7.5, 3.0, 12.0}, 80, 32, 20).value();
    const ShadeOptions o = physical(4);
    const Image a = render(roofless, camera, o), b = render(roofless, camera, o);
    bool noisy = false;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            ASSERT_EQ(a.rgb(x, y).r, b.rgb(x, y).r);
            // shadePixel draws pixel (x, y)'s numbers, as render() does.
            ASSERT_EQ(shadePixel(roofless, camera, x, y, o).g, a.rgb(x, y).g);
            if (x > 0 && a.rgb(x, y).g != a.rgb(x - 1, y).g) noisy = true;
        }
    }
    EXPECT_TRUE(noisy);  // neighbours draw their own rays
}

TEST(SkyAmbient, SceneFieldIsReadAndChecked) {
    const std::string head =
        R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
            "camera": {"position": [0, 0, 0]}, "render": )";
    auto scene = parseVoxelScene(head + R"({"sky_ambient": 0.3, "sky_ambient_rays": 24}})", "s");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->shading.skyAmbientRays, 24);
    EXPECT_EQ(scene->shading.skyAmbient, 0.3f);
    // The share is then unused, and the scene says so.
    ASSERT_EQ(scene->warnings.size(), 1u);
    EXPECT_NE(scene->warnings[0].find("render.sky_ambient is not used"), std::string::npos)
        << scene->warnings[0];
    scene = parseVoxelScene(head + R"({"sky_ambient": 0.3, "sky_ambient_rays": 0}})", "s");
    ASSERT_TRUE(scene.ok());
    EXPECT_TRUE(scene->warnings.empty());
    scene = parseVoxelScene(head + "{}}", "s");
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->shading.skyAmbientRays, 0);
    EXPECT_TRUE(scene->warnings.empty());
    for (const char* bad : {R"({"sky_ambient_rays": -1}})", R"({"sky_ambient_rays": 257}})",
                            R"({"sky_ambient_rays": 2.5}})", R"({"sky_ambient_rays": "8"}})"}) {
        auto s = parseVoxelScene(head + bad, "bad.json");
        ASSERT_FALSE(s.ok()) << bad;
        EXPECT_NE(s.error().message().find("render.sky_ambient_rays"), std::string::npos)
            << s.error().message();
        EXPECT_NE(s.error().message().find("bad.json"), std::string::npos) << s.error().message();
    }
}

}  // namespace
}  // namespace luxel::voxel
