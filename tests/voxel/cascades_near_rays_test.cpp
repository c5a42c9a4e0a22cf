// The picture's near emitters cast their visibility lines once for both terms
// (src/voxel/cascades/cascade_near_rays.h; docs/algorithms/voxel-radiance-cascades.md §5):
// nearEmitterLight and nearEmitterHighlight reading one NearEmitterRays give exactly what each
// gives casting its own lines, with fewer lines cast. On the shipped thin-walls scene (one lamp,
// walls around it, glossy default blocks) and on a floor of lamps whose faces have more near
// emitters than NearEmitterRays keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "luxel/voxel/render_image.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/voxel_scene.h"
#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_near_rays.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/path_trace_surface.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::cascades;
using namespace luxel::voxel::test;

struct Tally {
    int nearPixels = 0;     // pixels whose surface has near emitters and some of their light
    int highlighted = 0;    // of those, pixels with a highlight
    long sharedCast = 0;    // lines cast by one NearEmitterRays for both terms
    long separateCast = 0;  // lines cast by one for each term
};

// Every pixel's near light and highlight, shared and separate, which must be equal to the bit.
Tally compareOverThePicture(const RadianceCascades::State& state, const Camera& camera) {
    Tally tally;
    const ShadeOptions& shading = state.shading;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = pixelSampleRay(camera, x, y, 0, 1);
            const SurfaceHit s = castToSurface(*state.world, state.textures, ray, shading.stepCap);
            if (!s.hit.hit || s.hit.normal == Int3{}) continue;
            // The specular-only lobe shadeSolverSurface gives the highlight.
            const PathSurface surface = pathSurfaceAt(*state.world, s, shading);
            const PathBsdf specular =
                specularLobe(pathBsdf(*surface.material, surface.albedo, s.hit.normal,
                                      normalize(ray.direction), shading));

            NearEmitterRays shared(state, s.hit);
            const Rgb light = nearEmitterLight(state, shared);
            const Rgb highlight = nearEmitterHighlight(state, shared, specular);
            NearEmitterRays forLight(state, s.hit), forHighlight(state, s.hit);
            const Rgb ownLight = nearEmitterLight(state, forLight);
            const Rgb ownHighlight = nearEmitterHighlight(state, forHighlight, specular);
            // The plain entry points cast their own lines too.
            const Rgb aloneLight = nearEmitterLight(state, s.hit);
            const Rgb aloneHighlight = nearEmitterHighlight(state, s.hit, specular);
            for (int c = 0; c < 3; ++c) {
                if (light[c] != ownLight[c] || highlight[c] != ownHighlight[c] ||
                    light[c] != aloneLight[c] || highlight[c] != aloneHighlight[c]) {
                    ADD_FAILURE() << "pixel " << x << "," << y << " channel " << c << ": light "
                                  << light[c] << " against " << ownLight[c] << " and "
                                  << aloneLight[c] << ", highlight " << highlight[c] << " against "
                                  << ownHighlight[c] << " and " << aloneHighlight[c];
                    return tally;
                }
            }
            if (light.maxComponent() > 0.0f) ++tally.nearPixels;
            if (highlight.maxComponent() > 0.0f) ++tally.highlighted;
            tally.sharedCast += shared.cast();
            tally.separateCast += forLight.cast() + forHighlight.cast();
        }
    }
    return tally;
}

TEST(CascadesNearRays, SharedLinesGiveTheSameLightAndHighlightOnThinWalls) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/thin-walls.json", 160, 90);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const auto state = buildCascadeState(scene->world, &scene->textures, scene->shading);
    ASSERT_FALSE(state->faces.nearEmitters.empty());
    const Tally tally = compareOverThePicture(*state, scene->camera);
    EXPECT_GT(tally.nearPixels, 100);
    EXPECT_GT(tally.highlighted, 100);
    // Every line the light casts, the highlight casts too: sharing saves them all.
    EXPECT_LT(tally.sharedCast, tally.separateCast);
    EXPECT_GT(tally.separateCast - tally.sharedCast, tally.sharedCast / 2);
}

TEST(CascadesNearRays, SharedLinesGiveTheSameLightPastTheKeptEmitters) {
    // A 6x6 patch of lamps hung two voxels over a glossy floor in a closed room: the floor under
    // it has far more than 16 near emitting faces (the lamps' undersides within 4 voxels), so
    // the lines past the kept ones are cast at every ask, and must still agree.
    VoxelWorld world = makeWorld({20, 8, 20});
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    ASSERT_TRUE(o.materials.setSlot(0, lampMaterial(Rgb(4.0f, 3.0f, 2.0f))).ok());
    ASSERT_TRUE(o.materials.setSlot(1, polishedFloor(0.3f)).ok());
    for (int z = 0; z < 20; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 20; ++x) {
                if (y == 0) {
                    world.set(x, y, z, Voxel{255, 255, 255, alphaForSlot(1)});
                } else if (x == 0 || z == 0 || x == 19 || y == 7 || z == 19) {
                    world.set(x, y, z, kWhite);
                }
            }
    for (int z = 7; z < 13; ++z)
        for (int x = 7; x < 13; ++x) world.set(x, 3, z, Voxel{255, 255, 255, alphaForSlot(0)});
    world.refreshEmptySpace();
    const auto state = buildCascadeState(world, nullptr, o);
    const FaceData& faces = state->faces;
    std::uint32_t longest = 0;
    for (std::size_t f = 0; f + 1 < faces.nearOffset.size(); ++f) {
        longest = std::max(longest, faces.nearOffset[f + 1] - faces.nearOffset[f]);
    }
    ASSERT_GT(longest, 16u);
    const Camera camera = *Camera::lookAt({3.5, 5.5, 3.5}, {10.0, 1.0, 10.0}, 70.0, 64, 48);
    const Tally tally = compareOverThePicture(*state, camera);
    EXPECT_GT(tally.nearPixels, 100);
    EXPECT_GT(tally.highlighted, 100);
    EXPECT_LT(tally.sharedCast, tally.separateCast);
}

}  // namespace
