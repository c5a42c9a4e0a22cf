// Casting the segments of the voxel radiance cascades once per world
// (docs/algorithms/voxel-radiance-cascades.md §3).
//
// The segment of a level-k probe p in bin b towards the upper probe q runs straight from
// p + tStart_k w_parent(b) (where the level below's segment for the parent bin ended) to
// p + tStart_{k+1} w_b, then on to q + tStart_{k+1} w_b (where q's segments for b's children
// start), so each chain of segments is an unbroken path and a wall anywhere on it stops the
// light. The straight part, shared by the eight corners, samples the bin along its own
// direction; only the short connector bends towards the corner.
#include <cmath>
#include <string>

#include "cascade_demand.h"
#include "cascade_passages.h"
#include "cascade_shared.h"
#include "cascade_state.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::cascades {

namespace {

// Leaves out (weight 0) the corners whose probe `from` cannot see, so the chains from a point
// near a wall lean on the probes in the open, not on those inside or behind the wall (their
// segments bend towards the wall). When it sees none, all keep their weights.
void keepVisibleCorners(const RadianceCascades::State& state, const Level& upper, Vec3d from,
                        Corners& corners) {
    const bool media = state.shading.lightPassesMedia();
    Corners visible = corners;
    float total = 0.0f;
    for (int c = 0; c < 8; ++c) {
        if (visible.weight[c] == 0.0f) continue;
        const Vec3d q = upper.position(corners.probe[c]);
        // Glass and water let the probe see through them (cascade_passages.h); cutout voxels
        // hide, as `occluded` has them.
        const bool hidden =
            media ? traceSegment(state, from, q - from, 1.0, false).end != kContinue
                  : occluded(*state.world, {from, q - from}, 1.0, state.shading.stepCap);
        if (hidden) visible.weight[c] = 0.0f;
        total += visible.weight[c];
    }
    if (total > 0.0f) corners = visible;
}

// The codes of the eight chains from `start` straight to `bend` and on to each corner's
// probe + `reach`: one cast for the straight part, then a connector per corner it leaves open.
void castBentSegments(const RadianceCascades::State& state, PassageWriter& passages, Vec3d start,
                      Vec3d bend, Vec3d reach, const Level& upper, const Corners& corners,
                      std::uint32_t* codes) {
    const SegmentTrace straight = traceSegment(state, start, bend - start, 1.0);
    if (straight.end != kContinue) {
        const std::uint32_t code = passages.codeOf(straight);
        for (int c = 0; c < 8; ++c) codes[c] = code;
        return;
    }
    for (int c = 0; c < 8; ++c) {
        if (corners.weight[c] == 0.0f) {
            codes[c] = kVoid;
        } else {
            const Vec3d end = upper.position(corners.probe[c]) + reach;
            const SegmentTrace connector = traceSegment(state, bend, end - bend, 1.0);
            if (straight.runs == 0) {
                codes[c] = passages.codeOf(connector);
                continue;
            }
            SegmentTrace chain = straight;
            appendTrace(chain, connector);
            codes[c] = passages.codeOf(chain);
        }
    }
}

// A level's codes (all kVoid) and corners (no weight) before anything is cast: a cast refused
// before or while it reaches the level leaves it so, carrying no light, instead of the last
// cast's codes, whose runs through glass index the passages this cast has cleared.
void layOutLevel(LevelData& data) {
    const Level& level = data.level;
    const int corners = level.top ? 1 : 8;
    const std::int64_t probes = level.probeCount();
    data.codes.assign(std::size_t(probes) * data.bins.count() * corners, kVoid);
    if (!level.top) data.corners.assign(std::size_t(probes), Corners{});
}

void castLevel(RadianceCascades::State& state, PassageWriter& passages, std::size_t k) {
    LevelData& data = state.levels[k];
    const Level& level = data.level;
    const bool top = level.top;
    const DirectionBins& below = k == 0 ? state.faces.bins : state.levels[k - 1].bins;
    const int bins = data.bins.count(), codesPerBin = top ? 1 : 8;
    const std::int64_t probes = level.probeCount();
    const LevelData* upper = top ? nullptr : &state.levels[k + 1];
    parallelForRange(int(probes), 1, [&](int begin, int end) {
        for (int p = begin; p < end; ++p) {
            if (passages.refused()) return;  // past the memory limit: the build is refused
            const Vec3d origin = level.position(p);
            if (!top) {
                data.corners[p] = cornersAround(upper->level, origin);
                keepVisibleCorners(state, upper->level, origin, data.corners[p]);
            }
            for (int b = 0; b < bins; ++b) {
                // Level 0 has the faces' bins; above, a bin's chain came through its parent.
                const Vec3d from = k == 0 ? data.bins.centre[b] : below.centre[data.bins.parent(b)];
                const Vec3d start = origin + from * level.tStart;
                std::uint32_t* codes = &data.codes[(std::size_t(p) * bins + b) * codesPerBin];
                if (top) {
                    codes[0] =
                        passages.codeOf(traceSegment(state, start, data.bins.centre[b], kInfinity));
                    continue;
                }
                const Vec3d bend = origin + data.bins.centre[b] * upper->level.tStart;
                castBentSegments(state, passages, start, bend,
                                 data.bins.centre[b] * upper->level.tStart, upper->level,
                                 data.corners[p], codes);
            }
        }
    });
}

// The faces' codes (all kVoid) and corners (no weight) laid out for the current face table, before
// anything is cast: a cast refused before or while it reaches the faces leaves them so, carrying
// no light, instead of the last cast's, which may belong to another table.
void layOutFaces(FaceData& faces) {
    const int count = faces.table.size();
    faces.codeOffset.resize(std::size_t(count) + 1);
    std::uint32_t offset = 0;
    for (int f = 0; f < count; ++f) {
        faces.codeOffset[f] = offset;
        offset += std::uint32_t(faces.bins.cosine[faces.table[f].normal].bin.size() * 8);
    }
    faces.codeOffset[count] = offset;
    faces.codes.assign(offset, kVoid);
    faces.corners.assign(std::size_t(count), Corners{});
    faces.skyOnly.assign(std::size_t(count), 0);
}

// Whether every weighted corner of every bin of the face's codes leaves the world at once (a
// face with none gathers nothing: its bins share kVoid).
bool seesOnlySky(const std::uint32_t* codes, std::size_t bins, const Corners& corners) {
    const std::uint32_t live = weightedCorners(corners);
    for (std::size_t i = 0; i < bins; ++i) {
        if (sharedCode(codes + i * 8, live) != kSky) return false;
    }
    return true;
}

void castFaces(RadianceCascades::State& state, PassageWriter& passages) {
    FaceData& faces = state.faces;
    const int count = faces.table.size();
    const Level& level0 = state.levels.front().level;
    parallelForRange(count, 64, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            if (passages.refused()) return;
            const Face& face = faces.table[f];
            const Int3 n = normalFromIndex(face.normal);
            const Vec3d normal{double(n.x), double(n.y), double(n.z)};
            const Vec3d centre = faceCentre(face);
            faces.corners[f] = cornersAround(level0, centre + normal * 0.5);
            keepVisibleCorners(state, level0, centre, faces.corners[f]);
            const auto& seen = faces.bins.cosine[face.normal];
            std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
            for (std::size_t i = 0; i < seen.bin.size(); ++i) {
                // Straight along the part of the bin in front of the face, then to the corners.
                const Vec3d bend = centre + seen.direction[i] * level0.tStart;
                castBentSegments(state, passages, centre, bend,
                                 faces.bins.centre[seen.bin[i]] * level0.tStart, level0,
                                 faces.corners[f], codes + i * 8);
            }
            faces.skyOnly[f] = seesOnlySky(codes, seen.bin.size(), faces.corners[f]);
        }
    });
}

}  // namespace

Status castSegments(RadianceCascades::State& state, const std::string& hint) {
    // Frees the last cast's before this one counts its own (assigning {} would keep its capacity,
    // which the budget does not see).
    state.passages = std::vector<Passage>();
    state.castMedia = mediaSignature(state.shading);
    state.castComplete = false;
    state.passagesRefusedAt = 0;
    ++state.casts;
    const std::uint64_t planned = state.plannedBytes, limit = state.memoryLimit;
    PassageWriter passages(state.passages, limit > planned ? limit - planned : 0);
    for (LevelData& level : state.levels) layOutLevel(level);
    layOutFaces(state.faces);
    for (std::size_t k = 0; k < state.levels.size() && !passages.refused(); ++k) {
        castLevel(state, passages, k);
    }
    if (!passages.refused()) castFaces(state, passages);
    // What the passes merge follows from the codes; a refused cast's too (they read what it left).
    findDemand(state);
    findSharedCodes(state);
    if (passages.refused()) {
        state.passagesRefusedAt = passages.reached();
        return Error(
            "radiance cascades: the segments' runs through glass and water need more "
            "than " +
            formatBytes(passages.reached()) + " beyond the " + formatBytes(planned) +
            " estimated, past the limit of " + formatBytes(limit) + " (" + hint + ")");
    }
    state.castComplete = true;
    return Ok{};
}

}  // namespace luxel::voxel::cascades
