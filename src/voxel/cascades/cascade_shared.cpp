// The codes the merged entries' corners share (cascade_shared.h): one pass over the demanded
// entries in the order a lighting pass merges them (cascade_light.cpp, mergeLevel).
#include "cascade_shared.h"

#include "cascade_demand.h"

namespace luxel::voxel::cascades {

namespace {

// Appends an entry's shared code, and its codes when they differ.
void add(std::vector<std::uint32_t>& shared, std::vector<std::uint32_t>& mixed,
         const std::uint32_t* codes, std::uint32_t live) {
    const std::uint32_t code = sharedCode(codes, live);
    shared.push_back(code);
    if (code == kMixed) mixed.insert(mixed.end(), codes, codes + 8);
}

void findFaces(FaceData& faces) {
    faces.shared = {};
    faces.mixed = {};
    faces.shared.reserve(faces.codes.size() / 8);
    faces.mixedStart.assign(std::size_t(faces.table.size()) + 1, 0);
    for (int f = 0; f < faces.table.size(); ++f) {
        faces.mixedStart[f] = std::uint32_t(faces.mixed.size());
        const std::uint32_t live = weightedCorners(faces.corners[f]);
        const std::size_t bins = faces.bins.cosine[faces.table[f].normal].bin.size();
        const std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
        for (std::size_t i = 0; i < bins; ++i) add(faces.shared, faces.mixed, codes + i * 8, live);
    }
    faces.mixedStart.back() = std::uint32_t(faces.mixed.size());
    faces.mixed.shrink_to_fit();
}

void findLevel(RadianceCascades::State& state, std::size_t k) {
    LevelData& data = state.levels[k];
    data.shared = {};
    data.mixed = {};
    data.sharedStart = {};
    if (data.level.top) return;  // one code per entry: nothing to share
    const int bins = data.bins.count(), words = demandBins(state, k) / 64;
    const DirectionBins* below = k == 0 ? nullptr : &state.levels[k - 1].bins;
    for (const std::int32_t p : data.demandProbes) {
        data.sharedStart.push_back({data.shared.size(), data.mixed.size()});
        const std::uint32_t live = weightedCorners(data.corners[p]);
        const auto addBin = [&](int b) {
            add(data.shared, data.mixed, &data.codes[(std::size_t(p) * bins + b) * 8], live);
        };
        forEachDemanded(&data.demand[std::size_t(p) * words], words, [&](int e) {
            if (!below) return addBin(e);  // level 0's entries are its own bins
            for (const int child : below->children(e)) addBin(child);
        });
    }
    data.shared.shrink_to_fit();
    data.mixed.shrink_to_fit();
}

}  // namespace

void findSharedCodes(RadianceCascades::State& state) {
    findFaces(state.faces);
    for (std::size_t k = 0; k < state.levels.size(); ++k) findLevel(state, k);
}

}  // namespace luxel::voxel::cascades
