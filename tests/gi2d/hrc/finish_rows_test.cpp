// The finish's rows in vectors against the same pixels one at a time (finish_rows.h): the same
// bits for every combination of neighbours, gates on both sides of the blur's threshold (NaN
// included) and widths that leave vector tails.
#include "gi2d/hrc/finish_rows.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <vector>

#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

TEST(HrcFinishRows, VectorsMatchThePixelsToTheBit) {
    Pcg32 rng(3);
    auto values = [&](int n, float scale) {
        std::vector<float> v(static_cast<std::size_t>(n));
        for (float& f : v) f = scale * rng.nextFloat();
        return v;
    };
    for (const int w : {1, 2, 3, 17, 64, 101}) {
        const std::vector<float> current = values(3 * w, 5), above = values(3 * w, 5),
                                 below = values(3 * w, 5), t = values(3 * w, 1),
                                 emission = values(3 * w, 2);
        // Gates near one another, so that |difference| falls on both sides of 0.1.
        std::vector<float> gates[3];
        for (auto& g : gates) {
            g = values(w, 0.3f);
            if (w > 5) g[5] = std::numeric_limits<float>::quiet_NaN();
        }
        for (int variant = 0; variant < 8; ++variant) {
            FinishRow row;
            row.current = current.data();
            row.blur = (variant & 1) != 0;
            row.above = (variant & 2) != 0 ? above.data() : nullptr;
            row.below = (variant & 4) != 0 ? below.data() : nullptr;
            row.opacityAbove = gates[0].data();
            row.opacityHere = gates[1].data();
            row.opacityBelow = gates[2].data();
            row.transmittance = t.data();
            row.emission = emission.data();
            row.width = w;
            row.frustums = variant == 6 ? 2.0f : 4.0f;
            std::vector<float> vectors(3 * w, -1.0f), pixels(3 * w, -2.0f);
            finishRow(row, vectors.data());
            finishPixels(row, 0, w, pixels.data());
            EXPECT_EQ(std::memcmp(vectors.data(), pixels.data(), vectors.size() * sizeof(float)), 0)
                << "width " << w << ", variant " << variant;
        }
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
