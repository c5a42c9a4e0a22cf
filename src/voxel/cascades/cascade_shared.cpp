// The codes the merged entries' corners share (cascade_shared.h): one pass over the demanded
// entries in the order a lighting pass merges them (cascade_light.cpp, mergeLevel).
#include "cascade_shared.h"

#include <vector>

#include "cascade_demand.h"

namespace luxel::voxel::cascades {

namespace {

// The streams' sizes, counted before they are made (findSharedCodes' budget).
struct StreamSize {
    std::uint64_t shared = 0, mixed = 0, starts = 0;
    std::uint64_t bytes() const {
        return (shared + mixed) * 4 + starts * sizeof(LevelData::SharedStart);
    }
};

// Appends an entry's shared code, and its codes when they differ; with `size`, only counts them.
void add(std::vector<std::uint32_t>& shared, std::vector<std::uint32_t>& mixed,
         const std::uint32_t* codes, std::uint32_t live, StreamSize* size) {
    const std::uint32_t code = sharedCode(codes, live);
    if (size) {
        ++size->shared;
        size->mixed += code == kMixed ? 8 : 0;
        return;
    }
    shared.push_back(code);
    if (code == kMixed) mixed.insert(mixed.end(), codes, codes + 8);
}

// The faces' streams, or with `size` their size alone.
void findFaces(FaceData& faces, StreamSize* size) {
    if (size) {
        size->starts += std::uint64_t(faces.table.size()) + 1;  // mixedStart, 4 B each: a bound
    } else {
        faces.shared.reserve(faces.codes.size() / 8);
        faces.mixedStart.assign(std::size_t(faces.table.size()) + 1, 0);
    }
    for (int f = 0; f < faces.table.size(); ++f) {
        if (!size) faces.mixedStart[f] = std::uint32_t(faces.mixed.size());
        const std::uint32_t live = weightedCorners(faces.corners[f]);
        const std::size_t bins = faces.bins.cosine[faces.table[f].normal].bin.size();
        const std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
        for (std::size_t i = 0; i < bins; ++i) {
            add(faces.shared, faces.mixed, codes + i * 8, live, size);
        }
    }
    if (!size) faces.mixedStart.back() = std::uint32_t(faces.mixed.size());
}

// Level k's streams, or with `size` their size alone.
void findLevel(RadianceCascades::State& state, std::size_t k, StreamSize* size) {
    LevelData& data = state.levels[k];
    if (data.level.top) return;  // one code per entry: nothing to share
    const int bins = data.bins.count(), words = demandBins(state, k) / 64;
    const DirectionBins* below = k == 0 ? nullptr : &state.levels[k - 1].bins;
    for (const std::int32_t p : data.demandProbes) {
        if (size) {
            ++size->starts;
        } else {
            data.sharedStart.push_back({data.shared.size(), data.mixed.size()});
        }
        const std::uint32_t live = weightedCorners(data.corners[p]);
        const auto addBin = [&](int b) {
            add(data.shared, data.mixed, &data.codes[(std::size_t(p) * bins + b) * 8], live, size);
        };
        forEachDemanded(&data.demand[std::size_t(p) * words], words, [&](int e) {
            if (!below) return addBin(e);  // level 0's entries are its own bins
            for (const int child : below->children(e)) addBin(child);
        });
    }
}

// Every stream emptied, its memory freed (assigning {} would keep the capacity): the pass merges
// from the codes.
void clearStreams(RadianceCascades::State& state) {
    state.faces.shared = std::vector<std::uint32_t>();
    state.faces.mixed = std::vector<std::uint32_t>();
    state.faces.mixedStart = std::vector<std::uint32_t>();
    for (LevelData& level : state.levels) {
        level.shared = std::vector<std::uint32_t>();
        level.mixed = std::vector<std::uint32_t>();
        level.sharedStart = std::vector<LevelData::SharedStart>();
    }
}

}  // namespace

bool findSharedCodes(RadianceCascades::State& state) {
    clearStreams(state);
    // Counted first, so they are made only where they fit beside the cascades' estimate and the
    // passages (the limit castSegments keeps), each vector allocated once at its size.
    StreamSize faces, total;
    findFaces(state.faces, &faces);
    std::vector<StreamSize> levels(state.levels.size());
    total = faces;
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        findLevel(state, k, &levels[k]);
        total.shared += levels[k].shared;
        total.mixed += levels[k].mixed;
        total.starts += levels[k].starts;
    }
    const std::uint64_t used = state.plannedBytes + state.passages.size() * sizeof(Passage);
    if (state.memoryLimit > 0 && used + total.bytes() > state.memoryLimit) return false;
    state.faces.shared.reserve(faces.shared);
    state.faces.mixed.reserve(faces.mixed);
    findFaces(state.faces, nullptr);
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        state.levels[k].shared.reserve(levels[k].shared);
        state.levels[k].mixed.reserve(levels[k].mixed);
        state.levels[k].sharedStart.reserve(levels[k].starts);
        findLevel(state, k, nullptr);
    }
    return true;
}

}  // namespace luxel::voxel::cascades
