// The medium's column-major copy (x * height + y) from its row-major one, for the HRC passes whose
// threads walk columns: the CPU packs and uploads the rows only (src/gi2d/hrc/hrc_gpu.cpp;
// reference: packMediumForGpu(medium, true) in src/gi2d/medium_gpu.h). One invocation per pixel.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, set = 0, binding = 0) readonly buffer Rows { MediumTexel rows[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Columns { MediumTexel columns[]; };
layout(push_constant) uniform Push { MediumTransposeParams params; };

void main() {
    const uvec2 c = gl_GlobalInvocationID.xy;
    if (c.x >= params.width || c.y >= params.height) return;
    columns[c.x * params.height + c.y] = rows[c.y * params.width + c.x];
}
