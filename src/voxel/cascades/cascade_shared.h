// The code each merged entry's weighted corners share, where they share one
// (docs/algorithms/voxel-radiance-cascades.md §5, "Shared codes"). Where the straight part of a
// bin's segment meets something its eight corners take one code (cascade_segments.cpp), and in
// the open all weighted corners continue: on the glass scene 65-90% of the entries a pass merges.
// A pass reads that one code from a dense stream instead of the entry's eight scattered codes,
// and a chain through glass is walked once for all the corners; the other entries' eight codes
// follow in a second stream, so the pass reads its codes in order, not scattered over the levels.
// The stream follows the codes and the demand, fixed while the cascades live, so it is found once
// per cast (CPU only: the GPU merges from the codes).
#pragma once

#include <bit>
#include <cstdint>

#include "cascade_state.h"

namespace luxel::voxel::cascades {

// An entry whose weighted corners do not all share one code: the merge reads its codes. Never a
// segment's code: PassageWriter hands out passages below kVoid - 1.
inline constexpr std::uint32_t kMixed = kVoid - 1;

// The code all the corners in `live` (bits, weightedCorners) share: kVoid when there are none
// (the merge reads nothing), kMixed when they differ.
inline std::uint32_t sharedCode(const std::uint32_t* codes, std::uint32_t live) {
    if (live == 0) return kVoid;
    const std::uint32_t first = codes[std::countr_zero(live)];
    for (live &= live - 1; live != 0; live &= live - 1) {
        if (codes[std::countr_zero(live)] != first) return kMixed;
    }
    return first;
}

// The corners with a weight, as bits: hidden corners have none (§3.2), and near a floor or a wall
// that is often half of them, so the merges skip them once per probe or face, not per bin.
inline std::uint32_t weightedCorners(const Corners& corners) {
    std::uint32_t live = 0;
    for (int c = 0; c < 8; ++c) live |= std::uint32_t(corners.weight[c] != 0.0f) << c;
    return live;
}

// Fills each level's `shared`, `mixed` and `sharedStart` and the faces' `shared`, `mixed` and
// `mixedStart` (cascade_state.h) from the codes, corners and demand (after findDemand;
// castSegments calls it). Counts them first: where they would take the cascades past
// State::memoryLimit beside State::plannedBytes and the passages, leaves them empty and returns
// false, and the pass merges from the codes alone, as it did before (the same light, slower).
bool findSharedCodes(RadianceCascades::State& state);

// Where a merge reads the next entry's shared code and, for a kMixed one, its eight codes.
struct SharedCursor {
    const std::uint32_t* shared = nullptr;  // null: no stream, the merge reads the codes
    const std::uint32_t* mixed = nullptr;
};

}  // namespace luxel::voxel::cascades
