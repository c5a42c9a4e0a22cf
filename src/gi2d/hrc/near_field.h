// The exact near field (docs/algorithms/holographic-radiance-cascades.md §12.3, "An exact near
// field in fog"): where every pixel of the canvas absorbs, a ray may stop at a transmittance of
// kNearFieldCutoff after at most ln(1 / cutoff) / sigma_min pixels, so brute-force rays are
// bounded; HRC's fluence at the pixels within kNearFieldRadius of a light, where its bias sits, is
// then replaced by the mean radiance over kNearFieldRays directions marched exactly from the
// pixel centre (the reference solver's convention, own pixel included).
#pragma once

#include <cstdint>
#include <vector>

#include "gi2d/hrc/light_scores.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::hrc {

inline constexpr int kNearFieldRadius = 5;                        // px from a light's pixel centre
inline constexpr int kNearFieldRays = LUXEL_HRC_NEAR_FIELD_RAYS;  // directions per pixel
inline constexpr float kNearFieldCutoff = 1e-3f;     // a ray stops below this T in every channel
inline constexpr float kNearFieldMaxReach = 512.0f;  // px: the longest ray the gather allows
// The budget of marched pixels (rays x reach): this many per canvas pixel, and per pixel of a
// 256 x 256 canvas on smaller ones (their solve is cheap).
inline constexpr double kNearFieldStepsPerPixel = 256;
inline constexpr double kNearFieldBudgetFloorPixels = 256.0 * 256.0;

struct NearFieldPlan {
    float reach = 0;                    // ln(1 / cutoff) / sigma_min, px (0: no absorption bound)
    std::vector<std::uint32_t> pixels;  // y * width + x, ascending; empty: the gather is off
    bool empty() const { return pixels.empty(); }
};

// The pixels to gather, or none: when some pixel of the canvas has sigma = 0 in some channel (or
// so little that a ray reaches farther than kNearFieldMaxReach), when the canvas has no light, or
// when the rays would cost more than the budget above.
// Lights are those of NearLightMask: max_c E_c min(sigma_c, 1) at least 1/64 of the brightest.
NearFieldPlan planNearField(const Medium2D& medium);
// The same from the solve's light scores of `medium`.
NearFieldPlan planNearField(const LightScores& scores);

// Mean radiance over kNearFieldRays directions 2 pi (k + 1/2) / N from the centre of (x, y),
// each marched for at most `reach` px (a plan's reach: beyond it T is below the cutoff anyway).
Rgb nearFieldGatherAt(const RayMarcher& marcher, int x, int y, double reach = 1e30);

// Overwrites the plan's pixels of `fluence` with the gather (in parallel).
void gatherNearFieldInPlace(const Medium2D& medium, const NearFieldPlan& plan, Image& fluence);

}  // namespace luxel::gi2d::hrc
