// HRC read-out (docs/algorithms/holographic-radiance-cascades.md §6.2; CPU twin: readOut in
// src/gi2d/hrc/readout.cpp): each pixel adds the cones of R_0 at the plane one pixel ahead along
// this frustum's axis (or the sky beyond the frame) to its canvas-space accumulator. The cones are
// binary16 (shared/hrc_layout.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"
#include "gi2d/hrc_common.glsl"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Cones { HrcConePair cones[]; };
layout(std430, set = 0, binding = 1) buffer Beyond { RgbTexel beyond[]; };
layout(push_constant) uniform Push { HrcReadoutParams params; };

// Canvas pixel of frame pixel (u, v); matches FrustumFrame::toCanvas.
uvec2 toCanvas(uint u, uint v) {
    if (params.frustum == 0u) return uvec2(u, v);
    if (params.frustum == 2u) return uvec2(params.canvasWidth - 1u - u, v);
    if (params.frustum == 1u) return uvec2(v, u);
    return uvec2(v, params.canvasHeight - 1u - u);
}

void main() {
    const uint u = gl_GlobalInvocationID.x, v = gl_GlobalInvocationID.y;
    if (u >= params.frameLength || v >= params.rows) return;
    const uint plane = uint(hrcReadoutPlane(int(u), 0));  // R_0: one cone per plane
    vec3 arriving;
    if (plane < params.frameLength) {
        const uint r = hrcConeHalf(plane, 1u, 0u, 0u, v, params.rows);
        const uint stride = hrcConeRowHalves(params.rows);
        arriving = vec3(halfOfWord(cones[r >> 1].evenOddRows, r),
                        halfOfWord(cones[(r + stride) >> 1].evenOddRows, r),
                        halfOfWord(cones[(r + 2u * stride) >> 1].evenOddRows, r));
    } else {
        arriving = vec3(params.skyR, params.skyG, params.skyB) * LUXEL_HRC_QUARTER_TURN;
    }
    const uvec2 c = toCanvas(u, v);
    const uint target = c.y * params.canvasWidth + c.x;
    beyond[target] = rgbTexel(texelRgb(beyond[target]) + arriving);
}
