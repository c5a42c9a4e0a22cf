// The compact lights' groups (docs/algorithms/holographic-radiance-cascades.md §12.5) against a
// brute-force labelling: random blobs and long snakes that join some of them into groups too
// large to be compact lights.
#include "gi2d/hrc/compact_lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

struct Group {
    std::vector<std::uint32_t> pixels;  // ascending
    int x0, y0, x1, y1;
    float score = 0;
};

// 8-connected groups of emitting pixels by repeated relabelling to the least neighbour label
// until nothing changes: slow, and nothing like the search's order of work.
std::vector<Group> bruteForceGroups(const Medium2D& m, const LightScores& scores) {
    const int w = m.width(), h = m.height();
    std::vector<int> label(static_cast<std::size_t>(w) * h, -1);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Rgb e = m.emission.rgb(x, y), t = m.absorption.rgb(x, y);
            bool emits = false;  // E (1 - exp(-sigma)) > 0 in some channel
            for (int c = 0; c < 3; ++c) emits = emits || e[c] * (1.0f - std::exp(-t[c])) > 0.0f;
            if (emits) label[static_cast<std::size_t>(y) * w + x] = y * w + x;
        }
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                int& l = label[static_cast<std::size_t>(y) * w + x];
                if (l < 0) continue;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        const int n = label[static_cast<std::size_t>(ny) * w + nx];
                        if (n >= 0 && n < l) l = n, changed = true;
                    }
                }
            }
        }
    }
    std::map<int, Group> groups;  // by least index: the search's order before its sort
    for (int i = 0; i < w * h; ++i) {
        if (label[static_cast<std::size_t>(i)] < 0) continue;
        auto [it, added] = groups.try_emplace(label[static_cast<std::size_t>(i)]);
        Group& g = it->second;
        const int x = i % w, y = i / w;
        if (added) g.x0 = g.x1 = x, g.y0 = g.y1 = y;
        g.x0 = std::min(g.x0, x), g.x1 = std::max(g.x1, x);
        g.y0 = std::min(g.y0, y), g.y1 = std::max(g.y1, y);
        g.pixels.push_back(static_cast<std::uint32_t>(i));
        g.score = std::max(g.score, scores.at(static_cast<std::size_t>(i)));
    }
    std::vector<Group> out;
    for (auto& [least, g] : groups) out.push_back(std::move(g));
    return out;
}

TEST(HrcCompactLights, GroupsMatchABruteForceLabelling) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const int w = 150, h = 110;
        Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb{}};
        for (std::size_t i = 0; i < m.absorption.size(); ++i) m.absorption.data()[i] = 1.0f;
        Pcg32 rng(seed);
        auto emit = [&](int x, int y, float e) {
            if (x >= 0 && y >= 0 && x < w && y < h) m.emission.setRgb(x, y, {e, e * 0.5f, e});
        };
        // Blobs of 1-10 px across, some dim (no light), then snakes that wander far.
        for (int b = 0; b < 70; ++b) {
            const int cx = static_cast<int>(rng.next() % w), cy = static_cast<int>(rng.next() % h);
            const int r = 1 + static_cast<int>(rng.next() % 5);
            const float e = rng.nextFloat() < 0.2f ? 0.01f : 1.0f + 9.0f * rng.nextFloat();
            for (int y = cy - r; y <= cy + r; ++y) {
                for (int x = cx - r; x <= cx + r; ++x) {
                    if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) emit(x, y, e);
                }
            }
        }
        for (int s = 0; s < 6; ++s) {
            int x = static_cast<int>(rng.next() % w), y = static_cast<int>(rng.next() % h);
            for (int step = 0; step < 120; ++step) {
                emit(x, y, 2.0f);
                x += static_cast<int>(rng.next() % 3) - 1;
                y += static_cast<int>(rng.next() % 3) - 1;
            }
        }
        // Pixels whose emission only the exponentials tell: sigma 1e-8 (exp rounds to 1, so they
        // do not emit) and 1e-7 (they do), some inside blobs, some bridging them.
        for (int k = 0; k < 200; ++k) {
            const int x = static_cast<int>(rng.next() % w), y = static_cast<int>(rng.next() % h);
            const float tiny = k % 2 == 0 ? 1e-8f : 1e-7f;
            m.absorption.setRgb(x, y, {tiny, tiny, tiny});
            if (m.emission.at(x, y, 0) == 0.0f) m.emission.setRgb(x, y, {2.0f, 2.0f, 2.0f});
        }
        const LightScores scores = LightScores::of(m);
        const float threshold = lightScoreThreshold(scores.brightest());
        std::vector<Group> expected;
        int large = 0;
        for (Group& g : bruteForceGroups(m, scores)) {
            const bool small =
                g.x1 - g.x0 < kCompactLightMaxSize && g.y1 - g.y0 < kCompactLightMaxSize;
            large += small ? 0 : 1;
            if (!small || !(g.score >= threshold)) continue;
            // A share above 0: the RMS radius of the emission about its centroid below
            // kCompactNoneRadius (the blobs' emission is even in each, 1 - exp(-1) of E).
            double weight = 0, mx = 0, my = 0, mxx = 0;
            for (const std::uint32_t i : g.pixels) {
                const double x = i % w + 0.5, y = i / w + 0.5, e = m.emission.data()[i * 3];
                weight += e, mx += e * x, my += e * y, mxx += e * (x * x + y * y);
            }
            mx /= weight, my /= weight;
            if (std::sqrt(std::max(0.0, mxx / weight - mx * mx - my * my)) <
                kCompactNoneRadius - 1e-9)
                expected.push_back(std::move(g));
        }
        std::stable_sort(expected.begin(), expected.end(),
                         [](const Group& a, const Group& b) { return a.score > b.score; });
        EXPECT_GT(large, 2) << seed;  // the snakes made some
        // The emitting pixels told by the search itself, and taken from the scores' codes.
        for (const bool coded : {false, true}) {
            LightScores given = LightScores::of(m, coded);
            const std::vector<CompactLight> found = findCompactLights(m, given);
            EXPECT_EQ(given.takeEmitting(), nullptr);  // taken by the search, where made
            ASSERT_EQ(found.size(), expected.size()) << seed << " " << coded;
            for (std::size_t k = 0; k < found.size(); ++k) {
                EXPECT_EQ(found[k].pixels, expected[k].pixels) << seed << " " << k;
                EXPECT_EQ(found[k].x0, expected[k].x0);
                EXPECT_EQ(found[k].y1, expected[k].y1);
                EXPECT_EQ(found[k].score, expected[k].score);
            }
        }
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
