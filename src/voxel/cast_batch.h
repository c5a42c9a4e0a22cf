// Rays and hits of the GPU cast passes (voxel_cast, octree_cast) in their buffer form
// (VoxelCastRay, VoxelCastHit in shared/voxel_layout.h), converted in one place for both.
#pragma once

#include <span>
#include <vector>

#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/core/error.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/dda.h"

namespace luxel::voxel {

// Rays rounded to float, each with the same tMax; `jumps` is voxel_cast's ChunkSkip.
inline std::vector<gpu::shared::VoxelCastRay> castRaysForGpu(std::span<const Ray> rays, double tMax,
                                                             bool jumps) {
    std::vector<gpu::shared::VoxelCastRay> out(rays.size());
    const float limit = static_cast<float>(tMax);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        out[i] = {
            float(r.origin.x),    float(r.origin.y),    float(r.origin.z),    limit,
            float(r.direction.x), float(r.direction.y), float(r.direction.z), jumps ? 1u : 0u};
    }
    return out;
}

inline Hit hitFromGpu(const gpu::shared::VoxelCastHit& o) {
    Hit h;
    h.hit = (o.flags & 1u) != 0;
    h.capped = (o.flags & 2u) != 0;
    h.steps = o.steps;
    if (!h.hit) return h;
    h.voxel = {o.voxelX, o.voxelY, o.voxelZ};
    h.normal = {o.normalX, o.normalY, o.normalZ};
    h.t = o.t;
    h.point = {o.pointX, o.pointY, o.pointZ};
    h.u = o.u;
    h.v = o.v;
    return h;
}

// Runs a cast pass (its dispatch writes one VoxelCastHit per ray into `hits`), appends its GPU
// time to `timings` when given, and downloads the `count` hits.
inline Result<std::vector<gpu::shared::VoxelCastHit>> runCastPass(
    gpu::Context& context, const gpu::Dispatch& dispatch, const gpu::Buffer& hits,
    std::size_t count, std::vector<gpu::PassTiming>* timings) {
    auto passes = context.run(std::span(&dispatch, 1));
    if (!passes) return passes.error();
    if (timings) timings->insert(timings->end(), passes->begin(), passes->end());
    std::vector<gpu::shared::VoxelCastHit> out(count);
    if (Status st = context.download(hits, std::as_writable_bytes(std::span(out))); !st) {
        return st.error();
    }
    return out;
}

}  // namespace luxel::voxel
