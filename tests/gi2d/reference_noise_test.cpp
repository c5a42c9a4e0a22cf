// The reference solver's default ray count is enough: two seeds differ by < 1% RMSE of the mean on
// every shipped scene. Also: results do not depend on the thread count.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "gi2d/shipped_scenes.h"
#include "luxel/core/metrics.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d {
namespace {

using testing_support::shippedScene;

class ReferenceNoise : public testing::TestWithParam<const char*> {};

TEST_P(ReferenceNoise, TwoSeedsAgreeWithinOnePercentAtTheDefaultRayCount) {
    const Medium2D medium = shippedScene(GetParam(), 96, 96);
    ReferenceOptions a, b;
    b.seed = a.seed + 1;
    const Image fa = solveReference(medium, a).value();
    const Image fb = solveReference(medium, b).value();
    const ImageErrors e = compareImages(fa, fb).value();
    std::printf("%s: RMSE between seeds = %.3f%% of mean %.4f (%d rays)\n", GetParam(),
                100.0 * e.rmse / e.meanReference, e.meanReference, a.rays);
    EXPECT_LT(e.rmse, 0.01 * e.meanReference);
    EXPECT_GT(e.rmse, 0.0) << "different seeds must give different jitter";
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, ReferenceNoise,
                         testing::Values("penumbra.json", "pinhole.json", "room.json", "fog.json",
                                         "thin-walls.json", "many-lights.json"),
                         [](const auto& param) {
                             return testing_support::sceneTestName(param.param);
                         });

TEST(ReferenceDeterminism, SameImageForAnyThreadCount) {
    const Medium2D medium = shippedScene("many-lights.json", 96, 72);
    ReferenceOptions options;
    options.rays = 64;
    Image images[3];
    const int threads[3] = {1, 2, 3};
    for (int i = 0; i < 3; ++i) {
        ThreadLimit limit(threads[i]);
        images[i] = solveReference(medium, options).value();
    }
    EXPECT_TRUE(images[0] == images[1]);
    EXPECT_TRUE(images[0] == images[2]);
}

TEST(ReferenceSolver, RejectsBadRayCounts) {
    const Medium2D medium = shippedScene("penumbra.json", 16, 16);
    ReferenceOptions options;
    options.rays = 0;
    auto r = solveReference(medium, options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message().find("rays must be in 1.."), std::string::npos);
}

}  // namespace
}  // namespace luxel::gi2d
