// Temporal upscaling on an analytic world: a textured plane seen by a pinhole camera, rendered
// exactly at any sub-pixel position, so the converged output has a ground truth.
#include "luxel/post/temporal.h"

#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/image_quality.h"
#include "luxel/post/upscale.h"

namespace luxel::post {
namespace {

// The plane z = 20, a checkerboard of 1.3-unit squares with a sinusoidal tint.
Rgb planeColour(Vec3d p) {
    const bool odd =
        (static_cast<int>(std::floor(p.x / 1.3)) + static_cast<int>(std::floor(p.y / 1.3))) & 1;
    const float v = odd ? 0.9f : 0.15f;
    return Rgb(v, v * (0.75f + 0.25f * float(std::sin(p.x))), 0.5f * v);
}

PinholeView lookingAlongZ(Vec3d position, int w, int h) {
    return {position, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, std::tan(0.5), w, h};
}

// A frame at view's size, rays through (x + 0.5 + j.x, y + 0.5 + j.y), box-filtered over
// `supersample`^2 sub-samples when > 1 (the ground truth); depth along the unit rays.
void renderPlane(const PinholeView& view, Vec2d j, int supersample, Image& colour, Image& depth) {
    colour = Image(view.width, view.height, 3);
    depth = Image(view.width, view.height, 1);
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            Rgb sum{};
            for (int sy = 0; sy < supersample; ++sy) {
                for (int sx = 0; sx < supersample; ++sx) {
                    const double ox = supersample > 1 ? (sx + 0.5) / supersample : 0.5 + j.x;
                    const double oy = supersample > 1 ? (sy + 0.5) / supersample : 0.5 + j.y;
                    const Vec3d d = normalize(view.direction(x + ox, y + oy));
                    const double t = (20.0 - view.position.z) / d.z;
                    sum = sum + planeColour(view.position + d * t);
                    if (sx == 0 && sy == 0) depth.at(x, y, 0) = static_cast<float>(t);
                }
            }
            colour.setRgb(x, y, sum * (1.0f / (supersample * supersample)));
        }
    }
}

double psnrAgainstTruth(const Image& image, const PinholeView& full) {
    Image truth, depth;
    renderPlane(full, {0, 0}, 6, truth, depth);
    return psnr(image, truth).value();
}

TEST(PostTemporal, JitterIsHaltonInsideThePixel) {
    EXPECT_DOUBLE_EQ(TemporalUpscaler::jitter(0).x, 0.0);  // Halton(1, 2) = 1/2
    EXPECT_NEAR(TemporalUpscaler::jitter(0).y, 1.0 / 3 - 0.5, 1e-12);
    for (int i = 0; i < 40; ++i) {
        const Vec2d j = TemporalUpscaler::jitter(i);
        EXPECT_GE(j.x, -0.5);
        EXPECT_LT(j.x, 0.5);
        EXPECT_GE(j.y, -0.5);
        EXPECT_LT(j.y, 0.5);
    }
}

TEST(PostTemporal, StaticCameraConvergesBeyondSpatialUpscaling) {
    const int w = 96, h = 64;
    const PinholeView full = lookingAlongZ({0.3, 0.2, 0}, w, h);
    PinholeView low = full;
    low.width = w / 2;
    low.height = h / 2;
    TemporalUpscaler temporal(w, h);
    Image colour, depth;
    renderPlane(low, {0, 0}, 1, colour, depth);
    const double bilinear = psnrAgainstTruth(upscaleBilinear(colour, w, h), full);
    for (int f = 0; f < 16; ++f) {
        const Vec2d j = temporal.nextJitter();
        renderPlane(low, j, 1, colour, depth);
        temporal.accumulate(colour, depth, full, j);
    }
    const double accumulated = psnrAgainstTruth(temporal.output(), full);
    EXPECT_GT(accumulated, bilinear + 3.0)
        << "bilinear " << bilinear << ", temporal " << accumulated;
}

TEST(PostTemporal, ReprojectionFollowsACameraMove) {
    const int w = 96, h = 64;
    TemporalUpscaler temporal(w, h);
    Image colour, depth;
    PinholeView full = lookingAlongZ({0, 0, 0}, w, h);
    for (int f = 0; f < 12; ++f) {
        PinholeView low = full;
        low.width = w / 2;
        low.height = h / 2;
        const Vec2d j = temporal.nextJitter();
        renderPlane(low, j, 1, colour, depth);
        temporal.accumulate(colour, depth, full, j);
    }
    // Sideways by several pixels: with reprojection the history lands where the plane moved.
    full.position = Vec3d{0.4, -0.25, 0};
    PinholeView low = full;
    low.width = w / 2;
    low.height = h / 2;
    const Vec2d j = temporal.nextJitter();
    renderPlane(low, j, 1, colour, depth);
    const double spatial = psnrAgainstTruth(upscaleBilinear(colour, w, h), full);
    temporal.accumulate(colour, depth, full, j);
    const double moved = psnrAgainstTruth(temporal.output(), full);
    EXPECT_GT(moved, spatial + 1.0) << "spatial " << spatial << ", reprojected " << moved;
    // Without reprojection (history taken at the same pixel) the output would smear: reset
    // gives the spatial estimate back.
    temporal.reset();
    temporal.accumulate(colour, depth, full, j);
    EXPECT_LT(psnrAgainstTruth(temporal.output(), full), moved);
}

}  // namespace
}  // namespace luxel::post
