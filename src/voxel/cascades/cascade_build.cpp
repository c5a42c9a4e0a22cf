// Building the voxel radiance cascades' faces, levels and segments
// (docs/algorithms/voxel-radiance-cascades.md §3, §5): at create(), and again at setLight() when
// what passes glass changes, so the cascades are always what a fresh create() with the new light
// would build. Which faces are probes depends on the light too: the faces of opaque voxels under
// glass are probes only while the glass lets light through (surface_faces.h).
#include <algorithm>
#include <string>
#include <utility>

#include "cascade_state.h"
#include "luxel/core/memory.h"

namespace luxel::voxel::cascades {

namespace {

bool sameFaces(const FaceTable& a, const FaceTable& b) {
    if (a.size() != b.size()) return false;
    for (int f = 0; f < a.size(); ++f) {
        if (!(a[f].voxel == b[f].voxel) || a[f].normal != b[f].normal) return false;
    }
    return true;
}

// The faces for the state's shading. The irradiance gathered so far moves with its face (voxel,
// normal), so new light still converges from where it was; a new face starts dark.
Status findFaces(RadianceCascades::State& state, std::int64_t exposed) {
    Result<FaceTable> table = FaceTable::build(
        *state.world, state.textures, std::max<std::int64_t>(exposed * 2, 1 << 20), &state.shading);
    if (!table) return table.error();
    FaceData& faces = state.faces;
    if (sameFaces(*table, faces.table)) return Ok{};
    std::vector<Rgb> irradiance(std::size_t(table->size()));
    for (int f = 0; f < faces.table.size() && std::size_t(f) < faces.irradiance.size(); ++f) {
        const int id = table->find(faces.table[f].voxel, faces.table[f].normal);
        if (id >= 0) irradiance[id] = faces.irradiance[f];
    }
    faces.table = std::move(*table);
    faces.irradiance = std::move(irradiance);
    // Everything kept per face is found again for the new table (updateFaceLight).
    faces.clearEmitterLight();
    faces.emission.clear();
    return Ok{};
}

// The levels for a level-0 spacing; kept (with their direction bins) when it is the same.
void useLevels(RadianceCascades::State& state, int spacing) {
    if (!state.levels.empty() && state.levels.front().level.spacing == spacing) return;
    state.levels.clear();
    for (const Level& level : planLevels(state.world->size(), spacing)) {
        LevelData data;
        data.level = level;
        data.bins = DirectionBins::build(level.binSide);
        state.levels.push_back(std::move(data));
    }
}

}  // namespace

Status checkEstimate(const CascadeEstimate& estimate) {
    if (estimate.fits) return Ok{};
    return Error("radiance cascades with probe spacing " + std::to_string(estimate.spacing) +
                 " need " + formatBytes(estimate.bytes) + ", more than the limit of " +
                 formatBytes(estimate.limit) + " (try a larger --rc-spacing)");
}

Status buildSegments(RadianceCascades::State& state) {
    // The limit the cascades were made under, not the memory free now: the spacing a light picks
    // does not depend on when it was set.
    CascadeOptions options = state.options;
    options.memoryLimit = state.memoryLimit;
    CascadeEstimate estimate = estimateCascades(*state.world, options);
    if (Status s = checkEstimate(estimate); !s) return s;
    if (Status s = findFaces(state, estimate.faces); !s) return s;
    // The faces' sun rays pass the glass too: found again for its new materials.
    state.faces.sunPassing.clear();
    const bool automatic = state.options.spacing == 0;
    const CascadeEstimate first = estimate;
    std::uint64_t firstRefusal = 0;
    state.stats.spacingNote.clear();
    for (;;) {
        useLevels(state, estimate.spacing);
        state.plannedBytes = estimate.bytes;
        state.stats.spacing = estimate.spacing;
        const bool last = !automatic || estimate.spacing >= kMaxCascadeSpacing;
        const std::string hint =
            !automatic ? "try a larger --rc-spacing, --no-refraction or a smaller world"
            : estimate.spacing > first.spacing
                ? "at the largest probe spacing, " + std::to_string(estimate.spacing) +
                      ": try --no-refraction or a smaller world"
                : "try --no-refraction or a smaller world";
        Status cast = castSegments(state, hint);
        if (cast || last) {
            if (cast && estimate.spacing != first.spacing) {
                state.stats.spacingNote =
                    "radiance cascades: probe spacing " + std::to_string(estimate.spacing) +
                    ", not " + std::to_string(first.spacing) + ": at spacing " +
                    std::to_string(first.spacing) +
                    " the segments' runs through glass and water needed more than " +
                    formatBytes(firstRefusal) + " beyond the " + formatBytes(first.bytes) +
                    " estimated, past the limit of " + formatBytes(first.limit);
            }
            return cast;
        }
        if (estimate.spacing == first.spacing) firstRefusal = state.passagesRefusedAt;
        // The next automatic spacing, as estimateCascades doubles it against the estimate.
        options.spacing = estimate.spacing * 2;
        estimate = estimateCascades(*state.world, options);
        options.spacing = 0;
    }
}

void updateStats(RadianceCascades::State& state) {
    CascadeStats& stats = state.stats;
    stats.faces = state.faces.table.size();
    stats.levels = int(state.levels.size());
    stats.probes = 0;
    stats.segments = std::int64_t(state.faces.codes.size());
    stats.passages = std::int64_t(state.passages.size());
    stats.bytes = state.faces.table.bytes() +
                  (state.faces.codes.size() + state.faces.shared.size() + state.faces.mixed.size() +
                   state.faces.mixedStart.size()) *
                      4 +
                  state.faces.skyOnly.size() + state.passages.size() * sizeof(Passage) +
                  state.sunRayMap.bytes();
    for (const LevelData& level : state.levels) {
        stats.probes += level.level.probeCount();
        stats.segments += std::int64_t(level.codes.size());
        stats.bytes += (level.codes.size() + level.shared.size() + level.mixed.size()) * 4 +
                       level.sharedStart.size() * sizeof(LevelData::SharedStart) +
                       std::uint64_t(level.level.probeCount()) * level.bins.count() * 15;
    }
}

}  // namespace luxel::voxel::cascades
