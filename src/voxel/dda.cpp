// castRay: the shared traversal kernel (src/gpu/shaders/shared/voxel_dda.h, the same code the GPU
// runs) in double over a VoxelWorld; conventions in dda.h. With the brick reach current (the
// usual case) the CPU runs its own loop for that kernel (src/voxel/fast_walk.h), which visits and
// jumps exactly as the shared one does.
#include "luxel/voxel/dda.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "luxel/core/parallel.h"
#include "voxel/cast_stream.h"
#include "voxel/fast_walk.h"
#include "voxel/parallel_beam.h"
#include "voxel/tile_start.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel {
namespace shared = gpu::shared;

namespace {

// Rays of a camera tile from outside the world that walk their own frustum on from the tile's
// plane (further planes, clear sub-tiles); from inside, the tile's plane lies near the origin and
// the sub-tiles' walks cost more than they save (docs/algorithms/voxel-traversal.md §4.6
// "Sub-tiles from outside").
constexpr std::size_t kSubTileRays = 16;

int resolvedCap(const VoxelWorld& world, int stepCap) {
    const Int3 size = world.size();
    return stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
}

shared::VoxelTrace trace(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap,
                         ChunkSkip skip) {
    const Int3 size = world.size();
    const int cap = resolvedCap(world, stepCap);
    if (skip == ChunkSkip::Enabled) return fast::traverseAny(world, ray, tMax, cap);
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    return shared::voxelTraverse(world, {size.x, size.y, size.z}, chunkShift, toShared(ray.origin),
                                 toShared(ray.direction), tMax, cap, skip == ChunkSkip::Enabled,
                                 world.emptySpaceCurrent());
}

// The SIMD walk needs the reach current (else castRay runs the shared kernel).
bool streamable(const VoxelWorld& world) {
    return world.emptySpaceCurrent();
}

// Hands the trace castRay makes of each ray to `take(i, trace)`. Rays from inside the world take
// castRay's one-ray loop (stream::Lanes), each handed over at once while the ray is at hand: a
// buffer of traces between the walk and the hit cost 5% to 12% on such rays
// (docs/algorithms/voxel-traversal.md §4.5). The others run through the SIMD walk in blocks,
// which also settles the rays that never walk (non-finite, tMax < 0, not eligible).
template <typename Take>
void streamRays(const VoxelWorld& world, std::span<const Ray> rays, double tMax, int stepCap,
                Take&& take) {
    constexpr std::size_t kBlock = 1024;
    shared::VoxelTrace traces[kBlock];
    // The lanes' rays of a block that mixes both kinds (a vector: Ray's members zero-initialise).
    thread_local std::vector<Ray> laneRays(kBlock);
    std::size_t index[kBlock];
    const stream::Walk walk{&world, tMax, resolvedCap(world, stepCap)};
    const bool walkable = tMax >= 0.0;
    for (std::size_t first = 0; first < rays.size(); first += kBlock) {
        const std::size_t n = std::min(kBlock, rays.size() - first);
        std::size_t m = 0;
        for (std::size_t i = first; i < first + n; ++i) {
            const Ray& ray = rays[i];
            if (stream::startsInside(world, ray) && walkable && finiteRay(ray) &&
                fast::eligible(world, ray)) {
                take(i, fast::traverse(world, ray, tMax, walk.cap));
            } else {
                laneRays[m] = ray;
                index[m++] = i;
            }
        }
        if (m == 0) continue;
        // Every ray of the block takes a lane: no copy.
        const bool all = m == n;
        stream::trace(walk, all ? rays.subspan(first, n) : std::span<const Ray>(laneRays.data(), m),
                      traces);
        for (std::size_t j = 0; j < m; ++j) take(all ? first + j : index[j], traces[j]);
    }
}

}  // namespace

void castRayBatch(const VoxelWorld& world, std::span<const Ray> rays, std::span<Hit> hits,
                  double tMax, int stepCap) {
    if (!streamable(world)) {
        for (std::size_t i = 0; i < rays.size(); ++i)
            hits[i] = castRay(world, rays[i], tMax, stepCap);
        return;
    }
    streamRays(world, rays, tMax, stepCap, [&](std::size_t i, const shared::VoxelTrace& trace) {
        hits[i] = hitFromTrace(rays[i], trace);
    });
}

void castCameraRays(const VoxelWorld& world, std::span<const Ray> rays, std::span<Hit> hits,
                    double tMax, int stepCap) {
    const Int3 size = world.size();
    const int cap = resolvedCap(world, stepCap);
    // The skip changes the loop count, so it is taken only where the step cap cannot end a walk
    // (a walk visits at most sx + sy + sz cells, dda.h).
    if (!streamable(world) || cap < size.x + size.y + size.z) {
        castRayBatch(world, rays, hits, tMax, stepCap);
        return;
    }
    // Every ray in the one-ray loop: after a skip the walk is mostly voxel steps near the surface,
    // where that loop is faster than the SIMD lanes (docs/algorithms/voxel-traversal.md §4.6).
    const bool walkable = tMax >= 0.0;
    for (std::size_t first = 0; first < rays.size(); first += kCameraTileRays) {
        const std::span<const Ray> tile =
            rays.subspan(first, std::min(kCameraTileRays, rays.size() - first));
        // The rays are read once: each sub-tile's bounds about the tile's main axis, the tile's
        // their union (the same bounds as reading the tile whole).
        stream::TileRays parts[kCameraTileRays / kSubTileRays];
        const std::size_t partCount = (tile.size() + kSubTileRays - 1) / kSubTileRays;
        const bool outside = !stream::startsInside(world, tile.front());
        // From inside, no sub-tiles: the tile's bounds alone.
        stream::TileRays all = outside ? stream::TileRays{} : stream::tileRays(tile);
        for (std::size_t k = 0; outside && k < partCount; ++k) {
            const std::span<const Ray> part = tile.subspan(
                k * kSubTileRays, std::min(kSubTileRays, tile.size() - k * kSubTileRays));
            parts[k] = k == 0 ? stream::tileRays(part) : stream::tileRays(part, all.m, all.sgn);
            all = k == 0 ? parts[0] : stream::mergeTileRays(all, parts[k]);
            if (!all.ok) break;
        }
        const stream::Skip whole = stream::tileSkip(world, all);
        for (std::size_t sub = 0; sub < tile.size(); sub += kSubTileRays) {
            const std::span<const Ray> part =
                tile.subspan(sub, std::min(kSubTileRays, tile.size() - sub));
            stream::Skip skip = whole;
            if (whole.axis >= 0 && !whole.clear && part.size() == kSubTileRays && outside) {
                // A sub-tile whose first ray has another main axis walks about its own.
                const stream::TileRays& own = parts[sub / kSubTileRays];
                const stream::Skip ownSkip = stream::mainAxis(part.front().direction) == own.m
                                                 ? stream::tileSkip(world, own, whole)
                                                 : stream::tileSkip(world, part, whole);
                if (ownSkip.axis >= 0) skip = ownSkip;
            }
            const std::size_t at = first + sub;
            // A tile with a skip has only finite rays (tileSkip checks them).
            const bool finite = skip.axis >= 0;
            if (skip.clear) {
                // No solid voxel in the tile's frustum: every ray misses, its walk one jump out of
                // the world where it enters it (§4.6 "Clear tiles"), none where it does not.
                for (std::size_t j = 0; j < part.size(); ++j) {
                    const Ray& ray = part[j];
                    Hit& hit = hits[at + j];
                    if (!walkable || !fast::eligible(world, ray)) {
                        hit = castRay(world, ray, tMax, stepCap);
                        continue;
                    }
                    writeMiss(hit, fast::entersWorld(ray, size, tMax) ? 1 : 0);
                }
                continue;
            }
            const auto one = [&](Hit& hit, const Ray& ray) {
                if (walkable && (finite || finiteRay(ray)) && fast::eligible(world, ray)) {
                    writeHit(hit, ray, fast::traverse<true>(world, ray, tMax, cap, skip));
                } else {
                    hit = castRay(world, ray, tMax, stepCap);
                }
            };
            // From inside the world every ray starts in its origin's cell: the one-ray start.
            if (!finite || !walkable || !outside) {
                for (std::size_t j = 0; j < part.size(); ++j) one(hits[at + j], part[j]);
                continue;
            }
            // The rays' starts and jumps to the plane in SIMD lanes, then each ray's walk on from
            // there in the one-ray loop (§4.6 "Starts in lanes").
            shared::VoxelWalk walks[kSubTileRays];
            stream::PlaneStart starts[kSubTileRays];
            stream::startAtPlane(world, part, skip, tMax, walks, starts);
            for (std::size_t j = 0; j < part.size(); ++j) {
                const Ray& ray = part[j];
                Hit& hit = hits[at + j];
                switch (starts[j]) {
                    case stream::PlaneStart::StartMissed:
                    case stream::PlaneStart::JumpMissed:
                        writeMiss(hit, starts[j] == stream::PlaneStart::JumpMissed ? 1 : 0);
                        break;
                    case stream::PlaneStart::Jumped:
                    case stream::PlaneStart::NotTaken:
                        writeHit(hit, ray,
                                 fast::walkFrom(world, walks[j], tMax, cap,
                                                starts[j] == stream::PlaneStart::Jumped ? 1 : 0));
                        break;
                    case stream::PlaneStart::OneRay:
                        one(hit, ray);
                        break;
                }
            }
        }
    }
}

void occludedBatch(const VoxelWorld& world, std::span<const Ray> rays,
                   std::span<std::uint8_t> occludedOut, double tMax, int stepCap) {
    if (!streamable(world)) {
        for (std::size_t i = 0; i < rays.size(); ++i) {
            occludedOut[i] = occluded(world, rays[i], tMax, stepCap);
        }
        return;
    }
    const auto plain = [&](std::size_t first, std::size_t end) {
        if (first == end) return;
        streamRays(world, rays.subspan(first, end - first), tMax, stepCap,
                   [&](std::size_t i, const shared::VoxelTrace& trace) {
                       occludedOut[first + i] = trace.hit;
                   });
    };
    const Int3 size = world.size();
    const int cap = resolvedCap(world, stepCap);
    // Runs of parallel rays with nearby origins (a beam) end their walks at the beam's plane,
    // past which none of them meets a solid voxel (docs/algorithms/voxel-traversal.md §4.7). The
    // whole walk may reach a step cap that the shorter one does not (occluded is then false): so
    // only where the cap cannot end a walk (a walk visits at most sx + sy + sz cells, dda.h).
    if (!(tMax >= 0.0) || cap < size.x + size.y + size.z) {
        plain(0, rays.size());
        return;
    }
    stream::BeamScan beams(world);
    std::size_t pending = 0;  // the first ray not yet cast
    for (std::size_t i = 0; i < rays.size();) {
        const std::size_t n = stream::beamLength(world, rays.subspan(i));
        if (n < stream::kMinBeamRays) {
            i += std::max<std::size_t>(n, 1);
            continue;
        }
        plain(pending, i);
        const std::span<const Ray> beam = rays.subspan(i, n);
        const stream::BeamLimit limit = beams.limit(beam);
        for (std::size_t j = 0; j < n; ++j) {
            const double tEnd = std::min(tMax, stream::beamPlaneT(beam[j], limit));
            occludedOut[i + j] = tEnd >= 0.0 && fast::traverse(world, beam[j], tEnd, cap).hit;
        }
        i += n;
        pending = i;
    }
    plain(pending, rays.size());
}

Hit castRay(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap, ChunkSkip skip) {
    if (!finiteRay(ray) || !(tMax >= 0.0)) return Hit{};
    return hitFromTrace(ray, trace(world, ray, tMax, stepCap, skip));
}

Hit castRayShared(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap,
                  ChunkSkip skip) {
    const Int3 size = world.size();
    if (!finiteRay(ray) || !(tMax >= 0.0)) return Hit{};
    const int cap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    return hitFromTrace(
        ray, shared::voxelTraverse(world, {size.x, size.y, size.z}, chunkShift,
                                   toShared(ray.origin), toShared(ray.direction), tMax, cap,
                                   skip == ChunkSkip::Enabled, world.emptySpaceCurrent()));
}

bool occluded(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap) {
    if (!finiteRay(ray) || !(tMax >= 0.0)) return false;
    return trace(world, ray, tMax, stepCap, ChunkSkip::Enabled).hit;
}

std::vector<Hit> castRays(const VoxelWorld& world, std::span<const Ray> rays, double tMax,
                          int stepCap, ChunkSkip skip) {
    std::vector<Hit> hits(rays.size());
    parallelForRange(static_cast<int>(rays.size()), 1024, [&](int begin, int end) {
        if (skip == ChunkSkip::Enabled) {
            castRayBatch(world, rays.subspan(begin, end - begin),
                         std::span<Hit>(hits).subspan(begin, end - begin), tMax, stepCap);
            return;
        }
        for (int i = begin; i < end; ++i) hits[i] = castRay(world, rays[i], tMax, stepCap, skip);
    });
    return hits;
}

}  // namespace luxel::voxel
