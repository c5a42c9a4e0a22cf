// The radiance cascades' picture of a glossy wall far from a small lamp
// (docs/algorithms/voxel-radiance-cascades.md §4.2, "Far lamps in the glossy lobe"): past the near
// term's reach the camera surface's two GGX rays alone drew the lamp's reflection, each that met
// the lamp a sparkle; now the surface light-samples the lamps and weighs both strategies by the
// balance heuristic. The far wall of GlossyWallsRoom: far fewer sparkles, the lobe's integral
// over the lamp as the path tracer finds it (at one sample as at many), and where no lamp can be
// picked, the old picture exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "voxel/glossy_lamp_room.h"
#include "voxel/room_pixels.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

Image picture(const VoxelWorld& world, const ShadeOptions& shading, bool lamps, int samples,
              const Camera& camera) {
    ShadeOptions o = shading;
    o.samplesPerPixel = samples;
    o.adaptiveSamples = 0;  // the estimator itself, not the pass that hides its sparkles
    CascadeOptions options;
    options.glossyEmitters = lamps;
    auto cascades = RadianceCascades::create(world, nullptr, o, options);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    cascades->solve();
    auto image = cascades->render(camera);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return std::move(*image);
}

TEST(CascadesGlossyLamps, AFarLampLeavesNoSparklesOnAGlossyWall) {
    const GlossyWallsRoom room;
    const Camera camera = farWallView();
    const auto wall = farWallPixels(room, camera);
    ASSERT_GT(wall.size(), 800u);
    const Sparkles now = sparkles(picture(room.world, room.o, true, 1, camera), wall, 3.0);
    const Sparkles before = sparkles(picture(room.world, room.o, false, 1, camera), wall, 3.0);
    std::printf(
        "%zu wall pixels over 3x their neighbours' median: %d (largest ratio %.2f), GGX rays "
        "alone %d (%.2f)\n",
        wall.size(), now.count, now.largest, before.count, before.largest);
    EXPECT_GE(before.count, 8);
    EXPECT_LE(now.count * 8, before.count);
    EXPECT_LT(now.largest * 5.0, before.largest);
}

// The wall's mean is the lobe's integral over the lamp: in the black room (only the lamp's glossy
// reflection shows) the path tracer's direct light (one bounce: what the camera surface's lobe
// sees of the lamp), at sixteen samples per pixel within 2% and at one within its noise (about 3%
// over these pixels). The GGX rays alone read low by what the split sum's normalisation costs a
// small light (A(cos_v, alpha) over the weight of the direction that meets it): 3-8% at 16 to 64
// samples, noise on a bias of about 6%.
TEST(CascadesGlossyLamps, TheWallsMeanIsTheLobesIntegralOverTheLamp) {
    const GlossyWallsRoom room(0.0f);
    const Camera camera = farWallView();
    const auto wall = farWallPixels(room, camera);
    ASSERT_GT(wall.size(), 800u);
    PathTraceOptions p;
    p.samplesPerPixel = 1024;
    p.maxBounces = 1;
    auto truth = pathTrace(room.world, camera, room.o, p);
    ASSERT_TRUE(truth.ok()) << truth.error().message();
    const double reference = regionMean(truth->radiance, wall);
    const double one = regionMean(picture(room.world, room.o, true, 1, camera), wall);
    const double many = regionMean(picture(room.world, room.o, true, 16, camera), wall);
    const double before = regionMean(picture(room.world, room.o, false, 64, camera), wall);
    std::printf(
        "wall mean: path (direct) %.5f, picture at 1 sample %.5f (%+.2f%%), at 16 %.5f "
        "(%+.2f%%), GGX rays alone at 64 %.5f (%+.2f%%)\n",
        reference, one, 100 * (one / reference - 1), many, 100 * (many / reference - 1), before,
        100 * (before / reference - 1));
    EXPECT_NEAR(one / reference, 1.0, 0.06);
    EXPECT_NEAR(many / reference, 1.0, 0.02);
    EXPECT_LT(std::abs(many / reference - 1.0), std::abs(before / reference - 1.0));
}

// Where the cells pick no lamp (none lights them: the lamp's emission turned off), the picture
// is the GGX rays' alone, bit for bit.
TEST(CascadesGlossyLamps, WithoutLampsThePictureIsTheOldOne) {
    GlossyWallsRoom room;
    ShadeOptions dark = room.o;
    ASSERT_TRUE(dark.materials.setSlot(0, lampMaterial(Rgb(0.0f))).ok());
    dark.skyTop = dark.skyHorizon = Rgb(0.3f);
    room.world.set(8, 17, 8, Voxel{});  // a hole in the ceiling lets the sky in
    room.world.refreshEmptySpace();
    const Camera camera = farWallView(32, 24);
    const Image now = picture(room.world, dark, true, 1, camera);
    const Image before = picture(room.world, dark, false, 1, camera);
    for (std::size_t i = 0; i < now.size(); ++i) ASSERT_EQ(now.data()[i], before.data()[i]) << i;
}

}  // namespace
