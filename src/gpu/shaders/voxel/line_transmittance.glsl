// lineTransmittance (src/voxel/solver_sun.cpp) on the GPU: what of the light along a straight
// line reaches its origin, through glass and water (the entry's transmission lobe weight,
// Beer-Lambert inside, 1 - F where it leaves), to the sky or to one face. Shared by the solvers'
// light (solver_light.glsl) and the ray caster's light from emissive voxels
// (emitter_light.glsl). The includer defines, before including:
//   bool lineMedia()                       transmissive materials pass light (refraction on and
//                                          some material transmits)
//   float lineTransmission(VoxelMaterial)  the material's transmission (0 with refraction off)
//   float lineFresnel(float cosI, float ior)  the dielectric Fresnel from the air into `ior`
// and has castToSurface, walkMedium, materialIndex and materials[].
#include "shared/near_emitters.h"  // emitterRectHolds: a face target's rectangle

// Below this the light that is left counts as none (kDarkTransmittance, solver_sun.cpp).
#define LUXEL_SOLVER_DARK 1e-4
// kMaxSunRayMedia (solver_sun.h).
#define LUXEL_SOLVER_SUN_MEDIA 8

float maxComponent(vec3 c) {
    return max(c.x, max(c.y, c.z));
}

// VoxelWorld::solid: a voxel of the world with nonzero alpha (outside the world: air).
bool lineSolidAt(ivec3 c) {
    if (any(lessThan(c, ivec3(0))) ||
        any(greaterThanEqual(c, ivec3(params.sizeX, params.sizeY, params.sizeZ)))) {
        return false;
    }
    return voxelSolidAt(0u, c);
}

// The transmission lobe weight of material m entered through a face with outward `normal`
// along unit `direction` (mediumEntryTransmission, solver_sun.cpp).
float entryTransmission(VoxelMaterial m, ivec3 normal, vec3 direction) {
    const float cosV = clamp(dot(vec3(normal), -direction), 0.0, 1.0);
    return (1.0 - m.metallic) * (1.0 - lineFresnel(cosV, m.ior)) * lineTransmission(m);
}

// 1 - F where the straight line leaves the medium through `outward` (mediumExitTransmission).
float exitTransmission(VoxelMaterial m, vec3 direction, ivec3 outward) {
    const float cosI = clamp(dot(direction, vec3(outward)), 0.0, 1.0);
    return 1.0 - lineFresnel(cosI, m.ior);
}

// Through the run of transmissive voxels entered at `hit` (throughMedia, solver_sun.cpp; with
// `inside`, the ray starts in hit.voxel at hit.point and crosses no entry face).
vec3 throughMedia(Hit hit, vec3 direction, inout vec3 origin, inout int media, bool inside) {
    vec3 t = vec3(1.0);
    ivec3 cell = hit.voxel, normal = hit.normal;
    vec3 point = hit.point;
    for (;;) {
        const VoxelMaterial m = materials[materialIndex(voxelValue(cell))];
        if (!inside) t = t * entryTransmission(m, normal, direction);
        inside = false;
        ++media;
        if (!(maxComponent(t) > LUXEL_SOLVER_DARK) || media > LUXEL_SOLVER_SUN_MEDIA) {
            return vec3(0.0);
        }
        const MediumExit exit = walkMedium(cell, point, direction);
        t = t * voxelTransmittance(vec3(m.absorptionR, m.absorptionG, m.absorptionB),
                                   exit.distance);
        if (!exit.intoSolid) {
            origin = exit.point;
            return t * exitTransmission(m, direction, exit.outward);
        }
        // Another solid touches the medium: entered directly, with no interface to the air.
        cell = exit.cell + exit.outward;
        normal = -exit.outward;
        point = exit.point;
    }
    return vec3(0.0);
}

// targetHolds (solver_sun.cpp): whether `voxel` is one of the faces of the target rectangle from
// faceVoxel with normal faceNormal and `extent` (CascadeNearEmitter's encoding; 0: one face).
bool lineTargetHolds(ivec3 faceVoxel, ivec3 faceNormal, uint extent, ivec3 voxel) {
    const int axis = faceNormal.x != 0 ? 0 : (faceNormal.y != 0 ? 1 : 2);
    return emitterRectHolds(faceVoxel, axis, extent, voxel);
}

// lineTransmittance (solver_sun.cpp): along the ray until it leaves the world (toFace false: the
// sky's share, sunRayTransmittance) or meets the face (faceVoxel, faceNormal) or the rectangle of
// faces `extent` gives (that face's share, faceRayTransmittance; 0 where it leaves the world or
// meets another opaque face first).
vec3 lineTransmittance(vec3 origin, vec3 direction, bool toFace, ivec3 faceVoxel,
                       ivec3 faceNormal, uint extent) {
    const bool media = lineMedia();
    if (!media && !toFace) {
        return castToSurface(origin, direction).hit.hit ? vec3(0.0) : vec3(1.0);
    }
    vec3 t = vec3(1.0), o = origin;
    int passed = 0;
    // Each round enters at least one medium, and past LUXEL_SOLVER_SUN_MEDIA the ray is dark.
    for (int round = 0; round <= LUXEL_SOLVER_SUN_MEDIA; ++round) {
        const SurfaceHit s = castToSurface(o, direction);
        if (!s.hit.hit) return toFace ? vec3(0.0) : t;
        if (s.hit.normal == ivec3(0)) return vec3(0.0);
        if (toFace && s.hit.normal == faceNormal &&
            lineTargetHolds(faceVoxel, faceNormal, extent, s.hit.voxel)) {
            return t;
        }
        if (!media) return vec3(0.0);
        // Starting on the face of an opaque voxel under glass or water, the ray is inside the
        // medium at once: no interface with the air to enter through (as lineTransmittance).
        const ivec3 behind = s.hit.voxel + s.hit.normal;
        const bool inside = passed == 0 && !(s.hit.t > 1e-9) && lineSolidAt(behind);
        t = t * throughMedia(s.hit, direction, o, passed, inside);
        if (!(maxComponent(t) > LUXEL_SOLVER_DARK)) return vec3(0.0);
    }
    return vec3(0.0);
}

// One face (or none: the sky) as the target.
vec3 lineTransmittance(vec3 origin, vec3 direction, bool toFace, ivec3 faceVoxel,
                       ivec3 faceNormal) {
    return lineTransmittance(origin, direction, toFace, faceVoxel, faceNormal, 0u);
}
