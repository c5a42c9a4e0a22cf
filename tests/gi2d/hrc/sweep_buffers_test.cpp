// The streaming HRC solver's buffers (docs/algorithms/holographic-radiance-cascades.md §7.1,
// §8.1): the estimates are what they allocate.
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/sweep_buffers.h"
#include "gi2d/hrc/sweep_solver.h"

namespace luxel::gi2d::hrc {
namespace {

// Frame shapes: square, long, tall, odd, a single cascade.
const std::pair<int, int> kShapes[] = {{1024, 1024}, {130, 64}, {97, 61}, {40, 300},
                                       {17, 5},      {16, 9},   {2, 3}};

TEST(SweepBuffers, EstimatesAreWhatTheBuffersAllocate) {
    for (const auto& [length, rows] : kShapes) {
        const int levels = cascadeCount(length);
        IntervalRing tables;
        tables.reshape(levels, rows, kSweepChunk);
        EXPECT_EQ(tables.bytes(), IntervalRing::bytesFor(levels, rows, kSweepChunk))
            << length << "x" << rows;
        ConeRing cones;
        cones.reshape(levels, rows, kSweepChunk);
        EXPECT_EQ(cones.bytes(), ConeRing::bytesFor(levels, rows, kSweepChunk))
            << length << "x" << rows;

        // A member loading rows [v0, v1) of every column, with 3 lengths and a span of 4.
        const Medium2D medium{Image(length, rows, 3), Image(length, rows, 3), Rgb()};
        const FrustumFrame frame = makeFrame(Frustum::PlusX, length, rows);
        ColumnWindow window;
        window.reshape(4, {0.5f, 1.0f, 1.25f}, rows);
        const int v0 = rows / 3, v1 = rows;
        for (int x = length - 1; x >= 0; --x) window.load(medium, frame, x, v0, v1);
        EXPECT_LE(window.bytes(), ColumnWindow::bytesFor(4, 3, rows, v1 - v0))
            << length << "x" << rows;
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
