// Bounce light on the GPU is the same loop around the GPU solves: it matches the CPU loop.
#include <gtest/gtest.h>

#include "gi2d/bounce_media.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "support/gpu_test_context.h"

namespace luxel::gi2d {
namespace {

Image bounced(const Medium2D& medium, const FluenceSolve& solve) {
    BounceOptions options;
    options.maxBounces = 4;
    auto r = solveWithBounces(medium, solve, options);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message());
    return r.ok() ? std::move(r->fluence) : Image();
}

TEST(BounceGpu, HrcAndRcMatchTheCpuLoop) {
    LUXEL_REQUIRE_GPU(context);
    const Medium2D room = test::reflectiveRoom(32);
    const Image hrcCpu = bounced(room, [](const Medium2D& m) { return solveHrc(m); });
    const Image hrcGpu =
        bounced(room, [&](const Medium2D& m) { return solveHrcOnGpu(*context, m); });
    EXPECT_LT(test::relativeL1(hrcGpu, hrcCpu), 0.01);
    const Image rcCpu = bounced(room, [](const Medium2D& m) { return solveRc(m); });
    const Image rcGpu = bounced(room, [&](const Medium2D& m) { return solveRcOnGpu(*context, m); });
    EXPECT_LT(test::relativeL1(rcGpu, rcCpu), 0.01);
    // And bouncing added light.
    const Image once = bounced(Medium2D{room.emission, room.absorption, Rgb()},
                               [](const Medium2D& m) { return solveHrc(m); });
    EXPECT_GT(test::relativeL1(hrcCpu, once), 0.1);
}

}  // namespace
}  // namespace luxel::gi2d
