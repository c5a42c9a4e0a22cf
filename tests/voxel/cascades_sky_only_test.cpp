// Faces whose every chain leaves the world at once (FaceData::skyOnly,
// docs/algorithms/voxel-radiance-cascades.md §5) take their normal's sky irradiance instead of
// gathering bin by bin: every face on the world's outer sides is one, a face looking into the
// world is not, and a pass gives the light the bin-by-bin gather gives, within float rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::cascades;
using namespace luxel::voxel::test;

// Whether the cell the face looks into lies outside the world.
bool looksOutOfTheWorld(const VoxelWorld& world, const Face& face) {
    const Int3 n = normalFromIndex(face.normal);
    return !world.inside(face.voxel.x + n.x, face.voxel.y + n.y, face.voxel.z + n.z);
}

// Irradiance after `passes` passes with the sky-only faces as found, and gathered bin by bin: the
// same within float rounding (relative to the brightest channel of the face).
void expectTheLightOfTheBinByBinGather(RadianceCascades::State& fast,
                                       RadianceCascades::State& binByBin, int passes) {
    binByBin.faces.skyOnly.assign(binByBin.faces.skyOnly.size(), 0);
    expectSameLightAfterPasses(fast, binByBin, passes, 2e-6f);
}

TEST(CascadesSkyOnly, FacesOnTheWorldsOuterSidesGatherTheSkyOnce) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto fast = buildCascadeState(scene->world, &scene->textures, scene->shading);
    auto binByBin = buildCascadeState(scene->world, &scene->textures, scene->shading);
    const FaceData& faces = fast->faces;
    ASSERT_EQ(faces.skyOnly.size(), std::size_t(faces.table.size()));
    int outward = 0, inward = 0, skyOnlyInward = 0;
    for (int f = 0; f < faces.table.size(); ++f) {
        if (looksOutOfTheWorld(scene->world, faces.table[f])) {
            ++outward;
            EXPECT_EQ(faces.skyOnly[f], 1) << f;
        } else {
            ++inward;
            skyOnlyInward += faces.skyOnly[f];
        }
    }
    EXPECT_GT(outward, 100);                // the ground's underside and its edges
    EXPECT_LT(skyOnlyInward, inward / 10);  // the cottage's faces see the cottage
    expectTheLightOfTheBinByBinGather(*fast, *binByBin, 3);
}

TEST(CascadesSkyOnly, AFloorAtTheTopOfTheWorldGathersPiTimesAUniformSky) {
    // One voxel high: the floor's top faces look out of the world, like its underside.
    VoxelWorld world = makeWorld({32, 1, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) world.set(x, 0, z, kWhite);
    world.refreshEmptySpace();
    const Rgb sky(0.8f, 0.9f, 1.0f);
    const ShadeOptions shading = plainLight(0.5f, Rgb(0.0f), sky);  // no sun
    auto fast = buildCascadeState(world, nullptr, shading);
    auto binByBin = buildCascadeState(world, nullptr, shading);
    lightingPass(*fast);
    const FaceData& faces = fast->faces;
    int up = 0;
    for (int f = 0; f < faces.table.size(); ++f) {
        EXPECT_EQ(faces.skyOnly[f], 1) << f;
        if (faces.table[f].normal != normalIndex({0, 1, 0})) continue;
        ++up;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(faces.irradiance[f][c], float(M_PI) * sky[c], 1e-4f * sky[c]) << f;
        }
    }
    EXPECT_EQ(up, 32 * 32);
    expectTheLightOfTheBinByBinGather(*fast, *binByBin, 2);
}

}  // namespace
