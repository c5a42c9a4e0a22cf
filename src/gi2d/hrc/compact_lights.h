// Compact lights (docs/algorithms/holographic-radiance-cascades.md §12.5): the small, connected
// groups of emitting pixels whose direct light luxel adds exactly instead of letting the cascades
// carry it. Each is split into point sources (one per pixel, or one for a light smaller than a
// pixel) with a table of radiant intensity per direction, the light their pixels send across
// parallel lines towards that direction, attenuated by the light's own pixels on the way out.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <vector>

#include "gi2d/hrc/light_scores.h"
#include "luxel/core/vec.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

inline constexpr int kCompactLightMaxSize = 12;  // px: the largest bounding box side
// The share of a light split off falls from 1 to 0 as its emission's RMS radius about its centroid
// grows from kCompactFullRadius to kCompactNoneRadius: a measure that changes smoothly as a light
// moves, so that no light pops in and out of the split (a disk of radius r: r / sqrt 2).
inline constexpr double kCompactFullRadius = 2.5;
inline constexpr double kCompactNoneRadius = 3.5;
// A light whose RMS radius is at most kPointFullRadius is one point source; from
// kPointNoneRadius on, one per pixel (kSourceBlock); in between both, blended.
inline constexpr double kPointFullRadius = 0.75;
inline constexpr double kPointNoneRadius = 1.0;
inline constexpr int kSourceBlock = 1;                     // px: a point source per block of pixels
inline constexpr int kIntensityDirections = 128;           // the intensity table, uniform over 2 pi
inline constexpr double kIntensityLineSpacing = 1.0 / 32;  // px between the table's parallel lines

struct PointSource {
    Vec2d position;  // the emission-weighted centre of its pixels, canvas px
    // Radiant intensity towards 2 pi (m + 1/2) / kIntensityDirections: the integral over the
    // lines' offset of the radiance they carry away from the source's pixels (radiance x px).
    std::vector<Rgb> intensity;
    // Linear between the table's directions; angle in [0, 2 pi) (callers' atan2 shifted). Inline:
    // the fans' gather calls it once a pixel and source.
    Rgb intensityTowards(double angle) const {
        // Entry m sits at 2 pi (m + 1/2) / n.
        const int n = static_cast<int>(intensity.size());
        double f = angle * (n / (2.0 * std::numbers::pi)) - 0.5;
        if (f < 0) f += n;
        const int i0 = std::min(static_cast<int>(f), n - 1);
        const int i1 = i0 + 1 < n ? i0 + 1 : 0;
        const float a = static_cast<float>(f - i0);
        const Rgb& p = intensity[static_cast<std::size_t>(i0)];
        const Rgb& q = intensity[static_cast<std::size_t>(i1)];
        return {p.r + a * (q.r - p.r), p.g + a * (q.g - p.g), p.b + a * (q.b - p.b)};
    }
};

struct CompactLight {
    std::vector<std::uint32_t> pixels;   // y * width + x
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // bounding box, inclusive
    Vec2d centre;                        // of the bounding box
    double radius = 0;                   // from the centre to the farthest pixel corner
    float score = 0;                     // its brightest pixel's light score
    double share = 0;                    // of its emission split off, in (0, 1]
    double rmsRadius = 0;                // of its emission about the emission's centroid, px
    std::vector<PointSource> sources;
};

// The 8-connected groups of emitting pixels (E (1 - exp(-sigma)) > 0 in some channel) whose
// bounding box is at most kCompactLightMaxSize on each side, which hold a light (light score at
// least lightScoreThreshold of the brightest) and whose share is above 0, brightest first.
// Intensity tables not yet made.
std::vector<CompactLight> findCompactLights(const Medium2D& medium);
// The same with the solve's light scores of `medium`, taking their emitting codes where they
// have them (LightScores::of with `emitting`).
std::vector<CompactLight> findCompactLights(const Medium2D& medium, LightScores& scores);

// Fills light.sources: the point sources and their intensity tables.
void makePointSources(const Medium2D& medium, CompactLight& light);

}  // namespace luxel::gi2d::hrc
