// The stencil walks' steps across uniform squares (docs/algorithms/radiance-cascades-2d.md §8):
// the radius every pixel reports, and the pass on media made of large uniform rectangles
// (fog of several densities, glowing fog, opaque walls, vacuum) that touch the canvas edges,
// against the exact pass over RayMarcher, cascade by cascade, with a sky behind; and the same
// image on any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_stencil.h"
#include "gi2d/rc/stencil_vs_exact.h"
#include "luxel/core/parallel.h"
#include "luxel/core/rng.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {
namespace {

// Rectangles of random size and place (some reach past the border) painted over a fog, each
// one of a few materials; `grey` keeps every absorption equal in its channels.
Medium2D blockMedium(int w, int h, std::uint64_t seed, bool grey) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb(0.4f, 0.7f, 1.0f)};
    struct Material {
        Rgb sigma, emission;
    };
    const Rgb tint = grey ? Rgb(1.0f) : Rgb(1.0f, 0.5f, 2.0f);
    const std::vector<Material> materials = {
        {Rgb(0.0f), Rgb(0.0f)},                      // vacuum
        {Rgb(0.01f) * tint, Rgb(0.0f)},              // thin fog
        {Rgb(0.15f) * tint, Rgb(0.0f)},              // dense fog
        {Rgb(0.08f) * tint, Rgb(1.5f, 0.6f, 0.2f)},  // glowing fog
        {Rgb(50.0f), Rgb(0.0f)},                     // opaque wall
        {Rgb(50.0f), Rgb(0.2f, 2.0f, 0.5f)},         // opaque emitter
        {Rgb(0.6f) * tint, Rgb(0.0f)},               // nearly opaque
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) m.absorption.setRgb(x, y, materials[1].sigma);
    }
    Pcg32 rng(seed);
    for (int r = 0; r < 14; ++r) {
        const int x0 = static_cast<int>(rng.nextFloat() * (w + 20)) - 10;
        const int y0 = static_cast<int>(rng.nextFloat() * (h + 20)) - 10;
        const int x1 = x0 + 4 + static_cast<int>(rng.nextFloat() * w * 0.5f);
        const int y1 = y0 + 4 + static_cast<int>(rng.nextFloat() * h * 0.5f);
        const Material& mat = materials[static_cast<std::size_t>(rng.nextFloat() * 7) % 7];
        for (int y = std::max(y0, 0); y < std::min(y1, h); ++y) {
            for (int x = std::max(x0, 0); x < std::min(x1, w); ++x) {
                m.absorption.setRgb(x, y, mat.sigma);
                m.emission.setRgb(x, y, mat.emission);
            }
        }
    }
    return m;
}

TEST(RcStencilSkip, UniformRadiusIsTheLargestUniformSquareOnTheCanvas) {
    for (bool grey : {true, false}) {
        const Medium2D medium = blockMedium(53, 41, 7, grey);
        const StencilMedium stencil(medium);
        const int w = medium.width(), h = medium.height();
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                // Brute force: grow the square while it stays on the canvas and uniform.
                int r = 0;
                for (;; ++r) {
                    const int n = r + 1;
                    bool uniform = x - n >= 0 && y - n >= 0 && x + n < w && y + n < h;
                    for (int dy = -n; dy <= n && uniform; ++dy) {
                        for (int dx = -n; dx <= n && uniform; ++dx) {
                            uniform = stencil.id(x + dx, y + dy) == stencil.id(x, y);
                        }
                    }
                    if (!uniform) break;
                }
                ASSERT_EQ(stencil.uniformRadius()[static_cast<std::size_t>(y) * w + x], r)
                    << "pixel " << x << ", " << y;
            }
        }
    }
}

TEST(RcStencilSkip, CrossingUniformSquaresMatchesTheExactPass) {
    struct Case {
        std::string name;
        Medium2D medium;
    };
    std::vector<Case> media;
    media.push_back({"grey blocks 160x120", blockMedium(160, 120, 3, true)});
    media.push_back({"coloured blocks 131x150", blockMedium(131, 150, 5, false)});
    media.push_back({"grey blocks 200x70", blockMedium(200, 70, 9, true)});
    RcOptions jittered;
    jittered.jitterX = 0.2548776662466927, jittered.jitterY = 0.8196805819961064;
    // A step across a square adds sigma times the summed length where the exact pass adds run
    // by run: both are the same optical depth to float rounding (a few 1e-7 of depths below the
    // 13.8 cutoff), and so is every value. A square crossed into a different material would be
    // off by far more (one cell of dense fog changes a ray's transmittance by 15%).
    for (const Case& m : media) {
        expectStencilMatchesExact(m.medium, RcOptions{}, m.name);
        expectStencilMatchesExact(m.medium, jittered, m.name + ", jittered");
    }
}

// Batches of walks taking turns, squares crossed per group: none of it depends on how the
// probes are split between threads.
TEST(RcStencilSkip, ThreadCountDoesNotChangeTheImage) {
    const Medium2D medium = blockMedium(160, 120, 3, true);
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        RcOptions options;
        options.merge = merge;
        Image first;
        for (int threads : {1, 2, 4}) {
            const ThreadLimit limit(threads);
            Image got = solveRc(medium, options).value();
            if (threads == 1) {
                first = std::move(got);
                continue;
            }
            EXPECT_TRUE(std::equal(got.data(), got.data() + got.size(), first.data()))
                << threads << " threads";
        }
    }
}

}  // namespace
}  // namespace luxel::gi2d::rc
