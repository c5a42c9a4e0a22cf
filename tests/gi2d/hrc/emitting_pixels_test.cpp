// The emitting pixels of the compact lights' search (§12.5): the vectors' sure answers against
// E (1 - exp(-sigma)) > 0 computed per channel as the search's exponentials do.
#include "gi2d/hrc/emitting_pixels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

bool emitsByExponentials(const float* e, const float* s) {
    for (int c = 0; c < 3; ++c) {
        if (e[c] * (1.0f - std::exp(-s[c])) > 0.0f) return true;
    }
    return false;
}

TEST(HrcEmittingPixels, SureAnswersMatchTheExponentials) {
    // Values on both sides of the sure bounds, tiny and huge, of both signs, NaN and infinity,
    // drawn per channel; 1000 pixels leave a tail after the vectors.
    const float inf = std::numeric_limits<float>::infinity();
    const float values[] = {0.0f,
                            -0.0f,
                            1e-6f,
                            9.9e-7f,
                            1e-30f,
                            9e-31f,
                            1e-40f,
                            3e-8f,
                            1e-7f,
                            0.5f,
                            1.0f,
                            64.0f,
                            -1e-6f,
                            -2.0f,
                            -1e-30f,
                            1e30f,
                            inf,
                            -inf,
                            std::numeric_limits<float>::quiet_NaN()};
    const int n = static_cast<int>(std::size(values));
    const int width = 1000;
    std::vector<float> emission(width * 3), sigma(width * 3);
    Pcg32 rng(11);
    for (int i = 0; i < width * 3; ++i) {
        emission[i] = values[rng.next() % n];
        sigma[i] = values[rng.next() % n];
    }
    std::vector<std::uint8_t> state(width, 7);
    const int unsure = emittingRow(emission.data(), sigma.data(), width, state.data());
    int twos = 0, ones = 0;
    for (int x = 0; x < width; ++x) {
        const float* e = &emission[3 * x];
        const float* s = &sigma[3 * x];
        const bool emits = emitsByExponentials(e, s);
        ASSERT_LE(state[x], 2) << x;
        if (state[x] == 1) {
            EXPECT_TRUE(emits) << x;
        } else if (state[x] == 0) {
            EXPECT_FALSE(emits) << x;
        }
        twos += state[x] == 2 ? 1 : 0;
        ones += state[x] == 1 ? 1 : 0;
    }
    EXPECT_EQ(unsure, twos);
    EXPECT_GT(ones, 100);  // the sure answers are most of the emitting pixels
    EXPECT_GT(twos, 10);
}

}  // namespace
}  // namespace luxel::gi2d::hrc
