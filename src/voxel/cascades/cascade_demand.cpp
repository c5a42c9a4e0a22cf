// Which entries of each level a lighting pass merges (cascade_demand.h): marked from the faces
// up, each level's demanded entries marking what they read of the level above.
#include "cascade_demand.h"

#include <algorithm>

namespace luxel::voxel::cascades {

namespace {

// Whether a segment's chain reads the level above: as mergeCorners and chainRadiance do, a void
// segment is left out and only a chain ending in kContinue calls next().
bool readsAbove(std::uint32_t code, const std::vector<Passage>& passages) {
    if (code == kVoid) return false;
    return (isPassage(code) ? passageEnd(code, passages) : code) == kContinue;
}

// A level's demand rows, to be marked.
struct Rows {
    std::vector<std::uint64_t>& bits;
    int words;

    // Marks the entry (probe, bin).
    void mark(std::int32_t probe, int bin) {
        bits[std::size_t(probe) * words + bin / 64] |= std::uint64_t(1) << (bin % 64);
    }
    // Marks (corner's probe, bin) for each of the eight corners whose segment reads it.
    void markCorners(const std::uint32_t* codes, const Corners& corners, int bin,
                     const std::vector<Passage>& passages) {
        for (int c = 0; c < 8; ++c) {
            if (corners.weight[c] != 0.0f && readsAbove(codes[c], passages)) {
                mark(corners.probe[c], bin);
            }
        }
    }
};

Rows rowsOf(RadianceCascades::State& state, std::size_t k) {
    LevelData& data = state.levels[k];
    return Rows{data.demand, demandBins(state, k) / 64};
}

// Level 0's radiance that the faces' gather reads.
void markFaces(RadianceCascades::State& state) {
    const FaceData& faces = state.faces;
    Rows rows = rowsOf(state, 0);
    for (int f = 0; f < faces.table.size(); ++f) {
        const auto& seen = faces.bins.cosine[faces.table[f].normal];
        const std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
        for (std::size_t i = 0; i < seen.bin.size(); ++i) {
            rows.markCorners(codes + i * 8, faces.corners[f], seen.bin[i], state.passages);
        }
    }
}

// The child means of level k + 1 that level k's demanded entries read.
void markAbove(RadianceCascades::State& state, std::size_t k) {
    const LevelData& data = state.levels[k];
    Rows upper = rowsOf(state, k + 1);
    const int bins = data.bins.count(), words = demandBins(state, k) / 64;
    const DirectionBins* below = k == 0 ? nullptr : &state.levels[k - 1].bins;
    for (const std::int32_t p : data.demandProbes) {
        const Corners& corners = data.corners[p];
        const auto markBin = [&](int b) {
            upper.markCorners(&data.codes[(std::size_t(p) * bins + b) * 8], corners, b,
                              state.passages);
        };
        forEachDemanded(&data.demand[std::size_t(p) * words], words, [&](int e) {
            if (!below) return markBin(e);  // level 0's entries are its own bins
            for (const int child : below->children(e)) markBin(child);
        });
    }
}

void listProbes(RadianceCascades::State& state, std::size_t k) {
    LevelData& data = state.levels[k];
    const int words = demandBins(state, k) / 64;
    data.demandProbes.clear();
    for (std::int64_t p = 0; p < data.level.probeCount(); ++p) {
        const std::uint64_t* row = &data.demand[std::size_t(p) * words];
        if (std::any_of(row, row + words, [](std::uint64_t w) { return w != 0; })) {
            data.demandProbes.push_back(std::int32_t(p));
        }
    }
}

}  // namespace

void findDemand(RadianceCascades::State& state) {
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        LevelData& data = state.levels[k];
        data.demand.assign(std::size_t(data.level.probeCount()) * (demandBins(state, k) / 64), 0);
        data.demandProbes.clear();
    }
    if (state.levels.empty()) return;
    markFaces(state);
    // Every level and the faces are laid out for this cast (castSegments): where a refused cast
    // stopped, the codes are void, which read nothing above.
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        listProbes(state, k);
        if (!state.levels[k].level.top) markAbove(state, k);
    }
}

std::vector<bool> demandedBins(const RadianceCascades::State& state, std::size_t k) {
    const LevelData& data = state.levels[k];
    const int words = demandBins(state, k) / 64;
    std::vector<std::uint64_t> any(std::size_t(words), 0);
    for (const std::int32_t p : data.demandProbes) {
        for (int w = 0; w < words; ++w) any[w] |= data.demand[std::size_t(p) * words + w];
    }
    std::vector<bool> bins(std::size_t(data.bins.count()), false);
    forEachDemanded(any.data(), words, [&](int e) {
        if (k == 0) {
            bins[e] = true;
            return;
        }
        for (const int child : state.levels[k - 1].bins.children(e)) bins[child] = true;
    });
    return bins;
}

}  // namespace luxel::voxel::cascades
