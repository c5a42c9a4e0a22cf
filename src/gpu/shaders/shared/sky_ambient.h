// The ray caster's sky ambient with occlusion (render.sky_ambient_rays;
// docs/algorithms/voxel-surfaces.md, "Sky ambient with occlusion"), the part both backends share:
// the limit on the rays, the key of their random numbers (shared/path_rng.h, with the pixel and
// sample) and the cosine-distributed direction of one ray. src/voxel/sky_ambient.cpp traces the
// rays on the CPU, voxel/sky_ambient.glsl on the GPU.
#ifndef LUXEL_GPU_SHARED_SKY_AMBIENT_H
#define LUXEL_GPU_SHARED_SKY_AMBIENT_H

#include "face_frame.h"
#include "glsl_compat.h"
#include "optics.h"

// Most rays per shaded point (ShadeOptions::skyAmbientRays, kMaxSkyAmbientRays).
#define LUXEL_SKY_AMBIENT_MAX_RAYS 256
// The rays' numbers are PathRng(LUXEL_SKY_AMBIENT_SEED, y * width + x, sample) on both backends
// (the GPU passes it as the low word, the high word 0).
#define LUXEL_SKY_AMBIENT_SEED 0x5ca1ab1eu

LUXEL_SHARED_BEGIN

// A cosine-distributed unit direction about the axis-aligned face normal from two uniform numbers
// in [0, 1) (pdf cos / π), in the face's frame (face_frame.h, as the path tracer's
// cosineDirection), in float: u1 < 1, so the ray leaves the face.
LUXEL_FUNC vec3 skyAmbientDirection(ivec3 normal, float u1, float u2) {
    const vec3 tu = faceTangentU(normal);
    const vec3 tv = faceTangentV(normal);
    const float r = sqrt(u1);
    const float phi = 2.0f * LUXEL_OPTICS_PI * u2;
    const float z = sqrt(1.0f - u1);
    return tu * (r * cos(phi)) + tv * (r * sin(phi)) +
           vec3(float(normal.x), float(normal.y), float(normal.z)) * z;
}

LUXEL_SHARED_END

#endif
