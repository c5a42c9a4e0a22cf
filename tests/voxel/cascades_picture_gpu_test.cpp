// The voxel radiance cascades' picture on the GPU (RadianceCascadesGpu::render) against its CPU
// reference (RadianceCascades::render) from the same faces' irradiance: the cottage, a room with
// glass, a mirror, rough metal and a lamp under a sun with a disk, a lamp's highlight on a glossy
// floor, a sky-only view and a camera
// inside a solid voxel; and the faces' table the shader probes. Runs on lavapipe where there is
// no hardware GPU, and skips where there is no Vulkan device.
//
// Both pictures cast the same rays and draw the same random numbers (shared/path_rng.h); the GPU
// works in float where the CPU works partly in double. So every pixel agrees to float rounding
// unless a ray passes within rounding of a voxel edge (a shadow ray, a GGX direction or the
// primary ray then meets another face). On lavapipe (CI) no pixel does: measured rel-L1 5e-9 on
// the cottage and at most 7e-8 in the glass room, low-frequency error at most 2e-7, every channel
// within 1e-3; the bounds (`Bounds`) are those with a margin of 10 or more. A hardware driver's
// sin, exp and sqrt round otherwise and may turn a few rays at edges (one of 4 sun rays in one
// pixel of 96x54 is about 5e-5 of rel-L1), so there the bounds allow a few such pixels. Either
// way a wrong term (1 sun ray instead of 4 moved 5% of the cottage's channels, rel-L1 8e-5, a
// block 3e-3; the glass room 64% of them) fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/gpu_test_context.h"
#include "voxel/cascades/cascade_picture_gpu.h"
#include "voxel/cascades/surface_faces.h"
#include "voxel/glossy_lamp_room.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

struct Parity {
    double relativeL1 = 0;    // sum |gpu - cpu| / sum |cpu| over every channel
    double lowFrequency = 0;  // the largest 8x8 block mean's |gpu - cpu| / the image's mean
    double same = 0;          // fraction of channels within 1e-3 relative (+1e-5 absolute)
};

Parity compare(const Image& cpu, const Image& gpu) {
    Parity p;
    EXPECT_EQ(cpu.width(), gpu.width());
    EXPECT_EQ(cpu.height(), gpu.height());
    if (cpu.width() != gpu.width() || cpu.height() != gpu.height()) return {1e9, 1e9, 0};
    double difference = 0, total = 0;
    int same = 0, count = 0;
    for (int y = 0; y < cpu.height(); ++y)
        for (int x = 0; x < cpu.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double a = cpu.at(x, y, c), b = gpu.at(x, y, c);
                EXPECT_TRUE(std::isfinite(b)) << x << "," << y;
                difference += std::abs(a - b);
                total += std::abs(a);
                same += std::abs(a - b) <= 1e-3 * std::abs(a) + 1e-5;
                ++count;
            }
    p.relativeL1 = total > 0 ? difference / total : difference;
    p.same = double(same) / count;
    const double mean = total / count;
    for (int by = 0; by < cpu.height(); by += 8)
        for (int bx = 0; bx < cpu.width(); bx += 8) {
            double a = 0, b = 0;
            for (int y = by; y < std::min(by + 8, cpu.height()); ++y)
                for (int x = bx; x < std::min(bx + 8, cpu.width()); ++x)
                    for (int c = 0; c < 3; ++c) a += cpu.at(x, y, c), b += gpu.at(x, y, c);
            const double pixels =
                3.0 * (std::min(by + 8, cpu.height()) - by) * (std::min(bx + 8, cpu.width()) - bx);
            if (mean > 0)
                p.lowFrequency = std::max(p.lowFrequency, std::abs(a - b) / pixels / mean);
        }
    return p;
}

struct Pictures {
    Image cpu, gpu;
    double gpuMilliseconds = 0;
};

// The shared context (the picture's shader is compiled once for all tests), or a skip.
#define REQUIRE_CONTEXT(context)                               \
    gpu::Context* context = ::luxel::test::sharedGpuContext(); \
    if (!context) GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message()

// The lighting passes on the GPU, then both pictures from the same irradiance.
Pictures drawBoth(gpu::Context& context, const VoxelWorld& world, const TextureSet* textures,
                  const ShadeOptions& shading, const std::vector<Camera>& cameras,
                  std::vector<Pictures>* more = nullptr) {
    // Four bounces: the pictures compare the same irradiance, whatever it converged to.
    CascadeOptions options;
    options.bounces = 4;
    auto cascades = RadianceCascades::create(world, textures, shading, options);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    if (!cascades.ok()) return {};
    auto gpu = RadianceCascadesGpu::create(context, *cascades);
    EXPECT_TRUE(gpu.ok()) << gpu.error().message();
    if (!gpu.ok()) return {};
    auto solved = gpu->solve();
    EXPECT_TRUE(solved.ok()) << solved.error().message();
    // One more pass, not downloaded: the GPU picture must read the irradiance on the device
    // (the CPU object still holds the last pass's until download()).
    EXPECT_TRUE(gpu->iterate(1).ok());
    std::vector<Pictures> drawn(cameras.size());
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        auto onGpu = gpu->render(cameras[i], &drawn[i].gpuMilliseconds);
        EXPECT_TRUE(onGpu.ok()) << onGpu.error().message();
        if (!onGpu.ok()) return {};
        drawn[i].gpu = std::move(*onGpu);
    }
    EXPECT_TRUE(gpu->download().ok());
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        auto onCpu = cascades->render(cameras[i]);
        EXPECT_TRUE(onCpu.ok()) << onCpu.error().message();
        if (!onCpu.ok()) return {};
        drawn[i].cpu = std::move(*onCpu);
    }
    EXPECT_EQ(context.validationMessages(), 0) << context.lastValidationMessage();
    if (more) *more = drawn;
    return drawn.empty() ? Pictures{} : std::move(drawn.front());
}

struct Bounds {
    double relativeL1, lowFrequency, same;
};

// Tight on a CPU device (lavapipe: measured), looser on hardware (a few rays turned at edges).
Bounds boundsFor(const gpu::Context& context) {
    if (context.device().type == "cpu") return {1e-6, 2e-6, 0.999};
    return {2e-4, 1e-3, 0.995};
}

void expectWithin(const Parity& p, const Bounds& b, const char* name) {
    std::printf("%s: rel-L1 %.2e, low-frequency %.2e, same %.5f\n", name, p.relativeL1,
                p.lowFrequency, p.same);
    EXPECT_LE(p.relativeL1, b.relativeL1) << name;
    EXPECT_LE(p.lowFrequency, b.lowFrequency) << name;
    EXPECT_GE(p.same, b.same) << name;
}

TEST(CascadesPictureGpu, CottageMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 96, 54);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const Pictures p =
        drawBoth(*context, scene->world, &scene->textures, scene->shading, {scene->camera});
    ASSERT_FALSE(p.gpu.empty());
    expectWithin(compare(p.cpu, p.gpu), boundsFor(*context), "cottage");
    EXPECT_GT(p.gpuMilliseconds, 0.0);
}

// A lit room's corner: a white floor and back wall, a clear glass block that absorbs, a mirror
// wall, a rough gold block (two GGX rays), a glossy dielectric block and a lamp, under a sky and
// a sun of radius 0.05 rad: every branch of the picture (sun rays through glass, the medium's
// exits, mirror and GGX reflections, followed levels, the disk behind a delta lobe).
struct GlassRoom {
    VoxelWorld world = makeWorld({24, 12, 24});
    ShadeOptions o;
    GlassRoom() {
        for (int z = 0; z < 24; ++z)
            for (int x = 0; x < 24; ++x) world.set(x, 0, z, kWhite);
        for (int y = 1; y < 10; ++y)
            for (int x = 0; x < 24; ++x) world.set(x, y, 0, kWhite);  // back wall
        for (int y = 1; y < 9; ++y)
            for (int z = 1; z < 16; ++z) world.set(1, y, z, Voxel{230, 230, 230, 2});  // mirror
        for (int y = 1; y < 5; ++y)
            for (int z = 6; z < 9; ++z)
                for (int x = 8; x < 11; ++x) world.set(x, y, z, Voxel{255, 255, 255, 1});  // glass
        for (int y = 1; y < 4; ++y)
            for (int z = 3; z < 6; ++z)
                for (int x = 14; x < 17; ++x) world.set(x, y, z, Voxel{255, 210, 120, 3});  // gold
        for (int y = 1; y < 3; ++y)
            for (int z = 10; z < 13; ++z)
                for (int x = 16; x < 19; ++x) world.set(x, y, z, Voxel{90, 160, 220, 4});
        world.set(5, 1, 3, Voxel{255, 255, 255, 5});  // lamp
        world.refreshEmptySpace();
        o = plainLight(0.7f, Rgb(0.0f), Rgb(0.3f, 0.45f, 0.8f));
        o.skyHorizon = Rgb(0.7f, 0.75f, 0.85f);
        o.sunIrradiance = Rgb(3.0f, 2.9f, 2.7f);
        o.sunDirection = {0.5f, 0.8f, 0.35f};
        o.sunAngularRadius = 0.05;
        EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(0.3f, 0.1f, 0.05f))).ok());
        EXPECT_TRUE(o.materials.setSlot(1, metal(0.0f, Rgb(0.95f))).ok());
        EXPECT_TRUE(o.materials.setSlot(2, metal(0.4f, Rgb(1.0f))).ok());
        Material glossy;
        glossy.name = "glossy";
        glossy.ior = 1.5f;
        glossy.roughness = 0.3f;
        EXPECT_TRUE(o.materials.setSlot(3, glossy).ok());
        EXPECT_TRUE(o.materials.setSlot(4, lampMaterial(Rgb(6.0f, 5.0f, 3.0f))).ok());
    }
};

TEST(CascadesPictureGpu, GlassMirrorAndMetalMatchTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    const GlassRoom room;
    const Camera camera = *Camera::lookAt({20.0, 7.0, 20.0}, {8.0, 2.0, 6.0}, 60.0, 96, 54);
    // Looking into the mirror, which shows the glass block and the room behind the camera.
    const Camera mirror = *Camera::lookAt({12.0, 4.0, 12.0}, {1.0, 3.0, 8.0}, 50.0, 64, 36);
    // Low over the rough floor towards the glass block and the mirror behind it: the floor's GGX
    // rays pass the glass and meet the mirror, which a rough lobe's rays do not follow (§4.2,
    // "Rough lobes follow one face").
    const Camera grazing = *Camera::lookAt({20.0, 1.5, 7.5}, {1.0, 1.2, 7.5}, 40.0, 64, 36);
    std::vector<Pictures> drawn;
    drawBoth(*context, room.world, nullptr, room.o, {camera, mirror, grazing}, &drawn);
    ASSERT_EQ(drawn.size(), 3u);
    const char* names[] = {"glass room", "glass room in the mirror", "glass room over the floor"};
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        expectWithin(compare(drawn[i].cpu, drawn[i].gpu), boundsFor(*context), names[i]);
    }
}

// The glass room's mirror made a polished metal of roughness 0.03 (GGX alpha 0.0009): a sharp
// lobe, which takes one GGX direction at the camera's surface on both backends (§4.2, "Sharp
// lobes take one ray"), and no light sample of its lamp ("Sharp lobes take no lamp samples").
TEST(CascadesPictureGpu, SharpMetalMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    GlassRoom room;
    EXPECT_TRUE(room.o.materials.setSlot(1, metal(0.03f, Rgb(0.95f))).ok());
    const Camera mirror = *Camera::lookAt({12.0, 4.0, 12.0}, {1.0, 3.0, 8.0}, 50.0, 64, 36);
    std::vector<Pictures> drawn;
    drawBoth(*context, room.world, nullptr, room.o, {mirror}, &drawn);
    ASSERT_EQ(drawn.size(), 1u);
    expectWithin(compare(drawn[0].cpu, drawn[0].gpu), boundsFor(*context),
                 "glass room in a sharp metal");
}

// A closed 14^3 white room with a lamp on the floor and a glass voxel and a white block beside it
// (lampRoomLight's materials); with `floorVoxel` the floor is that voxel instead.
VoxelWorld lampRoom(const Voxel* floorVoxel) {
    VoxelWorld world = makeWorld({14, 14, 14});
    for (int z = 0; z < 14; ++z)
        for (int y = 0; y < 14; ++y)
            for (int x = 0; x < 14; ++x) {
                if (y == 0 && floorVoxel) {
                    world.set(x, y, z, *floorVoxel);
                } else if (x == 0 || y == 0 || z == 0 || x == 13 || y == 13 || z == 13) {
                    world.set(x, y, z, kWhite);
                }
            }
    world.set(6, 1, 6, Voxel{255, 255, 255, 2});  // lamp
    world.set(8, 1, 6, Voxel{255, 255, 255, 1});  // glass
    world.set(6, 1, 8, kWhite);
    world.refreshEmptySpace();
    return world;
}

// lampRoom's light: no sun or sky, the glass tinted, the lamp bright.
ShadeOptions lampRoomLight() {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(0.2f, 0.1f, 0.05f))).ok());
    EXPECT_TRUE(o.materials.setSlot(1, lampMaterial(Rgb(20.0f, 15.0f, 10.0f))).ok());
    return o;
}

// A lamp on the floor of a closed room, a glass voxel and a wall block beside it: the emitters'
// light near the lamp is taken exactly at each pixel (near_emitters.glsl), through the glass
// and past the block's shadow, as on the CPU.
TEST(CascadesPictureGpu, LightNearALampMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    const VoxelWorld world = lampRoom(nullptr);
    ShadeOptions o = lampRoomLight();
    const Camera camera = *Camera::lookAt({10.5, 6.0, 10.5}, {6.5, 1.0, 6.5}, 70.0, 64, 48);
    const Pictures p = drawBoth(*context, world, nullptr, o, {camera});
    ASSERT_FALSE(p.gpu.empty());
    expectWithin(compare(p.cpu, p.gpu), boundsFor(*context), "lamp room");
    // A new emission through setLight: the GPU picture takes the new lists and far shares.
    auto cascades = RadianceCascades::create(world, nullptr, o);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    auto gpu = RadianceCascadesGpu::create(*context, *cascades);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ASSERT_TRUE(gpu->iterate(2).ok());
    ASSERT_TRUE(gpu->render(camera).ok());
    ASSERT_TRUE(o.materials.setSlot(1, lampMaterial(Rgb(5.0f, 30.0f, 12.0f))).ok());
    ASSERT_TRUE(cascades->setLight(o).ok());
    ASSERT_TRUE(gpu->uploadLight().ok());
    ASSERT_TRUE(gpu->iterate(2).ok());
    auto onGpu = gpu->render(camera);
    ASSERT_TRUE(onGpu.ok()) << onGpu.error().message();
    ASSERT_TRUE(gpu->download().ok());
    auto onCpu = cascades->render(camera);
    ASSERT_TRUE(onCpu.ok()) << onCpu.error().message();
    expectWithin(compare(*onCpu, *onGpu), boundsFor(*context), "lamp room, new emission");
}

// A glossy floor beside a lamp, a glass voxel and a wall block: the camera surface's highlight
// of the near emitters is light-sampled (nearEmitterHighlight, through the glass and past the
// block), its GGX rays counting those emitters by the share left, as on the CPU.
TEST(CascadesPictureGpu, HighlightOfALampOnAGlossyFloorMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    const Voxel glossyFloor{200, 200, 200, 3};
    const VoxelWorld world = lampRoom(&glossyFloor);
    ShadeOptions o = lampRoomLight();
    ASSERT_TRUE(o.materials.setSlot(2, polishedFloor(0.2f)).ok());
    const Camera low = *Camera::lookAt({6.5, 3.5, 1.5}, {6.5, 1.0, 5.5}, 60.0, 64, 48);
    const Camera across = *Camera::lookAt({11.5, 3.0, 9.5}, {7.0, 1.0, 6.5}, 60.0, 64, 48);
    std::vector<Pictures> drawn;
    drawBoth(*context, world, nullptr, o, {low, across}, &drawn);
    ASSERT_EQ(drawn.size(), 2u);
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        expectWithin(compare(drawn[i].cpu, drawn[i].gpu), boundsFor(*context),
                     i == 0 ? "glossy floor before the lamp" : "glossy floor across the lamp");
    }
}

// A glossy room lit by a small lamp far from its glossy walls: the lamps light-sampled in the
// camera surface's glossy lobe and the GGX rays that meet them weighed by the balance heuristic
// (glossy_emitters.glsl), as on the CPU, at one sample and at four.
TEST(CascadesPictureGpu, FarLampOnGlossyWallsMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    GlossyWallsRoom room;
    const Camera camera = farWallView(64, 48);
    // A block's mean moves by up to 3.6e-6 of the image's on lavapipe (the light sample's lobe
    // density and weight are the CPU's double against the GPU's float), the other bounds as
    // tight as elsewhere.
    Bounds bounds = boundsFor(*context);
    bounds.lowFrequency = std::max(bounds.lowFrequency, 1e-5);
    const Camera ceiling = *Camera::lookAt({3.5, 2.5, 3.5}, {12.0, 17.0, 12.0}, 60.0, 64, 48);
    for (int samples : {1, 4}) {
        room.o.samplesPerPixel = samples;
        std::vector<Pictures> drawn;
        drawBoth(*context, room.world, nullptr, room.o, {camera, ceiling}, &drawn);
        ASSERT_EQ(drawn.size(), 2u);
        for (std::size_t i = 0; i < drawn.size(); ++i) {
            expectWithin(compare(drawn[i].cpu, drawn[i].gpu), bounds,
                         i == 0 ? "far glossy wall" : "glossy ceiling");
        }
    }
}

// GlossyWallsRoom with walls and ceiling of roughness 0.8 (GGX alpha 0.64): a very rough lobe,
// which takes one GGX direction at the camera's surface on both backends (§4.2, "Very rough
// lobes take one ray"), the far lamp light-sampled against that one.
TEST(CascadesPictureGpu, FarLampOnVeryRoughWallsMatchesTheCpuPicture) {
    REQUIRE_CONTEXT(context);
    GlossyWallsRoom room;
    Material rough = polishedFloor(0.1f);
    rough.roughness = 0.8f;
    ASSERT_TRUE(room.o.materials.setSlot(1, rough).ok());
    Bounds bounds = boundsFor(*context);
    bounds.lowFrequency = std::max(bounds.lowFrequency, 1e-5);  // as for the far lamp above
    for (int samples : {1, 4}) {
        room.o.samplesPerPixel = samples;
        std::vector<Pictures> drawn;
        drawBoth(*context, room.world, nullptr, room.o, {farWallView(64, 48)}, &drawn);
        ASSERT_EQ(drawn.size(), 1u);
        expectWithin(compare(drawn[0].cpu, drawn[0].gpu), bounds, "very rough far wall");
    }
}

// Over the ray caster's upload (the viewer's GPU source): the same picture as over the picture's
// own upload, the world not sent again, and the ray caster's own frame unchanged by the picture
// drawn over its buffers.
TEST(CascadesPictureGpu, DrawsOverAnUploadedWorldWithoutSendingItAgain) {
    REQUIRE_CONTEXT(context);
    const GlassRoom room;
    const Camera camera = *Camera::lookAt({20.0, 7.0, 20.0}, {8.0, 2.0, 6.0}, 60.0, 64, 36);
    auto cascades = RadianceCascades::create(room.world, nullptr, room.o);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    auto gpu = RadianceCascadesGpu::create(*context, *cascades);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ASSERT_TRUE(gpu->iterate(3).ok());
    auto own = gpu->render(camera);
    ASSERT_TRUE(own.ok()) << own.error().message();

    auto caster = VoxelGpuRenderer::create(*context, room.world, nullptr);
    ASSERT_TRUE(caster.ok()) << caster.error().message();
    auto before = caster->render(camera, room.o);
    ASSERT_TRUE(before.ok()) << before.error().message();
    const std::uint64_t worldSent = caster->uploads().world;
    gpu->useUploadedWorld(*caster);
    auto shared = gpu->render(camera);
    ASSERT_TRUE(shared.ok()) << shared.error().message();
    ASSERT_EQ(shared->size(), own->size());
    for (std::size_t i = 0; i < own->size(); ++i) {
        ASSERT_EQ(shared->data()[i], own->data()[i]) << i;
    }
    EXPECT_EQ(caster->uploads().world, worldSent);
    auto after = caster->render(camera, room.o);
    ASSERT_TRUE(after.ok()) << after.error().message();
    for (std::size_t i = 0; i < before->size(); ++i) {
        ASSERT_EQ(after->data()[i], before->data()[i]) << i;
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(CascadesPictureGpu, SkyOnlyIsTheSky) {
    REQUIRE_CONTEXT(context);
    // One voxel in a corner so the cascades have a face; the camera looks up past it.
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(0, 0, 0, kWhite);
    world.refreshEmptySpace();
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.2f, 0.4f, 0.9f));
    o.skyHorizon = Rgb(0.9f, 0.8f, 0.7f);
    o.sunIrradiance = Rgb(2.0f);
    const Camera up = *Camera::create({8.0, 8.0, 8.0}, 20.0, 45.0, 60.0, 24, 16);
    const Pictures p = drawBoth(*context, world, nullptr, o, {up});
    ASSERT_FALSE(p.gpu.empty());
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const Rgb sky = skyColor(up.rayAt(x + 0.5, y + 0.5).direction, o);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(p.gpu.at(x, y, c), sky[c], 1e-5) << x << "," << y;
                EXPECT_NEAR(p.cpu.at(x, y, c), sky[c], 1e-5) << x << "," << y;
            }
        }
}

TEST(CascadesPictureGpu, CameraInsideASolidVoxelSeesBlackAndWhatDoesNotFitIsRefused) {
    REQUIRE_CONTEXT(context);
    VoxelWorld world = makeWorld({16, 8, 16});
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) world.set(x, 0, z, kWhite);
    for (int y = 1; y < 5; ++y)
        for (int z = 5; z < 10; ++z)
            for (int x = 5; x < 10; ++x) world.set(x, y, z, kWhite);
    world.refreshEmptySpace();
    ShadeOptions o = plainLight(0.6f, Rgb(0.0f), Rgb(0.5f));
    o.sunIrradiance = Rgb(2.0f);
    auto cascades = RadianceCascades::create(world, nullptr, o, CascadeOptions{});
    ASSERT_TRUE(cascades.ok());
    auto gpu = RadianceCascadesGpu::create(*context, *cascades);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ASSERT_TRUE(gpu->iterate(2).ok());
    const Camera inside = *Camera::create({7.5, 2.5, 7.5}, 30.0, -10.0, 70.0, 24, 16);
    auto black = gpu->render(inside);
    ASSERT_TRUE(black.ok()) << black.error().message();
    for (float v : std::span(black->data(), black->size())) EXPECT_EQ(v, 0.0f);
    // A larger image after a smaller one (the picture's buffer grows): the room seen from outside
    // is lit.
    const Camera outside = *Camera::lookAt({14.0, 6.0, 1.0}, {7.0, 2.0, 7.0}, 60.0, 40, 30);
    auto lit = gpu->render(outside);
    ASSERT_TRUE(lit.ok()) << lit.error().message();
    double sum = 0;
    for (float v : std::span(lit->data(), lit->size())) sum += v;
    EXPECT_GT(sum, 0.0);
    // A budget too small for the picture: refused with its bytes, and the next frame without
    // one is drawn.
    auto tight = gpu->render(outside, nullptr, 4096);
    ASSERT_FALSE(tight.ok());
    for (const char* part : {"40x30 on the GPU needs", "faces' table", "adaptive pixel list 592 B",
                             "the budget is 4.0 KiB"}) {
        EXPECT_NE(tight.error().message().find(part), std::string::npos) << tight.error().message();
    }
    EXPECT_TRUE(gpu->render(outside).ok());
    auto huge = Camera::create({7.5, 2.5, 7.5}, 0.0, 0.0, 60.0, 16384, 8192);
    ASSERT_TRUE(huge.ok());
    auto refused = gpu->render(*huge);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message().find("pixels"), std::string::npos);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// The faces' table as the shader probes it: every face at its id, a face of the same voxel with
// another normal and voxels without faces not found.
TEST(CascadesPictureGpu, FaceSlotsFindEveryFaceAndNothingElse) {
    const GlassRoom room;
    auto table = cascades::FaceTable::build(room.world, nullptr, 1 << 22);
    ASSERT_TRUE(table.ok());
    const auto slots = cascades::faceSlots(*table);
    const std::uint32_t mask = std::uint32_t(slots.size() - 1);
    ASSERT_EQ(slots.size() & mask, 0u);
    ASSERT_GE(slots.size(), 2u * table->size());
    const auto find = [&](Int3 v, int normal) {
        const std::uint32_t low = gpu::shared::cascadeFaceKeyLow(v.x, v.y, normal),
                            high = std::uint32_t(v.z);
        std::uint32_t slot = gpu::shared::cascadeFaceHash(low, high) & mask;
        for (std::uint32_t probe = 0; probe <= mask; ++probe) {
            if (slots[slot].id == LUXEL_PICTURE_EMPTY_SLOT) return -1;
            if (slots[slot].keyLow == low && slots[slot].keyHigh == high) {
                return int(slots[slot].id);
            }
            slot = (slot + 1) & mask;
        }
        return -1;
    };
    for (int id = 0; id < table->size(); ++id) {
        const cascades::Face& f = (*table)[id];
        EXPECT_EQ(find(f.voxel, f.normal), id);
    }
    for (int z = 0; z < 24; ++z)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 24; ++x)
                for (int n = 0; n < 6; ++n) {
                    EXPECT_EQ(find({x, y, z}, n), table->find({x, y, z}, n));
                }
}

}  // namespace
