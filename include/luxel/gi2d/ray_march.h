// Exact front-to-back integration of radiance along a ray through the pixel medium.
//
// The ray visits pixels with an Amanatides-Woo DDA (exact segment length per crossed cell); runs of
// identical cells are merged, and aligned 2^k x 2^k blocks of identical cells (a quadtree built
// once per medium) are crossed in one step. Both are exact: a uniform run of lengths a and b gives
// exp(-s a) exp(-s b) = exp(-s (a + b)) and E(1 - t_a) + t_a E(1 - t_b) = E(1 - t_a t_b).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d {

// What a ray segment delivers towards its start: radiance L and transmittance T (per channel).
struct RaySegment {
    Rgb radiance;
    Rgb transmittance{1.0f, 1.0f, 1.0f};
};

class RayMarcher {
  public:
    // Keeps a packed copy of the medium: per pixel a 32-bit word (material id + block level) and a
    // palette of the distinct (sigma, E) pairs. The medium must have at most kMaxPixels pixels.
    explicit RayMarcher(const Medium2D& medium);

    static constexpr std::uint64_t kMaxPixels = 1ull << 28;

    int width() const { return width_; }
    int height() const { return height_; }

    // Integrates from `origin` (inside the canvas or on its border) along the unit vector
    // `direction` for at most `maxDistance` pixels. A ray that leaves the canvas before
    // maxDistance picks up the boundary radiance behind what it crossed. Integration stops early
    // once every channel's transmittance is below `cutoff`. `depthScale` multiplies the length
    // counted in every crossed pixel (HRC's cascade-0 rays,
    // docs/algorithms/holographic-radiance-cascades.md §3.1); the path itself is unchanged.
    RaySegment march(Vec2d origin, Vec2d direction, double maxDistance = 1e30, float cutoff = 1e-6f,
                     float depthScale = 1.0f) const;

    // The part of the segment [from, to] that lies on the canvas, without boundary radiance
    // (empty space outside). `leftCanvas` tells whether `to` lies outside the canvas, i.e. whether
    // the ray continues into the open beyond the segment.
    RaySegment segment(Vec2d from, Vec2d to, bool* leavesCanvas = nullptr) const;

    // Bytes the marcher holds for a medium of this size (at most: every pixel distinct).
    static std::uint64_t bytesFor(std::uint64_t width, std::uint64_t height);

  private:
    struct Material {
        float sigma[3];
        float emission[3];
        bool operator==(const Material&) const = default;
    };

    // Per pixel word: material id in the high 28 bits, block level in the low 4. One small word
    // per step keeps the traversal in cache; the palette is only read where the material changes.
    static constexpr int kLevelBits = 4;
    static constexpr std::uint32_t kLevelMask = (1u << kLevelBits) - 1;

    RaySegment marchImpl(Vec2d origin, Vec2d direction, double maxDistance, float cutoff,
                         bool addBoundary, float depthScale = 1.0f) const;
    void buildPalette(const Medium2D& medium);
    void buildBlockLevels();

    int width_, height_;
    Rgb boundary_;
    std::vector<Material> palette_;
    // Per pixel: material id << kLevelBits | k, where k is the largest level such that the
    // aligned 2^k block holding the pixel lies inside the canvas and has one material.
    std::vector<std::uint32_t> grid_;
};

}  // namespace luxel::gi2d
