// HRC cone merging, top-down (docs/algorithms/holographic-radiance-cascades.md §5; paper Eq 13-17).
// R_n(p, y, i) is the angular fluence of cone i at probe (plane p, row y) of cascade n: radiance
// integrated over the cone's angle, everything beyond included. Stored as binary16 in the layout of
// the GPU's hrc_merge (src/gpu/shaders/shared/hrc_layout.h): per (p, i) three channel planes of
// rows, the rows padded to an even count. Arithmetic is done in float; each merged value is rounded
// once, as the GPU and the CPU sweep round it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/ray_tables.h"
#include "luxel/core/half.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d::hrc {

class ConeBuffer {
  public:
    void reset(int planes, int cones, int rows);

    int planes() const { return planes_; }
    int cones() const { return cones_; }
    int rows() const { return rows_; }

    bool inRange(int p, int y) const { return p >= 0 && p < planes_ && y >= 0 && y < rows_; }
    Rgb at(int p, int i, int y) const {
        const std::size_t r = index(p, i, 0, y);
        return {halfToFloat(data_[r]), halfToFloat(data_[r + stride_]),
                halfToFloat(data_[r + 2 * stride_])};
    }
    void set(int p, int i, int y, Rgb value) {
        const std::size_t r = index(p, i, 0, y);
        data_[r] = floatToHalf(value.r);
        data_[r + stride_] = floatToHalf(value.g);
        data_[r + 2 * stride_] = floatToHalf(value.b);
    }
    // Every binary16 value in memory order (GPU uploads and readbacks: the hrc_merge layout).
    std::span<std::uint16_t> halves() { return data_; }
    std::span<const std::uint16_t> halves() const { return data_; }

    // Bytes of a buffer of this shape.
    static std::uint64_t bytesFor(int planes, int cones, int rows);

  private:
    std::size_t index(int p, int i, int c, int y) const {
        return ((static_cast<std::size_t>(p) * cones_ + i) * 3 + c) * stride_ + y;
    }
    int planes_ = 0, cones_ = 0, rows_ = 0;
    std::size_t stride_ = 0;  // values per channel plane: the rows padded to an even count
    std::vector<std::uint16_t> data_;
};

// Angular weights of cascade n+1's cones (docs/algorithms/holographic-radiance-cascades.md §5, Eq
// 13): w[j] = width of cone j at level n+1.
std::vector<float> coneWeights(int level);

// Where cascade 0's merge finds the lights (§12.3): the canvas mask and the frame it merges in.
struct MergeNearLights {
    const NearLightMask* mask = nullptr;
    FrustumFrame frame{};
};

// R_n from R_{n+1} (`upper`; nullptr for the top level, where every probe sees only the sky).
// Probes outside the frame read `sky` radiance times the cone width, so boundary light is still
// shadowed by everything on the canvas in front of it. Odd planes merge at the ray end (Eq 14);
// even planes average the merged near and far fluences (Eq 15-17), never interpolating before
// the merge. `nearLights` (cascade 0; none: the whole near-probe blend everywhere) weighs the near
// probe's row blend by the mask at the pixel each plane is read out for (hrcNearRowWeightAt).
void mergeCascade(const RayTables& tables, int n, const ConeBuffer* upper, Rgb sky, ConeBuffer& out,
                  const MergeNearLights& nearLights = {});

}  // namespace luxel::gi2d::hrc
