// The level-by-level passes' cone storage (src/gi2d/hrc/cone_merge.h): binary16 in the layout the
// GPU's hrc_merge writes (src/gpu/shaders/shared/hrc_layout.h), so uploads and readbacks are
// plain copies. Checked here without a GPU; HrcPasses.* checks it against the shaders.
#include <gtest/gtest.h>

#include "gi2d/hrc/cone_merge.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/half.h"

namespace luxel::gi2d::hrc {
namespace {

TEST(ConeBuffer, StoresBinary16InTheGpuLayout) {
    ConeBuffer cones;
    const int planes = 3, count = 2, rows = 5;  // an odd row count: one padding row per plane
    cones.reset(planes, count, rows);
    ASSERT_EQ(cones.halves().size(), static_cast<std::size_t>(planes * count * 3 * 6));
    EXPECT_EQ(ConeBuffer::bytesFor(planes, count, rows), cones.halves().size_bytes());
    for (int p = 0; p < planes; ++p) {
        for (int i = 0; i < count; ++i) {
            for (int y = 0; y < rows; ++y) {
                cones.set(p, i, y, Rgb(p + 0.1f * i + 0.01f * y, 1.0f / 3.0f, 70.123f * (y + 1)));
            }
        }
    }
    for (int p = 0; p < planes; ++p) {
        for (int i = 0; i < count; ++i) {
            for (int y = 0; y < rows; ++y) {
                const Rgb stored = cones.at(p, i, y);
                const float values[3] = {p + 0.1f * i + 0.01f * y, 1.0f / 3.0f, 70.123f * (y + 1)};
                const float read[3] = {stored.r, stored.g, stored.b};
                for (std::uint32_t c = 0; c < 3; ++c) {
                    // Rounded once to the nearest half, where the shader's layout puts it.
                    EXPECT_EQ(read[c], halfToFloat(floatToHalf(values[c])));
                    const std::uint32_t at = gpu::shared::hrcConeHalf(
                        std::uint32_t(p), std::uint32_t(count), std::uint32_t(i), c,
                        std::uint32_t(y), std::uint32_t(rows));
                    EXPECT_EQ(cones.halves()[at], floatToHalf(values[c]));
                }
                // One binary16 step at most: 2^-11 of the value.
                EXPECT_NEAR(stored.b, 70.123f * (y + 1), 70.123f * (y + 1) * 0x1p-11f);
            }
        }
    }
    // The padding row of every channel plane stays zero, as hrc_merge writes it.
    for (std::uint32_t plane = 0; plane < std::uint32_t(planes * count * 3); ++plane) {
        EXPECT_EQ(cones.halves()[plane * 6 + 5], 0u) << plane;
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
