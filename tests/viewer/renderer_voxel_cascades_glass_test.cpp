// The viewer's radiance cascades when refraction is toggled (R) over a world with glass: the
// cascades take the new light (RadianceCascades::setLight builds their faces under glass and
// segments again), so the frame is the library's picture after the same passes and setLight.
#include <gtest/gtest.h>

#include "luxel/post/finish.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/radiance_cascades.h"
#include "renderer_voxel.h"
#include "voxel_frame_source.h"
#include "voxel_solver.h"

namespace luxel::viewer {
namespace {

// A floor with a glass block on it (texture slot 0) under the default sun.
voxel::VoxelWorld floorWithGlassBlock() {
    auto world = voxel::VoxelWorld::create({16, 8, 16}, 8);
    EXPECT_TRUE(world.ok());
    voxel::addBox(*world, {0, 0, 0}, {16, 1, 16}, {90, 160, 70, 255});
    voxel::addBox(*world, {5, 1, 5}, {11, 4, 11}, {230, 240, 255, 0});
    world->refreshEmptySpace();
    return std::move(*world);
}

VoxelState cascadesState() {
    VoxelState s;
    s.camera.position = {8, 7, -6};
    s.camera.pitchDegrees = -25;
    s.width = 24;
    s.height = 16;
    s.solver.kind = VoxelSolver::Cascades;
    voxel::Material glass;
    glass.name = "glass";
    glass.ior = 1.5f;
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.absorption = Rgb(0.1f);
    EXPECT_TRUE(s.shading.materials.setSlot(0, glass).ok());
    return s;
}

Image libraryFrame(const voxel::RadianceCascades& cascades, const VoxelState& s) {
    const FlyCamera& c = s.camera;
    auto camera = voxel::Camera::create(c.position, c.yawDegrees, c.pitchDegrees, c.fovYDegrees,
                                        s.width, s.height);
    EXPECT_TRUE(camera.ok());
    auto radiance = cascades.render(*camera);
    EXPECT_TRUE(radiance.ok());
    post::PostOptions finishing = s.post;
    finishing.tone.exposureStops = s.exposure;
    return post::finish(*radiance, finishing);
}

int differentValues(const Image& a, const Image& b) {
    EXPECT_EQ(a.size(), b.size());
    int different = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        different += a.data()[i] != b.data()[i];
    }
    return different;
}

TEST(RendererVoxelCascades, RefractionToggledGivesTheCascadesTheNewLight) {
    const voxel::VoxelWorld world = floorWithGlassBlock();
    RendererVoxel renderer(floorWithGlassBlock(), makeCpuVoxelFrameSource());
    VoxelState s = cascadesState();
    VoxelState copy = s;
    renderer.setState(std::move(copy));
    auto library = voxel::RadianceCascades::create(world, nullptr, s.shading);
    ASSERT_TRUE(library.ok()) << library.error().message();
    const Frame first = renderer.step();
    ASSERT_TRUE(first.note.empty()) << first.note;
    library->iterate();
    const Image refracted = libraryFrame(*library, s);
    EXPECT_EQ(differentValues(first.picture, refracted), 0);
    for (bool refraction : {false, true}) {
        s.shading.refraction = refraction;
        copy = s;
        renderer.setState(std::move(copy));
        const Frame toggled = renderer.step();
        bool relit = false;
        for (const PassTime& p : toggled.passes) relit |= p.name == "cascades light";
        EXPECT_TRUE(relit) << refraction;
        ASSERT_TRUE(library->setLight(s.shading).ok());
        library->iterate();
        const Image expected = libraryFrame(*library, s);
        EXPECT_EQ(differentValues(toggled.picture, expected), 0) << refraction;
        // Without refraction the glass block looks different.
        if (!refraction) {
            EXPECT_GT(differentValues(expected, refracted), 0);
        }
    }
}

}  // namespace
}  // namespace luxel::viewer
