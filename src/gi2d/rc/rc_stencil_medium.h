// The pixel medium as RC stencil walks read it (docs/algorithms/radiance-cascades-2d.md §8): a
// palette of the distinct materials, and per pixel absorption planes with the emitters marked.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::rc {

// The pixel medium as stencil walks read it: per pixel an id into a palette of the distinct
// (sigma, E) pairs, kept as a structure of arrays.
class StencilMedium {
  public:
    explicit StencilMedium(const Medium2D& medium);

    int width() const { return width_; }
    int height() const { return height_; }
    std::uint32_t id(int x, int y) const { return ids_[static_cast<std::size_t>(y) * width_ + x]; }
    const std::uint32_t* ids() const { return ids_.data(); }
    // Every material has equal absorption in its three channels.
    bool grey() const { return grey_; }
    const float* sigma(int c) const { return sigma_[c].data(); }
    const float* emission(int c) const { return emission_[c].data(); }
    std::size_t paletteSize() const { return sigma_[0].size(); }
    // Adds light to a ray: some channel both absorbs and emits.
    bool emits(std::uint32_t id) const {
        for (int c = 0; c < 3; ++c) {
            if (sigma_[c][id] != 0.0f && emission_[c][id] != 0.0f) return true;
        }
        return false;
    }

    // Per pixel, row-major: absorption of channel c (only c = 0 for grey media), its sign bit
    // set where the pixel emits (the planes of the walks are copies).
    const float* planeSigma(int c) const { return planeSigma_[c].data(); }

    // Per pixel, row-major: the largest r (at most kMaxUniformRadius) such that every pixel within
    // Chebyshev distance r lies on the canvas and has this pixel's material. A walk may cross
    // those pixels in one step (docs/algorithms/radiance-cascades-2d.md §8).
    const std::uint8_t* uniformRadius() const { return uniformRadius_.data(); }
    static constexpr int kMaxUniformRadius = 255;

    // Bytes held for a medium of this size (at most: every pixel distinct).
    static std::uint64_t bytesFor(std::uint64_t width, std::uint64_t height);

  private:
    int width_, height_;
    bool grey_ = true;
    std::vector<std::uint32_t> ids_;
    std::vector<float> sigma_[3], emission_[3];
    std::vector<float> planeSigma_[3];
    std::vector<std::uint8_t> uniformRadius_;

    void buildUniformRadius();
};

// Probe-major ((p * stored + s), what cascadePass and readOut use) to slot-major ((s * probes + p))
// and back.
std::vector<Rgb> toSlotMajor(const std::vector<Rgb>& probeMajor, int stored);
std::vector<Rgb> toProbeMajor(const std::vector<Rgb>& slotMajor, int stored);

}  // namespace luxel::gi2d::rc
