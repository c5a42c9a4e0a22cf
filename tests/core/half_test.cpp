// binary16 conversions: exact against the compiler's _Float16 where it has one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "luxel/core/half.h"

namespace luxel {
namespace {

TEST(Half, KnownValues) {
    EXPECT_EQ(floatToHalf(0.0f), 0x0000);
    EXPECT_EQ(floatToHalf(-0.0f), 0x8000);
    EXPECT_EQ(floatToHalf(1.0f), 0x3c00);
    EXPECT_EQ(floatToHalf(-2.0f), 0xc000);
    EXPECT_EQ(floatToHalf(65504.0f), 0x7bff);
    EXPECT_EQ(floatToHalf(1e6f), 0x7c00);      // overflow -> inf
    EXPECT_EQ(floatToHalf(0x1p-24f), 0x0001);  // smallest subnormal
    EXPECT_EQ(halfToFloat(0x3555), 0.333251953125f);
    EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(NAN))));
}

TEST(Half, EveryHalfRoundTrips) {
    for (unsigned h = 0; h < 65536; ++h) {
        const float f = halfToFloat(static_cast<std::uint16_t>(h));
        if (std::isnan(f)) continue;
        ASSERT_EQ(floatToHalf(f), h) << std::hex << h;
    }
}

#ifdef __FLT16_MAX__
TEST(Half, RoundsLikeTheCompiler) {
    std::uint32_t state = 1;
    for (int i = 0; i < 2000000; ++i) {
        state = state * 1664525u + 1013904223u;
        const float f = std::bit_cast<float>(state);
        if (std::isnan(f)) continue;
        const auto expected = std::bit_cast<std::uint16_t>(static_cast<_Float16>(f));
        ASSERT_EQ(floatToHalf(f), expected) << f;
    }
}
#endif

}  // namespace
}  // namespace luxel

namespace luxel {
namespace {

TEST(Half, BulkConversionsMatchTheScalarOnes) {
    std::vector<float> values;
    std::uint32_t state = 3;
    for (int i = 0; i < 10007; ++i) {
        state = state * 1664525u + 1013904223u;
        const float f = std::bit_cast<float>(state);
        values.push_back(std::isnan(f) ? 1.0f : f);
    }
    std::vector<std::uint16_t> halves(values.size());
    floatsToHalves(values.data(), halves.data(), values.size());
    std::vector<float> back(values.size());
    halvesToFloats(halves.data(), back.data(), halves.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        ASSERT_EQ(halves[i], floatToHalf(values[i])) << values[i];
        ASSERT_EQ(std::bit_cast<std::uint32_t>(back[i]),
                  std::bit_cast<std::uint32_t>(halfToFloat(halves[i])));
    }
    std::printf("bulk half conversion uses %s\n",
                hasHardwareHalfConversion() ? "F16C" : "software");
}

}  // namespace
}  // namespace luxel
