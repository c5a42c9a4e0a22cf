// The CPU side of the shared A&W walk (src/gpu/shaders/shared/voxel_walk.h): double precision,
// and the conversion of a finished walk into a voxel::Hit, shared by the dense world's castRay
// (dda.cpp) and the octree's (src/octree/octree_trace.cpp).
#pragma once

#include <cmath>

#include "gpu/shaders/shared/glsl_compat.h"
#include "luxel/voxel/dda.h"

#define LUXEL_REAL double
#define LUXEL_REAL3 dvec3

namespace luxel::gpu::shared {

inline double voxelNextToward(double x, double toward) {
    return std::nextafter(x, toward);
}

}  // namespace luxel::gpu::shared

#include "gpu/shaders/shared/voxel_walk.h"

namespace luxel::voxel {

inline bool finiteRay(const Ray& ray) {
    const Vec3d& o = ray.origin;
    const Vec3d& d = ray.direction;
    return std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) && std::isfinite(d.x) &&
           std::isfinite(d.y) && std::isfinite(d.z) && !(d.x == 0.0 && d.y == 0.0 && d.z == 0.0);
}

inline gpu::shared::dvec3 toShared(const Vec3d& v) {
    return {v.x, v.y, v.z};
}

// A miss with `steps`, and the Hit of a finished walk (cell, entry t and face, the point snapped
// onto the face, and (u, v)), stored into `out` field by field: a Hit built on the stack and
// copied is written there in pieces and read back in other pieces, which stalls each copy on
// store forwarding (docs/algorithms/voxel-traversal.md §4.6, "Starts in lanes").
inline void writeMiss(Hit& out, int steps, bool capped = false) {
    out.hit = false;
    out.capped = capped;
    out.voxel = {0, 0, 0};
    out.normal = {0, 0, 0};
    out.t = kInfinity;
    out.point = {0.0, 0.0, 0.0};
    out.u = 0.0f;
    out.v = 0.0f;
    out.steps = steps;
}

inline void writeHit(Hit& out, const Ray& ray, const gpu::shared::VoxelTrace& trace) {
    if (!trace.hit) {
        writeMiss(out, trace.steps, trace.capped);
        return;
    }
    out.hit = true;
    out.capped = trace.capped;
    out.voxel = {trace.cell.x, trace.cell.y, trace.cell.z};
    out.normal = {0, 0, 0};
    if (trace.axis >= 0) out.normal[trace.axis] = -trace.stp[trace.axis];
    out.t = trace.t;
    const gpu::shared::VoxelSurface surface =
        gpu::shared::voxelSurface(toShared(ray.origin), toShared(ray.direction), trace);
    out.point = {surface.point.x, surface.point.y, surface.point.z};
    out.u = surface.u;
    out.v = surface.v;
    out.steps = trace.steps;
}

// writeHit into a new Hit.
inline Hit hitFromTrace(const Ray& ray, const gpu::shared::VoxelTrace& trace) {
    Hit hit;
    writeHit(hit, ray, trace);
    return hit;
}

}  // namespace luxel::voxel
