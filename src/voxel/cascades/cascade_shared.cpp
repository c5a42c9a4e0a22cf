// The codes the merged entries' corners share (cascade_shared.h): one pass over the demanded
// entries in the order a lighting pass merges them (cascade_light.cpp, mergeLevel).
#include "cascade_shared.h"

#include "cascade_demand.h"

namespace luxel::voxel::cascades {

namespace {

void findFaces(FaceData& faces) {
    faces.shared.assign(faces.codes.size() / 8, kVoid);
    for (int f = 0; f < faces.table.size(); ++f) {
        const std::uint32_t live = weightedCorners(faces.corners[f]);
        const std::size_t bins = faces.bins.cosine[faces.table[f].normal].bin.size();
        const std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
        for (std::size_t i = 0; i < bins; ++i) {
            faces.shared[faces.codeOffset[f] / 8 + i] = sharedCode(codes + i * 8, live);
        }
    }
}

void findLevel(RadianceCascades::State& state, std::size_t k) {
    LevelData& data = state.levels[k];
    data.shared = {};
    data.sharedStart = {};
    if (data.level.top) return;  // one code per entry: nothing to share
    const int bins = data.bins.count(), words = demandBins(state, k) / 64;
    const DirectionBins* below = k == 0 ? nullptr : &state.levels[k - 1].bins;
    for (const std::int32_t p : data.demandProbes) {
        data.sharedStart.push_back(data.shared.size());
        const std::uint32_t live = weightedCorners(data.corners[p]);
        const auto add = [&](int b) {
            data.shared.push_back(sharedCode(&data.codes[(std::size_t(p) * bins + b) * 8], live));
        };
        forEachDemanded(&data.demand[std::size_t(p) * words], words, [&](int e) {
            if (!below) return add(e);  // level 0's entries are its own bins
            for (const int child : below->children(e)) add(child);
        });
    }
    data.shared.shrink_to_fit();
}

}  // namespace

void findSharedCodes(RadianceCascades::State& state) {
    findFaces(state.faces);
    for (std::size_t k = 0; k < state.levels.size(); ++k) findLevel(state, k);
}

}  // namespace luxel::voxel::cascades
