// The light of emissive faces near a point of the radiance cascades' picture, exactly
// (docs/algorithms/voxel-radiance-cascades.md §4.1, "Near a lamp"): the weight that splits each
// emitter's light between the faces' interpolated irradiance (far) and the pixel's own exact
// term (near), and Lambert's contour integral over the emitting square at the pixel's point.
// Shared by the CPU picture (src/voxel/cascades/cascade_near_emitters.cpp) and the GPU's
// (src/gpu/shaders/voxel/near_emitters.glsl), in float on both so they agree to rounding; the
// faces' own far part (cascade_emitters.cpp) takes the same weight.
//
// Buffers of cascades_picture after shared/cascade_picture_layout.h's 0..18:
//   19 RgbTexel per face: its emitter irradiance less the near part at its centre (far part)
//   20 uint per face + 1: where each face's list of near emitters starts in 21 (CSR offsets)
//   21 CascadeNearEmitter: the lists, each entry an emitting face and its radiance
#ifndef LUXEL_GPU_SHARED_NEAR_EMITTERS_H
#define LUXEL_GPU_SHARED_NEAR_EMITTERS_H

#include "glsl_compat.h"

// Inside this distance (voxels, from the receiving point to the emitting face's centre) an
// emitter's light is the pixel's own exact term alone; past the outer one it is the faces'
// interpolated irradiance alone; between, a smooth step shares it (measured on thin-walls:
// docs/voxel-gi-measures.md, "Near a lamp").
#define LUXEL_NEAR_EMITTER_INNER 1.5f
#define LUXEL_NEAR_EMITTER_OUTER 4.0f
// The glossy highlight of a near emitter takes each quarter of the face as up to this many points
// a side (the quarter's one visibility ray for all): a GGX lobe of roughness 0.4 is about as wide
// as a quarter seen from a voxel away, so one point per quarter draws its reflection as four
// spots (nearHighlightSide picks fewer where the lobe is wider than the points' spacing).
#define LUXEL_NEAR_HIGHLIGHT_SIDE 3

LUXEL_SHARED_BEGIN

// An emitting face as the picture's near lists hold it: its voxel, normalIndex (0 +x, 1 -x,
// 2 +y, 3 -y, 4 +z, 5 -z) and emitted radiance. The ray caster's lamp light
// (shared/emitter_light.h) uses the same record for a rectangle of coplanar faces of one
// radiance: `extent` holds its size less one along a = (axis + 1) % 3 (low 16 bits) and
// b = (axis + 2) % 3 (high 16 bits), from the voxel given; the cascades' faces have extent 0.
struct CascadeNearEmitter {
    int x, y, z;
    uint normal;
    float r, g, b;
    uint extent;
};

// The size of an emitter's rectangle along a and along b (CascadeNearEmitter's extent).
LUXEL_FUNC uint emitterSizeA(uint extent) {
    return (extent & 0xffffu) + 1u;
}
LUXEL_FUNC uint emitterSizeB(uint extent) {
    return (extent >> 16u) + 1u;
}

// Whether `voxel` is one of the rectangle's: on the plane of `axis` (its normal / 2), from
// `corner` up to its size along a and b (faceRayTransmittance's target, both backends).
LUXEL_FUNC bool emitterRectHolds(ivec3 corner, int axis, uint extent, ivec3 voxel) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const int da = voxel[a] - corner[a], db = voxel[b] - corner[b];
    return voxel[axis] == corner[axis] && da >= 0 && db >= 0 && da < int(emitterSizeA(extent)) &&
           db < int(emitterSizeB(extent));
}

// The share of an emitter's light taken exactly at a point `d` voxels from its centre: 1 within
// `inner`, 0 from `outer` on, a smoothstep between (continuous with its slope, so no seam).
LUXEL_FUNC float nearEmitterWeight(float d, float inner, float outer) {
    if (!(d > inner)) return 1.0f;
    if (!(d < outer)) return 0.0f;
    const float t = (d - inner) / (outer - inner);
    return 1.0f - t * t * (3.0f - 2.0f * t);
}

// The point with coordinate `n` on `axis` and `pa`, `pb` on a = (axis + 1) % 3 and
// b = (axis + 2) % 3, made whole: storing into a component picked at run time, then reading the
// vector, stalls the CPU's store forwarding (docs/algorithms/voxel-radiance-cascades.md §5).
LUXEL_FUNC vec3 nearEmitterPlanePoint(int axis, float n, float pa, float pb) {
    return axis == 0 ? vec3(n, pa, pb) : (axis == 1 ? vec3(pb, n, pa) : vec3(pa, pb, n));
}

LUXEL_FUNC vec3 nearEmitterNormal(uint normal) {
    const float outward = (normal & 1u) == 0u ? 1.0f : -1.0f;
    const uint axis = normal / 2u;
    return vec3(axis == 0u ? outward : 0.0f, axis == 1u ? outward : 0.0f,
                axis == 2u ? outward : 0.0f);
}

// The emitting face's centre, or with `quarter` 0..3 the centre of that quarter (faceCentre,
// faceQuarterCentre: where the visibility rays aim).
LUXEL_FUNC vec3 nearEmitterPoint(CascadeNearEmitter e, int quarter) {
    const vec3 p = vec3(float(e.x) + 0.5f, float(e.y) + 0.5f, float(e.z) + 0.5f) +
                   nearEmitterNormal(e.normal) * 0.5f;
    if (quarter < 0) return p;
    const int axis = int(e.normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
    return nearEmitterPlanePoint(axis, p[axis], p[a] + ((quarter & 1) != 0 ? 0.25f : -0.25f),
                                 p[b] + ((quarter & 2) != 0 ? 0.25f : -0.25f));
}

// Point `sub` (0 .. side^2 - 1) of a side x side grid of cell centres over quarter `quarter` of
// the emitting face (the highlight's points).
LUXEL_FUNC vec3 nearEmitterQuarterPoint(CascadeNearEmitter e, int quarter, int sub, int side) {
    const vec3 p = nearEmitterPoint(e, quarter);
    const int axis = int(e.normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
    const float cell = 0.5f / float(side);
    return nearEmitterPlanePoint(axis, p[axis], p[a] + ((float(sub % side) + 0.5f) * cell - 0.25f),
                                 p[b] + ((float(sub / side) + 0.5f) * cell - 0.25f));
}

// Points a side of each quarter for the highlight seen through a GGX lobe of `alpha` from
// `distance` voxels (to the face's centre): the points of a quarter lie 0.5 / (side distance)
// radians apart, and the fewest that keeps that spacing within alpha are taken, at most
// LUXEL_NEAR_HIGHLIGHT_SIDE. The default roughness 0.7 (alpha 0.49) needs one point per quarter
// past a voxel, so most pixels evaluate the lobe 4 times per emitter instead of 36.
LUXEL_FUNC int nearHighlightSide(float distance, float alpha) {
    const float spacing = 0.5f / (max(distance, 0.25f) * max(alpha, 1e-3f));
    return spacing <= 1.0f ? 1 : (spacing <= 2.0f ? 2 : LUXEL_NEAR_HIGHLIGHT_SIDE);
}

// Corner `i` (0..3, in order around it) of the emitting face (faceCorners, cascade_emitters.cpp).
LUXEL_FUNC vec3 nearEmitterCorner(CascadeNearEmitter e, int i) {
    const int axis = int(e.normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
    const vec3 c = vec3(float(e.x), float(e.y), float(e.z));
    return nearEmitterPlanePoint(axis, (e.normal & 1u) == 0u ? c[axis] + 1.0f : c[axis],
                                 (i == 1 || i == 2) ? c[a] + 1.0f : c[a],
                                 (i == 2 || i == 3) ? c[b] + 1.0f : c[b]);
}

// Lambert's contour integral without L over the quadrilateral c0..c3 (in order around it): the
// projected solid angle / 2 of that polygon at `x` with unit normal `n`, |sum_i theta_i n . u_i|
// / 2. The caller makes sure the polygon lies in front of x's plane and faces x.
LUXEL_FUNC float quadFormFactor(vec3 x, vec3 n, vec3 c0, vec3 c1, vec3 c2, vec3 c3) {
    float sum = 0.0f;
    vec3 v0 = normalize(c0 - x);
    for (int i = 0; i < 4; ++i) {
        const vec3 v1 = normalize((i == 0 ? c1 : (i == 1 ? c2 : (i == 2 ? c3 : c0))) - x);
        const vec3 c = cross(v0, v1);
        const float s = length(c);
        if (s > 1e-12f) sum += atan(s, dot(v0, v1)) * dot(n, c) / s;
        v0 = v1;
    }
    return abs(sum) * 0.5f;
}

// quadFormFactor of the emitting square at `x`; 0 unless the emitter faces x and lies in front
// of it (the square never straddles the receiving plane: both lie on voxel planes).
LUXEL_FUNC float nearEmitterFormFactor(vec3 x, vec3 n, CascadeNearEmitter e) {
    const vec3 toReceiver = x - nearEmitterPoint(e, -1);
    if (!(dot(nearEmitterNormal(e.normal), toReceiver) > 0.0f) || !(dot(n, toReceiver) < 0.0f)) {
        return 0.0f;
    }
    return quadFormFactor(x, n, nearEmitterCorner(e, 0), nearEmitterCorner(e, 1),
                          nearEmitterCorner(e, 2), nearEmitterCorner(e, 3));
}

LUXEL_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(luxel::gpu::shared::CascadeNearEmitter) == 32);
static_assert(offsetof(luxel::gpu::shared::CascadeNearEmitter, normal) == 12);
static_assert(offsetof(luxel::gpu::shared::CascadeNearEmitter, r) == 16);
#endif

#endif
