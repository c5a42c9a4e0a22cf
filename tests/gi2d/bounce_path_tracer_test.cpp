// The converged reference (source iteration through the shared bounce rule) against an
// independent Monte Carlo path tracer through the same pixel medium.
#include <gtest/gtest.h>

#include <cstdio>

#include "bounce_media.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/reference_solver.h"
#include "path_tracer_2d.h"

namespace luxel::gi2d {
namespace {

constexpr int kBlock = 8;

Image converged(const Medium2D& medium) {
    ReferenceOptions ref;
    ref.rays = 512;
    auto r = solveReferenceWithBounces(medium, ref);
    EXPECT_TRUE(r.ok() && r->converged);
    return std::move(r->fluence);
}

// Mean of each kBlock x kBlock block, transparent pixels only (opaque ones read their own
// emission in the reference and are not what the path tracer estimates).
Image blockMeans(const Image& fluence, const Medium2D& medium) {
    Image blocks(fluence.width() / kBlock, fluence.height() / kBlock, 3);
    for (int by = 0; by < blocks.height(); ++by) {
        for (int bx = 0; bx < blocks.width(); ++bx) {
            Rgb sum;
            int n = 0;
            for (int y = by * kBlock; y < (by + 1) * kBlock; ++y) {
                for (int x = bx * kBlock; x < (bx + 1) * kBlock; ++x) {
                    if (medium.absorption.at(x, y, 0) >= 1.0f) continue;
                    sum += fluence.rgb(x, y);
                    ++n;
                }
            }
            blocks.setRgb(bx, by, n > 0 ? sum * (1.0f / n) : Rgb());
        }
    }
    return blocks;
}

Image pathTraced(const Medium2D& medium, int paths, std::uint64_t seed) {
    const test::PathTracer2D tracer(medium);
    Image out(medium.width(), medium.height(), 3);
    parallelForRange(medium.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < medium.width(); ++x) {
                if (medium.absorption.at(x, y, 0) < 1.0f)
                    out.setRgb(x, y, tracer.fluence(x, y, paths, seed));
            }
        }
    });
    return out;
}

struct Agreement {
    double error, noise;
};

// rel-L1 (reference vs path tracer) of the block means, and the path tracer's own noise (two
// seeds against each other, / sqrt 2).
Agreement compare(const char* name, const Medium2D& medium, int paths) {
    const Image reference = blockMeans(converged(medium), medium);
    const Image a = blockMeans(pathTraced(medium, paths, 1), medium);
    const Image b = blockMeans(pathTraced(medium, paths, 2), medium);
    const double noise = test::relativeL1(a, b) / std::sqrt(2.0);
    const double error = test::relativeL1(reference, a);
    std::printf(
        "%s: reference vs path tracer, %dx%d block means: rel-L1 %.4f (path tracer noise "
        "%.4f)\n",
        name, kBlock, kBlock, error, noise);
    return {error, noise};
}

// In fog the model is exact up to the per-pixel discretisation: agreement within the noise
// (1.5 times it) plus 1%.
TEST(BouncePathTracer, FogMatchesReference) {
    const Agreement a = compare("fog", test::fogScene(48), 96);
    EXPECT_LT(a.noise, 0.04);
    EXPECT_LT(a.error, 1.5 * a.noise + 0.01);
}

// Walls: the reference's surface rule estimates the light arriving at a wall from its
// neighbours' fluence (uniform over the half circle, half a pixel off the wall) where a
// Lambertian wall weighs it by the cosine; a looser bound: the noise plus 5%.
TEST(BouncePathTracer, ReflectiveRoomCloseToReference) {
    const Agreement a = compare("room", test::reflectiveRoom(48), 96);
    EXPECT_LT(a.noise, 0.04);
    EXPECT_LT(a.error, 1.5 * a.noise + 0.05);
}

}  // namespace
}  // namespace luxel::gi2d
