// One lamp rectangle (EmitterFace, emitter_light.h) as the shaders store it and where it lies,
// for the ray caster's grid of lamps (emitter_light.cpp) and the radiance cascades' picks among
// them (cascades/glossy_emitters.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gpu/shaders/shared/near_emitters.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/emitter_light.h"

namespace luxel::voxel {

// EmitterFace is the shader's CascadeNearEmitter, byte for byte.
static_assert(sizeof(EmitterFace) == sizeof(gpu::shared::CascadeNearEmitter) &&
              offsetof(EmitterFace, normal) == offsetof(gpu::shared::CascadeNearEmitter, normal) &&
              offsetof(EmitterFace, r) == offsetof(gpu::shared::CascadeNearEmitter, r) &&
              offsetof(EmitterFace, extent) == offsetof(gpu::shared::CascadeNearEmitter, extent));

inline gpu::shared::CascadeNearEmitter shaderFace(const EmitterFace& f) {
    return {f.x, f.y, f.z, f.normal, f.r, f.g, f.b, f.extent};
}

// The centre of the emitter's rectangle (on the face's plane, the voxel's side it faces).
inline Vec3d rectCentre(const EmitterFace& e) {
    const int axis = int(e.normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
    Vec3d c{double(e.x), double(e.y), double(e.z)};
    if ((e.normal & 1u) == 0u) c[axis] += 1.0;
    c[a] += 0.5 * double(gpu::shared::emitterSizeA(e.extent));
    c[b] += 0.5 * double(gpu::shared::emitterSizeB(e.extent));
    return c;
}

// Squared distance from p to the axis-aligned box [lo, hi].
inline double boxDistanceSquared(Vec3d p, Vec3d lo, Vec3d hi) {
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max({lo[a] - p[a], 0.0, p[a] - hi[a]});
        d2 += d * d;
    }
    return d2;
}

}  // namespace luxel::voxel
