// Which entries of each level a lighting pass must merge
// (docs/algorithms/voxel-radiance-cascades.md §5): only those a chain from a face reaches. The
// faces read level 0's radiance at their corners, in the bins in front of them; a level's entry
// reads the level above's child means at its corners; and only through a segment that is not
// void, has a corner weight, and ends (past its passages) in kContinue. Probes far from every
// surface, or inside solids, and the bins behind the surfaces are never read, and the codes that
// decide this are fixed while the cascades live, so the set is found once per cast.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "cascade_state.h"

namespace luxel::voxel::cascades {

// Finds each level's demand and demandProbes (LevelData) from the codes, corners and passages
// of the last cast (castSegments calls it).
void findDemand(RadianceCascades::State& state);

// The bins of level k that its demanded entries merge (for the levels above 0 the children of
// the bins demanded), as flags: the only bins whose sky a pass reads there.
std::vector<bool> demandedBins(const RadianceCascades::State& state, std::size_t k);

// Entries of a level's rows in LevelData::demand: level 0's radiance bins, above it the bins of
// the level below (the child means), 64 to a word.
inline int demandBins(const RadianceCascades::State& state, std::size_t k) {
    const int bins = state.levels[k].bins.count();
    return k == 0 ? bins : bins / 4;
}

// Calls body(bin) for each entry of a demand row of `words` words, in increasing order.
template <typename Body>
inline void forEachDemanded(const std::uint64_t* row, int words, Body&& body) {
    for (int w = 0; w < words; ++w) {
        for (std::uint64_t bits = row[w]; bits != 0; bits &= bits - 1) {
            body(w * 64 + std::countr_zero(bits));
        }
    }
}

}  // namespace luxel::voxel::cascades
