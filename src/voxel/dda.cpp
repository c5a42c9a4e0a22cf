// castRay: the shared traversal kernel (src/gpu/shaders/shared/voxel_dda.h, the same code the GPU
// runs) in double over a VoxelWorld; conventions in dda.h.
#include "luxel/voxel/dda.h"

#include <bit>
#include <cmath>

#include "luxel/core/parallel.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

bool finite(const Vec3d& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

shared::dvec3 toShared(const Vec3d& v) {
    return {v.x, v.y, v.z};
}

}  // namespace

Hit castRay(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap, ChunkSkip skip) {
    Hit hit;
    const Int3 size = world.size();
    const Vec3d& d = ray.direction;
    if (!finite(ray.origin) || !finite(d) || (d.x == 0.0 && d.y == 0.0 && d.z == 0.0) ||
        !(tMax >= 0.0)) {
        return hit;
    }
    const int cap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    const shared::dvec3 o = toShared(ray.origin), dir = toShared(d);
    const shared::VoxelTrace trace =
        shared::voxelTraverse(world, {size.x, size.y, size.z}, chunkShift, o, dir, tMax, cap,
                              skip == ChunkSkip::Enabled, world.emptySpaceCurrent());
    hit.steps = trace.steps;
    hit.capped = trace.capped;
    if (!trace.hit) return hit;
    hit.hit = true;
    hit.voxel = {trace.cell.x, trace.cell.y, trace.cell.z};
    hit.t = trace.t;
    if (trace.axis >= 0) hit.normal[trace.axis] = -trace.stp[trace.axis];
    const shared::VoxelSurface surface = shared::voxelSurface(o, dir, trace);
    hit.point = {surface.point.x, surface.point.y, surface.point.z};
    hit.u = surface.u;
    hit.v = surface.v;
    return hit;
}

std::vector<Hit> castRays(const VoxelWorld& world, std::span<const Ray> rays, double tMax,
                          int stepCap, ChunkSkip skip) {
    std::vector<Hit> hits(rays.size());
    parallelForRange(static_cast<int>(rays.size()), 1024, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) hits[i] = castRay(world, rays[i], tMax, stepCap, skip);
    });
    return hits;
}

}  // namespace luxel::voxel
