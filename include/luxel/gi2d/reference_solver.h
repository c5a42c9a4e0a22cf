// Ground-truth 2D fluence: for every pixel, radiance integrated over all directions by brute force.
//
// Directions are stratified and jittered: ray k of N points at angle 2*pi*(k + u_k)/N with u_k
// uniform per pixel (seeded from (seed, x, y), so the image does not depend on the thread count).
// Each ray starts at the pixel centre and is marched exactly through the medium (RayMarcher), its
// own pixel included. The result is the fluence convention of docs/conventions.md: mean radiance
// over directions, F = (1/2pi) * integral of L d(theta); inside a uniform emitter of radiance E it
// reads E.
#pragma once

#include <cstdint>
#include <functional>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {

struct ReferenceOptions {
    // Directions per pixel. The default keeps the RMSE between two seeds under 1% of the image mean
    // on the shipped scenes (tests/gi2d/reference_noise_test.cpp).
    int rays = 1024;
    std::uint64_t seed = 1;
    float transmittanceCutoff = 1e-6f;  // stop a ray once T is below this in every channel
    // Called from worker threads with the number of rows just finished.
    std::function<void(int rows)> onRowsDone;
};

inline constexpr int kMaxReferenceRays = 1 << 20;

// Fluence for the whole medium (3 channels). Fails for a ray count outside 1..kMaxReferenceRays or
// when the working memory would not fit.
Result<Image> solveReference(const Medium2D& medium, const ReferenceOptions& options = {});

// Fluence at one pixel, for tests and probes.
Rgb referenceFluenceAt(const RayMarcher& marcher, int x, int y, const ReferenceOptions& options);

// Rays the reference solver casts for a medium of this size.
inline std::uint64_t referenceRayCount(int width, int height, int rays) {
    return static_cast<std::uint64_t>(width) * height * rays;
}

}  // namespace luxel::gi2d
