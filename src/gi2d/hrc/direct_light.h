// Exact direct light from compact lights (docs/algorithms/holographic-radiance-cascades.md §12.5).
// Fluence is linear in emission for a fixed absorption field, so the compact lights' emission is
// taken out of the medium the cascades solve and their fluence is added here instead:
//  - beyond kDirectNearFactor radii (+ kDirectNearMargin px) of a light, each of its point sources
//    (compact_lights.h) shines as intensity(phi) / (2 pi d) times the transmittance to the pixel,
//    read from a fan of rays marched from the source (kFanSectors rays, each sector split into a
//    ray per px of arc at the length of its longer ray) with a sample per px along each;
//  - nearer, the mean radiance over kDirectNearRays directions across the cone the light
//    subtends, marched exactly from the pixel centre through the medium, counting the light's
//    emission only (the reference solver's quantity for that light).
// Lights are taken brightest first while the work stays within a budget; the rest stay in the
// cascades' medium.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "gi2d/hrc/light_scores.h"
#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

inline constexpr int kDirectNearRays = 64;
inline constexpr int kFanSectors = 256;       // a fan's first rays, split where they run far
inline constexpr double kFanRaysPerPx = 1.0;  // rays per px of arc at a sector's longer ray
inline constexpr double kDirectNearFactor = 2.0;
inline constexpr double kDirectNearMargin = 2.0;
inline constexpr float kDirectCutoff = 1e-4f;  // a fan ray stops below this T in every channel
// Work (DirectLight::work) allowed per canvas pixel (per pixel of a 256 x 256 canvas on smaller
// ones).
inline constexpr double kDirectWorkPerPixel = 128;
inline constexpr double kDirectBudgetFloorPixels = 256.0 * 256.0;

struct DirectLight {
    Image fluence;  // the compact lights' fluence (empty when none)
    // y * width + x and the share of its emission the cascades no longer see.
    std::vector<std::pair<std::uint32_t, float>> removed;
    // Marched pixels and pixels gathered from a fan, the budget's unit.
    std::uint64_t work = 0;
    bool empty() const { return removed.empty(); }
};

struct DirectLightOptions {
    // Fan sectors whose wedge holds no absorbing pixel are not split (T = 1 in them: the same
    // light to rounding, far fewer rays in vacuum). Off: every lit sector split (the dense fan).
    bool vacuumSectors = true;
};

DirectLight exactDirectLight(const Medium2D& medium, const DirectLightOptions& options = {});
// The same with the solve's light scores of `medium` (their emitting codes taken, where made).
DirectLight exactDirectLight(const Medium2D& medium, LightScores& scores,
                             const DirectLightOptions& options = {});

// Whether the split's memory fits, checked before the search allocates: the solve's light scores
// (held through it), the search's label a pixel, the direct fluence and the reduced medium's copy
// (the solve of the reduced medium checks its own on top of them).
Status checkDirectLightMemory(int width, int height);

// The medium with the removed pixels' emission scaled by 1 - share (absorption unchanged).
Medium2D withoutDirectLights(const Medium2D& medium, const DirectLight& direct);

// fluence += direct.fluence.
void addDirectLight(const DirectLight& direct, Image& fluence);

// The direct light's CPU time and work (DirectLight::work), for the callers' pass timings.
struct DirectLightSplit {
    double milliseconds = 0;
    std::uint64_t work = 0;
};

// The split of §12.5 around a solve, for both backends. Where a compact light qualifies, `onSplit`
// is told the direct light's time and work, `solveRest` solves the medium without the lights'
// emission with `options` less the direct light, and their direct light is added to what it
// returns. std::nullopt where none qualifies: the caller solves the medium as it is. The split's
// memory is checked first (an error where it does not fit). `scores` are the medium's
// (LightScores::of, with the emitting codes for the search); where the split happens they become
// the reduced medium's, as `solveRest` is given them (the rows of the removed pixels scored again).
std::optional<Result<Image>> solveSplittingDirectLight(
    const Medium2D& medium, LightScores& scores, const HrcOptions& options,
    const std::function<Result<Image>(const Medium2D&, LightScores&, const HrcOptions&)>& solveRest,
    const std::function<void(const DirectLightSplit&)>& onSplit);

}  // namespace luxel::gi2d::hrc
