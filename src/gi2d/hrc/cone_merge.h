// HRC cone merging, top-down (docs/algorithms/holographic-radiance-cascades.md §5; paper Eq 13-17).
// R_n(p, y, i) is the angular fluence of cone i at probe (plane p, row y) of cascade n: radiance
// integrated over the cone's angle, everything beyond included. Stored as float RGB, rows
// innermost: ((p * 2^n + i) * rows + y).
#pragma once

#include <span>
#include <vector>

#include "gi2d/hrc/ray_tables.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d::hrc {

class ConeBuffer {
  public:
    void reset(int planes, int cones, int rows);

    int planes() const { return planes_; }
    int cones() const { return cones_; }
    int rows() const { return rows_; }

    bool inRange(int p, int y) const { return p >= 0 && p < planes_ && y >= 0 && y < rows_; }
    Rgb& at(int p, int i, int y) { return data_[index(p, i, y)]; }
    const Rgb& at(int p, int i, int y) const { return data_[index(p, i, y)]; }
    // Every entry in memory order (GPU uploads and readbacks: the hrc_merge layout).
    std::span<Rgb> data() { return data_; }
    std::span<const Rgb> data() const { return data_; }

  private:
    std::size_t index(int p, int i, int y) const {
        return (static_cast<std::size_t>(p) * cones_ + i) * rows_ + y;
    }
    int planes_ = 0, cones_ = 0, rows_ = 0;
    std::vector<Rgb> data_;
};

// Angular weights of cascade n+1's cones (docs/algorithms/holographic-radiance-cascades.md §5, Eq
// 13): w[j] = width of cone j at level n+1.
std::vector<float> coneWeights(int level);

// R_n from R_{n+1} (`upper`; nullptr for the top level, where every probe sees only the sky).
// Probes outside the frame read `sky` radiance times the cone width, so boundary light is still
// shadowed by everything on the canvas in front of it. Odd planes merge at the ray end (Eq 14);
// even planes average the merged near and far fluences (Eq 15-17), never interpolating before
// the merge.
void mergeCascade(const RayTables& tables, int n, const ConeBuffer* upper, Rgb sky,
                  ConeBuffer& out);

}  // namespace luxel::gi2d::hrc
