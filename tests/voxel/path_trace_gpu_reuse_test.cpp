// The GPU path tracer over a world uploaded once: a second pass sends nothing, a new view (the
// viewer's restart after a camera move) sends only the camera's parameters, an edit sends the
// chunks it touched and the emitters found again, and the image after it is the CPU's of the
// edited world. Also the refusal, with the bytes, of sums that do not fit in host memory.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "gpu/shaders/shared/path_trace_layout.h"
#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/voxel/voxel_gpu.h"
#include "support/memory_limit.h"
#include "voxel/path_trace_gpu_support.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr Voxel kLamp{255, 255, 255, 1};  // texture slot 0: the lamp's material

// A closed grey room lit by one emissive block (path_trace_gpu_test.cpp's lamp room).
struct LampRoom {
    VoxelWorld world = makeWorld({12, 8, 12});
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    LampRoom() {
        for (int z = 0; z < 12; ++z)
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 12; ++x) {
                    if (x == 0 || y == 0 || z == 0 || x == 11 || y == 7 || z == 11) {
                        world.set(x, y, z, Voxel{180, 180, 180, 255});
                    }
                }
        world.set(3, 1, 8, kLamp);
        world.refreshEmptySpace();
        const Material lamp = lampMaterial(Rgb(20.0f, 15.0f, 10.0f));
        EXPECT_TRUE(o.materials.setSlot(0, lamp).ok());
    }
};

bool sameImage(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), sizeof(float) * a.width() * a.height() * 3) == 0;
}

void expectSameUploads(const VoxelGpuUploads& a, const VoxelGpuUploads& b, const char* what) {
    EXPECT_EQ(a.world, b.world) << what;
    EXPECT_EQ(a.textures, b.textures) << what;
    EXPECT_EQ(a.materials, b.materials) << what;
    EXPECT_EQ(a.parameters, b.parameters) << what;
    EXPECT_EQ(a.shadows, b.shadows) << what;
}

TEST(PathTraceGpuReuse, ANewViewOrPassSendsNoWorldAndAnEditSendsItsChunks) {
    REQUIRE_CONTEXT(context);
    LampRoom room;
    auto renderer = VoxelGpuRenderer::create(*context, room.world);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    const VoxelGpuUploads created = renderer->uploads();
    EXPECT_GT(created.world, 0u);
    EXPECT_EQ(renderer->worldGeneration(), 1u);
    const Camera toward = *Camera::lookAt({6.0, 4.0, 7.0}, {6.0, 2.0, 0.5}, 70.0, 12, 9);
    const Camera across = *Camera::lookAt({9.0, 5.0, 3.0}, {2.0, 1.0, 6.0}, 70.0, 12, 9);
    PathTraceOptions p;
    p.samplesPerPixel = 16;
    auto tracer = PathTracerGpu::create(*context, *renderer, room.world, toward, room.o, p);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    EXPECT_EQ(&tracer->uploaded(), &*renderer);
    ASSERT_TRUE(tracer->addSamples(4).ok());
    const VoxelGpuUploads first = renderer->uploads();
    const std::uint64_t params = sizeof(gpu::shared::VoxelRenderParams);
    EXPECT_EQ(first.world, created.world);
    EXPECT_EQ(first.textures, created.textures);
    EXPECT_EQ(first.materials, LUXEL_VOXEL_MATERIALS * sizeof(gpu::shared::VoxelMaterial));
    EXPECT_EQ(first.parameters, created.parameters + params);
    const std::uint64_t oneEmitter = sizeof(gpu::shared::PathEmitterVoxel);
    EXPECT_EQ(tracer->emitterUploadBytes(), oneEmitter);

    // Another pass of the same view: nothing at all.
    ASSERT_TRUE(tracer->addSamples(4).ok());
    expectSameUploads(renderer->uploads(), first, "second pass");

    // A new view: the camera's parameters, no world, no materials, no emitters; and the image
    // is a new tracer's.
    ASSERT_TRUE(tracer->restart(across, room.o, p).ok());
    EXPECT_EQ(tracer->samplesDone(), 0);
    ASSERT_TRUE(tracer->addSamples(p.samplesPerPixel).ok());
    VoxelGpuUploads moved = first;
    moved.parameters += params;
    expectSameUploads(renderer->uploads(), moved, "new view");
    EXPECT_EQ(tracer->emitterUploadBytes(), oneEmitter);
    const PathTraceImage fresh = traceGpu(*context, room.world, across, room.o, p);
    EXPECT_TRUE(sameImage(tracer->image().radiance, fresh.radiance));
    EXPECT_TRUE(sameImage(tracer->image().standardError, fresh.standardError));

    // The lamp moves to the other side of the room: the two chunks' worth of voxels (and every
    // count, mask and reach) go up, the generation moves on, and the restarted tracer finds the
    // lamp where it is now. With the old list its light samples would aim at an empty voxel.
    room.world.set(3, 1, 8, Voxel{});
    room.world.set(9, 1, 9, kLamp);
    room.world.refreshEmptySpace();
    ASSERT_TRUE(renderer->updateRegion(room.world, {3, 1, 8}, {4, 2, 9}).ok());
    ASSERT_TRUE(renderer->updateRegion(room.world, {9, 1, 9}, {10, 2, 10}).ok());
    EXPECT_GT(renderer->uploads().world, first.world);
    EXPECT_EQ(renderer->worldGeneration(), 3u);
    p.samplesPerPixel = 64;
    ASSERT_TRUE(tracer->restart(across, room.o, p).ok());
    ASSERT_TRUE(tracer->addSamples(p.samplesPerPixel).ok());
    EXPECT_EQ(tracer->emitterUploadBytes(), 2 * oneEmitter);
    expectSameSamples(traceCpu(room.world, across, room.o, p), tracer->image(), "lamp moved");
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(PathTraceGpuReuse, ARestartChecksAsCreateDoesAndMayGrowTheImage) {
    REQUIRE_CONTEXT(context);
    LampRoom room;
    PathTraceOptions p;
    p.samplesPerPixel = 4;
    const Camera small = *Camera::lookAt({6.0, 4.0, 7.0}, {6.0, 2.0, 0.5}, 70.0, 8, 6);
    auto tracer = PathTracerGpu::create(*context, room.world, small, room.o, p);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    ASSERT_TRUE(tracer->addSamples(4).ok());
    PathTraceOptions bad = p;
    bad.maxBounces = kMaxPathBounces + 1;
    const Status refused = tracer->restart(small, room.o, bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message().find("max bounces"), std::string::npos);
    EXPECT_EQ(tracer->samplesDone(), 0);
    // The view it had goes on from no samples: a new tracer's image.
    ASSERT_TRUE(tracer->addSamples(4).ok());
    EXPECT_TRUE(sameImage(tracer->image().radiance,
                          traceGpu(*context, room.world, small, room.o, p).radiance));
    // A larger image, and emitters turned off (the list is sent again, empty: one placeholder).
    const Camera large = *Camera::lookAt({6.0, 4.0, 7.0}, {6.0, 2.0, 0.5}, 70.0, 16, 12);
    p.sampleEmitters = false;
    ASSERT_TRUE(tracer->restart(large, room.o, p).ok());
    ASSERT_TRUE(tracer->addSamples(4).ok());
    EXPECT_EQ(tracer->emitterUploadBytes(), 2 * sizeof(gpu::shared::PathEmitterVoxel));
    const PathTraceImage image = tracer->image();
    EXPECT_EQ(image.radiance.width(), 16);
    EXPECT_TRUE(
        sameImage(image.radiance, traceGpu(*context, room.world, large, room.o, p).radiance));
}

TEST(PathTraceGpuReuse, RefusesSumsThatDoNotFitInHostMemory) {
    REQUIRE_CONTEXT(context);
    // 8192 x 8192 pixels of 112 bytes: 7.0 GiB on the host, with 256 MiB to spare. The refusal
    // comes before anything is allocated or sent to the device.
    const int code = luxel::test::runUnderMemoryLimit(256 * 1024 * 1024, [&] {
        const VoxelWorld world = floorWorld();
        const Camera camera = *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8192, 8192);
        auto tracer = PathTracerGpu::create(*context, world, camera,
                                            plainLight(0.5f, Rgb(0.0f), Rgb(1.0f)), {});
        if (tracer.ok()) return 1;
        const std::string& m = tracer.error().message();
        const std::string device = "path tracing 8192x8192 on the GPU needs ";
        const std::string host =
            "path tracing 8192x8192 on the GPU (the running sums and a download) needs 7.0 GiB, "
            "only ";
        // A device with less than the sums' 3 GiB refuses first, naming its memory.
        return m.rfind(host, 0) == 0 || m.rfind(device, 0) == 0 ? 0 : 2;
    });
    EXPECT_EQ(code, 0);
}

}  // namespace
