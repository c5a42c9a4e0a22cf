// The ray caster's light from emissive voxel faces (docs/algorithms/voxel-surfaces.md, "Light
// from emissive voxels"): which faces light a point, the fade that ends their reach, and the
// fixed points on a face that the shadow rays aim at. The exact unoccluded light of a face is
// nearEmitterFormFactor (shared/near_emitters.h). Shared by the CPU (src/voxel/emitter_light.cpp)
// and the GPU (src/gpu/shaders/voxel/emitter_light.glsl), in float on both.
//
// Buffers of voxel_render after shared/voxel_layout.h's 0..14:
//   15 uint per grid cell + 1: where each cell's list of faces starts in 16 (CSR offsets); the
//      grid covers the world in cubes of LUXEL_EMITTER_CELL voxels, x fastest
//   16 uint: the lists, each entry an index into 17
//   17 CascadeNearEmitter: the emitters, rectangles of open emissive faces of one radiance on one
//      plane (voxel, normal index, radiance, extent)
#ifndef LUXEL_GPU_SHARED_EMITTER_LIGHT_H
#define LUXEL_GPU_SHARED_EMITTER_LIGHT_H

#include "glsl_compat.h"
#include "near_emitters.h"

// Side of the grid's cells, in voxels.
#define LUXEL_EMITTER_CELL 8
// The emitters that light one point: the strongest (by unoccluded light) this many get shadow
// rays, the rest none (a bound on the cost per point in worlds with many lamps).
#define LUXEL_EMITTER_MAX_FACES 16
// Shadow rays over all the hits of one camera sample's path (primary, mirror and refracted ones,
// in the tracer's order): each hit takes as many of its strongest faces as the rays left allow
// (faces x render.emitter_rays), later hits none. Bounds the rays of a pixel where glass splits a
// path into dozens of hits, and keeps the GPU shader's loops within what software rasterisers
// allow (llvmpipe ends all loops of an invocation after 65535 iterations in all).
#define LUXEL_EMITTER_PATH_RAYS 64
// Shadow rays per face: render.emitter_rays in 1..LUXEL_EMITTER_MAX_RAYS.
#define LUXEL_EMITTER_MAX_RAYS 64
// Coplanar open faces of one radiance are merged into rectangles of at most this many faces a
// side (EmitterLights::build), each lit as one emitter with its exact light and
// render.emitter_rays shadow rays over it (larger ones would draw coarser penumbrae).
#define LUXEL_EMITTER_RECT_SIDE 4
// The default floor: a face whose unoccluded irradiance (largest channel) at a point is below
// this lights it not at all, and below twice this only partly (emitterFade).
#define LUXEL_EMITTER_FLOOR 5e-4f

LUXEL_SHARED_BEGIN

// The share of a face's light kept at a point where its unoccluded irradiance (largest channel)
// is `e`: 0 up to `threshold` (the floor), rising linearly to 1 at twice that, so the reach ends
// without an edge.
LUXEL_FUNC float emitterFade(float e, float threshold) {
    return clamp((e - threshold) / threshold, 0.0f, 1.0f);
}

// The rank by which a point keeps its strongest faces: the unoccluded irradiance `e` (>= 0) with
// its 10 lowest mantissa bits cleared, so faces of equal light by symmetry, whose float values
// differ in the last bits between the CPU and the GPU, tie and the earlier in the list wins on
// both.
LUXEL_FUNC uint emitterRank(float e) {
#ifdef __cplusplus
    return std::bit_cast<uint>(e) & ~0x3ffu;
#else
    return floatBitsToUint(e) & ~0x3ffu;
#endif
}

// The rectangle an emitter stands for (CascadeNearEmitter's extent), in world coordinates along
// its plane's axes a = (axis + 1) % 3 and b = (axis + 2) % 3: [loA, hiA] x [loB, hiB].
struct EmitterSpan {
    float loA, hiA, loB, hiB;
};

// The emitter's rectangle cut to the part in front of the receiving face through `x` with
// axis-aligned outward normal `n`: a receiving plane across the emitter's own axes cuts its
// rectangle along that axis (both lie on voxel planes), and the part behind it lights nothing.
// Empty (lo >= hi on an axis) when nothing is left.
LUXEL_FUNC EmitterSpan emitterSpanInFront(vec3 x, vec3 n, CascadeNearEmitter e) {
    const int axis = int(e.normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
    const vec3 c = vec3(float(e.x), float(e.y), float(e.z));
    EmitterSpan s = EmitterSpan(c[a], c[a] + float(emitterSizeA(e.extent)), c[b],
                                c[b] + float(emitterSizeB(e.extent)));
    if (n[a] > 0.5f) s.loA = max(s.loA, x[a]);
    if (n[a] < -0.5f) s.hiA = min(s.hiA, x[a]);
    if (n[b] > 0.5f) s.loB = max(s.loB, x[b]);
    if (n[b] < -0.5f) s.hiB = min(s.hiB, x[b]);
    return s;
}

LUXEL_FUNC float emitterSpanArea(EmitterSpan s) {
    return max(s.hiA - s.loA, 0.0f) * max(s.hiB - s.loB, 0.0f);
}

// The coordinate of the emitter's plane on its axis (its voxels' far side for an outward normal
// towards +axis).
LUXEL_FUNC float emitterPlaneCoordinate(CascadeNearEmitter e) {
    const int axis = int(e.normal / 2u);
    const float c = float(axis == 0 ? e.x : (axis == 1 ? e.y : e.z));
    return (e.normal & 1u) == 0u ? c + 1.0f : c;
}

// Corner `i` (0..3, in order around it, as nearEmitterCorner) of the span on the emitter's plane.
LUXEL_FUNC vec3 emitterSpanCorner(CascadeNearEmitter e, EmitterSpan s, int i) {
    return nearEmitterPlanePoint(int(e.normal / 2u), emitterPlaneCoordinate(e),
                                 (i == 1 || i == 2) ? s.hiA : s.loA,
                                 (i == 2 || i == 3) ? s.hiB : s.loB);
}

// The unoccluded light of the span at `x` (receiving normal `n`), Lambert's contour integral
// (quadFormFactor); 0 when the span is empty, faces away from x or, on a plane parallel to the
// receiver's, lies behind it. For a unit face it is nearEmitterFormFactor.
LUXEL_FUNC float emitterFormFactor(vec3 x, vec3 n, CascadeNearEmitter e, EmitterSpan s) {
    if (!(emitterSpanArea(s) > 0.0f)) return 0.0f;
    const vec3 c0 = emitterSpanCorner(e, s, 0);
    const vec3 toReceiver = x - c0;
    const int axis = int(e.normal / 2u);
    if (!(dot(nearEmitterNormal(e.normal), toReceiver) > 0.0f)) return 0.0f;
    if (abs(n[axis]) > 0.5f && !(dot(n, toReceiver) < 0.0f)) return 0.0f;
    return quadFormFactor(x, n, c0, emitterSpanCorner(e, s, 1), emitterSpanCorner(e, s, 2),
                          emitterSpanCorner(e, s, 3));
}

// Where shadow ray `i` of `n` aims on the span: a fixed rank-1 lattice over it (u stratified,
// v by the golden ratio), the same at every point so the picture has no noise (a penumbra is
// drawn in n steps).
LUXEL_FUNC vec3 emitterRayTarget(CascadeNearEmitter e, EmitterSpan s, int i, int n) {
    const float u = (float(i) + 0.5f) / float(n);
    const float t = (float(i) + 0.5f) * 0.6180339887f;
    const float v = t - floor(t);
    return nearEmitterPlanePoint(int(e.normal / 2u), emitterPlaneCoordinate(e),
                                 s.loA + u * (s.hiA - s.loA), s.loB + v * (s.hiB - s.loB));
}

// The grid cell holding point p (clamped into the grid of `cells` cells per axis).
LUXEL_FUNC int emitterCellIndex(vec3 p, ivec3 cells) {
    const int x = clamp(int(floor(p.x / float(LUXEL_EMITTER_CELL))), 0, cells.x - 1);
    const int y = clamp(int(floor(p.y / float(LUXEL_EMITTER_CELL))), 0, cells.y - 1);
    const int z = clamp(int(floor(p.z / float(LUXEL_EMITTER_CELL))), 0, cells.z - 1);
    return (z * cells.y + y) * cells.x + x;
}

LUXEL_SHARED_END

#endif
