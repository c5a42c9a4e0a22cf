// Where the lights are, told once per solve (docs/algorithms/holographic-radiance-cascades.md
// §12.3): per canvas pixel, how much of cascade 0's near-probe row blend (§5.1) it keeps. Next
// to a light that blend reads the neighbouring row's fluence, which there is parallax rather than
// the angular correction §5.1 wants; the merge of cascade 0 reads this mask at the pixel its
// plane is read out for (§6.2: plane p feeds pixel p - 1).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gi2d/hrc/light_scores.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

class NearLightMask {
  public:
    // Lights are the pixels whose max_c E_c min(sigma_c, 1) is at least 1/64 of the brightest
    // pixel's; each pixel keeps a share of the blend by its distance to the nearest one's centre:
    // none within 1 px, the whole from 3 px, linear between (near_lights.cpp). A canvas without
    // emission keeps the whole blend everywhere.
    static NearLightMask fromMedium(const Medium2D& medium);
    // From the solve's light scores of the medium.
    static NearLightMask fromScores(const LightScores& scores);
    // The same from the solve's light scores, in place, keeping the allocations of a mask of the
    // same size.
    void build(const LightScores& scores);

    int width() const { return width_; }
    int height() const { return height_; }
    // The kept fraction of pixel (x, y) in 64ths, 0 .. 64 (the merges weigh the blend by it with
    // hrcNearRowWeightAt, shared/hrc_kernels.h).
    std::uint8_t at(int x, int y) const { return bytes_[static_cast<std::size_t>(y) * width_ + x]; }
    // Whether any pixel of canvas column x / row y keeps less than the whole blend: the CPU sweep
    // reads the mask only along the columns and rows that do.
    bool columnNear(int x) const { return columnNear_[static_cast<std::size_t>(x)] != 0; }
    bool rowNear(int y) const { return rowNear_[static_cast<std::size_t>(y)] != 0; }
    // The bytes row by row, padded to whole 32-bit words (the GPU's hrc_merge reads words).
    std::span<const std::uint8_t> bytes() const { return bytes_; }

    // Bytes of the mask (what the GPU holds) and with the column and row flags.
    static std::uint64_t bytesFor(int width, int height);
    static std::uint64_t hostBytesFor(int width, int height);

  private:
    int width_ = 0, height_ = 0;
    std::vector<std::uint8_t> bytes_, columnNear_, rowNear_;
};

}  // namespace luxel::gi2d::hrc
