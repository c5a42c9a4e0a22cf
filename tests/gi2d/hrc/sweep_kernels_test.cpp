// The streaming HRC solver's row kernels (docs/algorithms/holographic-radiance-cascades.md §7.1)
// against plain float arithmetic in the same order.
#include "gi2d/hrc/sweep_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "luxel/core/half.h"
#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

// A traced ray behind opaque cells (sigma 50 per pixel: t about e^-50) multiplies transmittances
// below the smallest normal float. The kernel flushes those to zero (its time went to subnormal
// assists); the binary16 intervals it stores must be the bits unflushed floats give.
TEST(SweepKernels, TraceBehindOpaqueCellsStoresWhatUnflushedFloatsGive) {
    constexpr int kRows = 200, kSteps = 6, kStride = kRows + 2 * kSweepRowPad;
    Pcg32 rng(7);
    // One transfer column per step, rows offset by kSweepRowPad so steps may look one row up.
    std::vector<std::vector<float>> planes(kSteps * 6, std::vector<float>(kStride, 0.0f));
    std::vector<CellTransfer> cells(kSteps);
    std::vector<TraceStep> steps;
    for (int s = 0; s < kSteps; ++s) {
        for (int y = 0; y < kStride; ++y) {
            // Opaque runs of varying length along the ray, so rows cross 0 to 6 opaque cells.
            const bool opaque = ((y * 7 + s * 3) % 11) < 6;
            const float length = 0.7f + 0.1f * static_cast<float>(s % 4);
            for (int c = 0; c < 3; ++c) {
                const float sigma = opaque ? 50.0f + 10.0f * c : 0.0005f;
                const float t = std::exp(-sigma * length);
                planes[s * 6 + c][y] = t;
                planes[s * 6 + 3 + c][y] = rng.nextFloat() * 4.0f * (1.0f - t);
            }
        }
        for (int c = 0; c < 6; ++c) cells[s].plane[c] = planes[s * 6 + c].data() + kSweepRowPad;
        steps.push_back({s, s % 3 - 1});
    }
    std::vector<std::vector<std::uint16_t>> out(6,
                                                std::vector<std::uint16_t>(kRows + kSweepRowPad));
    IntervalRowsOut rows;
    for (int c = 0; c < 6; ++c) rows.plane[c] = out[c].data();
    traceRows(steps, cells.data(), rows, 3, kRows);

    int subnormalProducts = 0;
    for (int y = 3; y < kRows; ++y) {
        for (int c = 0; c < 3; ++c) {
            float l = 0.0f, t = 1.0f;  // Eq 8, front to back, as the kernel orders it
            for (const TraceStep& step : steps) {
                const int row = y + step.dv;
                l = l + t * cells[step.column].plane[3 + c][row];
                t = t * cells[step.column].plane[c][row];
                subnormalProducts += std::fpclassify(t) == FP_SUBNORMAL ? 1 : 0;
            }
            ASSERT_EQ(out[c][y], floatToHalf(l)) << "row " << y << " channel " << c;
            ASSERT_EQ(out[3 + c][y], floatToHalf(t)) << "row " << y << " channel " << c;
        }
    }
    EXPECT_GT(subnormalProducts, 100);  // the case the flush is for does occur here

    // The flush ends with the call: this thread's floats keep their subnormals.
    volatile float tiny = 1e-30f;
    EXPECT_EQ(std::fpclassify(tiny * 1e-10f), FP_SUBNORMAL);
}

}  // namespace
}  // namespace luxel::gi2d::hrc
