// Per-pixel HRC arithmetic both backends run (docs/algorithms/holographic-radiance-cascades.md
// §6.2, §7): which plane a pixel reads, the opacity gate of the cross blur (paper Eq 21), and the
// pixel's own half-pixel segment in front of the light arriving at its read-out plane, and where a
// merged cone lies in memory. Compiled as C++ by src/gi2d/hrc/readout.cpp, finish.cpp and
// cone_merge.cpp, and as GLSL by hrc_merge, hrc_readout and hrc_finish.
#ifndef LUXEL_GPU_SHARED_HRC_KERNELS_H
#define LUXEL_GPU_SHARED_HRC_KERNELS_H

#include "glsl_compat.h"

#define LUXEL_HRC_QUARTER_TURN 1.57079632679489662f
#define LUXEL_HRC_INV_TWO_PI 0.159154943091895336f
// Eq 21: a neighbour whose opacity differs from the centre's by more than this is not blurred in.
#define LUXEL_HRC_BLUR_GATE 0.1f

LUXEL_SHARED_BEGIN

// A radiance interval (§1): the radiance L a ray segment delivers towards its start and its
// transmittance T.
struct HrcInterval {
    vec3 radiance;
    vec3 transmittance;
};

// Canvas pixel shown at pixel `frame` (u, v) of the frame of frustum 0 (+x), 1 (+y), 2 (-x) or
// 3 (-y) (§6.1): the +-y frames are reflections across the diagonal. FrustumFrame::toCanvas on the
// CPU, hrc_trace's reads of the canvas medium on the GPU.
LUXEL_FUNC ivec2 hrcFrameToCanvas(uint frustum, ivec2 frame, int canvasWidth, int canvasHeight) {
    if (frustum == 0u) return frame;
    if (frustum == 2u) return ivec2(canvasWidth - 1 - frame.x, frame.y);
    if (frustum == 1u) return ivec2(frame.y, frame.x);
    return ivec2(frame.y, canvasHeight - 1 - frame.x);
}

// Empty space: nothing emitted, everything transmitted.
LUXEL_FUNC HrcInterval hrcEmptyInterval() {
    return HrcInterval(vec3(0.0f), vec3(1.0f));
}

// Front-to-back compositing, the paper's Eq 8: `near` in front of `far`.
LUXEL_FUNC HrcInterval hrcOver(HrcInterval near, HrcInterval far) {
    return HrcInterval(near.radiance + near.transmittance * far.radiance,
                       near.transmittance * far.transmittance);
}

// The mean of two intervals: ray extension averages the two bent paths of an odd ray (§4).
LUXEL_FUNC HrcInterval hrcAverage(HrcInterval a, HrcInterval b) {
    return HrcInterval((a.radiance + b.radiance) * 0.5f,
                       (a.transmittance + b.transmittance) * 0.5f);
}

// Cascade 0's two rays run along the frustum's edges (±45 degrees), yet each stands for the half
// of the frustum between its edge and the axis (§3.1): across the one pixel column to the next
// plane those directions travel ln(1 + sqrt 2) / (pi / 4) = 1.1222 px on average, the diagonal
// sqrt 2. Its traced cells count with their lengths times this ratio, so a uniform medium gets
// the optical depth of the sub-cone rather than of its edge.
#define LUXEL_HRC_C0_DEPTH_SCALE 0.793515f

// The factor on the optical depth of traced cascade `level` (§3.1): cascade 0's ratio, unless
// cascade 0 is the base that ray extension builds the longer rays from (`tracedLevels` 1), where
// the rays must keep their true length.
LUXEL_FUNC float hrcTracedDepthScale(int level, int tracedLevels) {
    return level == 0 && tracedLevels > 1 ? LUXEL_HRC_C0_DEPTH_SCALE : 1.0f;
}

// y offset of ray k of cascade `level` across one plane spacing (§2): 2k - 2^level.
LUXEL_FUNC int hrcRayOffsetY(int level, int k) {
    return 2 * k - (1 << level);
}

// One side of a cone merge (§5): on an odd plane the ray ends on the upper plane (Eq 14) ...
LUXEL_FUNC vec3 hrcMergeOdd(HrcInterval ray, float weight, vec3 upperBeyond) {
    return ray.radiance * weight + ray.transmittance * upperBeyond;
}

// ... on an even plane the near upper probe and the far one, reached by the double-length ray,
// are merged first and then averaged (Eq 15-17).
LUXEL_FUNC vec3 hrcMergeEven(vec3 upperNear, HrcInterval doubleRay, float weight, vec3 upperFar) {
    const vec3 far = doubleRay.radiance * weight + doubleRay.transmittance * upperFar;
    return (upperNear + far) * 0.5f;
}

// Every upper cone is read as a blend of neighbouring rows (§5.1): the row Eq 14-17 name and, for
// side s, the rows towards the cone's bisector ("towards the axis": the sub-cone seen from the
// probe crosses the upper plane between its ray's end and the bisector, one row in on odd planes,
// two at the far probe of even planes); the near probe of even planes at cascades 0 and 1 also
// takes the row along the side's ray.
LUXEL_FUNC int hrcTowardsAxis(int side) {
    return side == 0 ? 1 : -1;
}

// The weight a of the row towards the bisector: 7/16 at cascade 0, then 2^-(level+1), halving
// per cascade (1/2 would interpolate the sub-cone's crossing exactly; the halving and cascade 0's
// 7/16, with the depth scale of §3.1, were chosen by measurement). Levels stay far below 30 (at
// most 2^28 pixels).
LUXEL_FUNC float hrcSecondRowWeight(int level) {
    return level == 0 ? 0.4375f : 1.0f / float(1u << uint(level + 1));
}

// The near probe's weight for the row along the side's ray: 1/4 at cascades 0 and 1, none above
// (chosen by measurement; 1/2 at cascade 0 before §3.1's depth scale).
LUXEL_FUNC float hrcNearRowWeight(int level) {
    return level <= 1 ? 0.25f : 0.0f;
}

// The near probe's row weight where the pixel read out from this plane keeps `kept64` 64ths of
// it (NearLightMask, §12.3): next to a light cascade 0's near-probe blend reads a neighbouring
// row's light, parallax rather than the angular correction of §5.1, so there it is turned off.
// Exact in float on both backends (a power of two times a small integer).
LUXEL_FUNC float hrcNearRowWeightAt(int level, uint kept64) {
    return level == 0 ? hrcNearRowWeight(level) * (float(kept64) * 0.015625f)
                      : hrcNearRowWeight(level);
}

// Odd planes and the near probe: (1 - a) row + a second.
LUXEL_FUNC vec3 hrcBlendTwoRows(vec3 row, vec3 second, float a) {
    return row * (1.0f - a) + second * a;
}

// The far probe of an even plane: the rows 0, 1 and 2 steps towards the bisector with weights
// 1 - 3a/2, a and a/2 (a = 1/2: the linear interpolation 1/4, 1/2, 1/4 over the two rows the
// sub-cone crosses there).
LUXEL_FUNC vec3 hrcBlendThreeRows(vec3 row, vec3 second, vec3 third, float a) {
    return row * (1.0f - 1.5f * a) + second * a + third * (0.5f * a);
}

// Values per channel plane of a merged cone (hrc_layout.h): the rows padded to an even count.
LUXEL_FUNC uint hrcConeRowHalves(uint rows) {
    return (rows + 1u) & ~1u;
}

// Where channel c of cone i of plane p, row y lies among the binary16 values of R_n (hrc_layout.h);
// `cones` = 2^n.
LUXEL_FUNC uint hrcConeHalf(uint p, uint cones, uint i, uint c, uint y, uint rows) {
    return ((p * cones + i) * 3u + c) * hrcConeRowHalves(rows) + y;
}

// The first plane of cascade `level` at or beyond u + 1: the read-out plane one pixel ahead.
LUXEL_FUNC int hrcReadoutPlane(int u, int level) {
    return (u + 1 + (1 << level) - 1) >> level;
}

// Opacity of a pixel over one pixel length, from its largest absorption channel.
LUXEL_FUNC float hrcOpacity(vec3 sigma) {
    return 1.0f - exp(-max(sigma.x, max(sigma.y, sigma.z)));
}

// Whether the cross blur takes a neighbour in (centre weight 4, neighbours 1, renormalised).
LUXEL_FUNC bool hrcBlurTakes(float centreOpacity, float neighbourOpacity) {
    return !(abs(neighbourOpacity - centreOpacity) > LUXEL_HRC_BLUR_GATE);
}

// Mean radiance over directions at a pixel: its own half-pixel segment (L = E(1 - e^{-sigma/2}),
// T = e^{-sigma/2}) over the `frustums` quarter turns, in front of the angular fluence arriving at
// its read-out planes, divided by 2 pi.
LUXEL_FUNC vec3 hrcFinishTransmittance(vec3 sigma) {
    return exp(sigma * -0.5f);
}

// The same with T given (hrcFinishTransmittance): the CPU reuses it along runs of equal sigma.
LUXEL_FUNC vec3 hrcFinishPixelThrough(vec3 t, vec3 emission, vec3 arriving, float frustums) {
    const vec3 own = emission * (vec3(1.0f) - t);
    return (own * (LUXEL_HRC_QUARTER_TURN * frustums) + t * arriving) * LUXEL_HRC_INV_TWO_PI;
}

LUXEL_FUNC vec3 hrcFinishPixel(vec3 sigma, vec3 emission, vec3 arriving, float frustums) {
    return hrcFinishPixelThrough(hrcFinishTransmittance(sigma), emission, arriving, frustums);
}

LUXEL_SHARED_END

#endif
