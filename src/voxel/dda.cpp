// castRay: the shared traversal kernel (src/gpu/shaders/shared/voxel_dda.h, the same code the GPU
// runs) in double over a VoxelWorld; conventions in dda.h. With the brick distances current (the
// usual case) the CPU runs its own loop for that kernel (src/voxel/fast_walk.h), which visits and
// jumps exactly as the shared one does.
#include "luxel/voxel/dda.h"

#include <bit>
#include <cmath>

#include "luxel/core/parallel.h"
#include "voxel/fast_walk.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel {
namespace shared = gpu::shared;

namespace {

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

}  // namespace

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
        for (int i = begin; i < end; ++i) hits[i] = castRay(world, rays[i], tMax, stepCap, skip);
    });
    return hits;
}

}  // namespace luxel::voxel
