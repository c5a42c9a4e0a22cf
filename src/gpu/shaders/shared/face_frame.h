// The tangent frame of an axis-aligned voxel face, the one castRay's (u, v) use: x faces take
// (z, y), y faces (x, z), z faces (x, y), whatever the normal's sign. One definition for the ray
// caster's normal maps, the path tracer's cosine and GGX directions and the sky ambient's rays, on
// the CPU (shading_physical.cpp, path_trace_bsdf.cpp, shared/sky_ambient.h) and the GPU
// (voxel_physical.glsl, path_surface.glsl).
#ifndef LUXEL_GPU_SHARED_FACE_FRAME_H
#define LUXEL_GPU_SHARED_FACE_FRAME_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

LUXEL_FUNC vec3 faceTangentU(ivec3 normal) {
    return normal.x != 0 ? vec3(0.0f, 0.0f, 1.0f) : vec3(1.0f, 0.0f, 0.0f);
}

LUXEL_FUNC vec3 faceTangentV(ivec3 normal) {
    return normal.y != 0 ? vec3(0.0f, 0.0f, 1.0f) : vec3(0.0f, 1.0f, 0.0f);
}

LUXEL_SHARED_END

#endif
