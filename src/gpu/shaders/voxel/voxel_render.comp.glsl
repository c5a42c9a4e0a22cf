// The voxel ray caster: one invocation per pixel of a band of rows, shading as the CPU renderer
// (src/voxel/shading.cpp), writing linear RGB. CPU reference: luxel::voxel::render.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_layout.h"

layout(local_size_x = LUXEL_VOXEL_GROUP_X, local_size_y = LUXEL_VOXEL_GROUP_Y) in;
#include "voxel/world_bindings.glsl"
layout(std430, set = 0, binding = 6) writeonly buffer Output { VoxelPixel pixels[]; };
layout(push_constant) uniform Push { VoxelBandPush band; };
// Bindings 11-14: the sun visibility arrays (shared/shadow_layout.h), declared by the include.
#include "voxel/sun_visibility.glsl"

// Bindings 15-17: the light from emissive voxels (shared/emitter_light.h), declared by
// emitter_light.glsl through voxel_physical.glsl.
#define LUXEL_VOXEL_EMITTER_BINDINGS

#include "voxel/voxel_world_access.glsl"
#include "voxel/texture_sample.glsl"
#include "voxel/voxel_shading.glsl"
#include "shared/pixel_samples.h"

void main() {
    const uint x = gl_GlobalInvocationID.x;
    const uint y = band.rowOffset + gl_GlobalInvocationID.y;
    if (x >= params.width || gl_GlobalInvocationID.y >= band.rows || y >= params.height) return;
    const float w = float(params.width), h = float(params.height);
    const vec3 forward = vec3(params.forwardX, params.forwardY, params.forwardZ);
    const vec3 right = vec3(params.rightX, params.rightY, params.rightZ);
    const vec3 up = vec3(params.upX, params.upY, params.upZ);
    const vec3 origin = vec3(params.positionX, params.positionY, params.positionZ);
    // shadePixel (render_image.cpp): stratified samples, Camera::rayAt at each, averaged.
    const int n = int(clamp(params.samplesPerPixel, 1u, uint(LUXEL_MAX_SAMPLES_PER_PIXEL)));
    vec3 sum = vec3(0.0);
    for (int k = 0; k < n; ++k) {
        const vec2 o = pixelSampleOffset(x, y, k, n);
        const float sx = (2.0 * (float(x) + o.x) / w - 1.0) * params.tanHalf * params.aspect;
        const float sy = (1.0 - 2.0 * (float(y) + o.y) / h) * params.tanHalf;
        sum += shadeRay(origin, normalize(forward + right * sx + up * sy), y * params.width + x,
                        uint(k));
    }
    const vec3 rgb = n == 1 ? sum : sum * (1.0 / float(n));
    pixels[y * params.width + x] = VoxelPixel(rgb.x, rgb.y, rgb.z, 1.0);
}
