// Direction bins of the voxel radiance cascades: an octahedral map of the sphere cut into
// side x side square bins (docs/algorithms/voxel-radiance-cascades.md §2). Bins nest: bin
// (bx, by) at side d covers exactly bins (2bx + i, 2by + j), i, j in {0, 1}, at side 2d, so a
// merge averages whole child bins. Solid angles, cosine weights and sky means are integrated
// numerically over each bin, so a uniform radiance gives exactly 4 pi (sphere) and pi (cosine).
#pragma once

#include <array>
#include <vector>

#include "../face_normal.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel::cascades {

// The unit direction at octahedral coordinates (u, v) in [0, 1]^2 (y is the pole).
Vec3d octahedralDirection(double u, double v);

struct DirectionBins {
    int side = 0;                    // bins per side of the map
    std::vector<Vec3d> centre;       // unit direction at each bin's centre, bin = by * side + bx
    std::vector<double> solidAngle;  // steradians; they sum to 4 pi
    // For each axis normal (normalIndex) the bins it sees and the integral of max(0, n . w) over
    // each: sum of weight = pi. Bins wholly behind the normal are left out.
    // `direction` is the cosine-weighted mean direction of the bin's part in front of the face:
    // where the face's own rays for the bin go (the centre of a bin across the horizon may lie
    // behind the face).
    struct CosineBins {
        std::vector<int> bin;
        std::vector<float> weight;
        std::vector<Vec3d> direction;
    };
    std::array<CosineBins, 6> cosine;

    static DirectionBins build(int side);
    int count() const { return side * side; }
    // The bin of side / 2 that holds `bin` (side must be even).
    int parent(int bin) const;
    // The four bins of side * 2 inside `bin`, in the finer map's numbering.
    std::array<int, 4> children(int bin) const;
};

// The solid-angle weighted mean of the scene's sky over each bin; with `wanted` (a flag per
// bin), over the bins flagged only, the others left black (the fine levels' maps have up to 65536
// bins, a pass reads few of them, and the sky is found again whenever the light is set).
std::vector<Rgb> skyMeans(const DirectionBins& bins, const ShadeOptions& shading,
                          const std::vector<bool>* wanted = nullptr);

}  // namespace luxel::voxel::cascades
