// The voxel radiance cascades' picture on the GPU (docs/algorithms/voxel-radiance-cascades.md
// §4.2, §4.3; CPU reference: RadianceCascades::render in src/voxel/cascades/cascade_picture.cpp):
// one invocation per pixel casts render.samples rays through it (the centre by default) and
// shades what it meets with the solver's material model (solver_shade.glsl) under the faces'
// irradiance the lighting passes left in the light buffer, the sun by shadow rays over its disk,
// and reflections and refraction followed through glass and polished metal
// (solver_reflected.glsl), drawing the same random numbers as the CPU (shared/path_rng.h); the emitters near the pixel are taken exactly at it
// (near_emitters.glsl) and the lamps beyond light-sampled in its glossy lobe
// (glossy_emitters.glsl). A second dispatch draws the pixels of strong contrast again with more
// rays (adaptive_samples.h). Buffers and push constants: shared/cascade_picture_layout.h,
// shared/near_emitters.h and shared/glossy_emitters.h.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_layout.h"
#include "shared/path_trace_layout.h"
#include "shared/medium_layout.h"
#include "shared/voxel_cascades_layout.h"
#include "shared/cascade_picture_layout.h"
#include "shared/near_emitters.h"
#include "shared/glossy_emitters.h"

layout(local_size_x = LUXEL_PICTURE_GROUP_X, local_size_y = LUXEL_PICTURE_GROUP_Y) in;
// Bindings 0-14 as voxel_render's (6, its image, and 10 are not read here).
#include "voxel/world_bindings.glsl"
layout(std430, set = 0, binding = 15) readonly buffer FaceLight { RgbTexel light[]; };
layout(std430, set = 0, binding = 16) readonly buffer FaceSlots { CascadeFaceSlot faceSlots[]; };
layout(std430, set = 0, binding = 17) readonly buffer GgxAlbedo { float ggxAlbedo[]; };
layout(std430, set = 0, binding = 18) writeonly buffer Picture { float picture[]; };
// The emitters near each face (shared/near_emitters.h).
layout(std430, set = 0, binding = 19) readonly buffer EmitterFar { RgbTexel emitterFar[]; };
layout(std430, set = 0, binding = 20) readonly buffer NearOffsets { uint nearOffset[]; };
layout(std430, set = 0, binding = 21) readonly buffer NearEmitters {
    CascadeNearEmitter nearEmitters[];
};
// The adaptive pass (src/voxel/cascades/adaptive_samples.h): its pixels' RGB first (written
// here, downloaded alone), then the list of the pixels, from word 3 x refineCount.
layout(std430, set = 0, binding = 22) buffer RefinePixels { uint refinePixels[]; };
// The lamps the glossy surfaces light-sample (shared/glossy_emitters.h).
layout(std430, set = 0, binding = 23) readonly buffer GlossyPicks { uint glossyPicks[]; };
layout(std430, set = 0, binding = 24) readonly buffer GlossyLamps {
    CascadeNearEmitter glossyLamps[];
};
// Named `path` so the path tracer's surface code (path_surface.glsl) reads its materialFlags.
layout(push_constant) uniform Push { CascadePicturePush path; };
// Bindings 11-14: the sun visibility arrays, declared by the include (the ray caster's shading
// code reads them; the picture's sun is shadow rays).
#include "voxel/sun_visibility.glsl"

#include "voxel/voxel_world_access.glsl"
#include "voxel/texture_sample.glsl"
#include "voxel/voxel_shading.glsl"
#include "shared/path_rng.h"
#include "shared/pixel_samples.h"
#include "shared/path_bsdf.h"
#include "voxel/path_surface.glsl"
#include "voxel/solver_light.glsl"
#include "voxel/near_emitters.glsl"

// RadianceCascades::reflectedLight's recursion, unrolled: level 2 takes every face as
// Lambertian; levels 1 and 0 follow glass and polished metal into the level below.
#define LUXEL_SOLVER_REFLECTED reflectedLight2
#include "voxel/solver_reflected.glsl"
#undef LUXEL_SOLVER_REFLECTED
#define LUXEL_SOLVER_SHADE shadeSurface2
#define LUXEL_SOLVER_RADIANCE reflectedLight2
#define LUXEL_SOLVER_AIR_EXITS LUXEL_PICTURE_FOLLOWED_AIR_EXITS
#include "voxel/solver_shade.glsl"
#undef LUXEL_SOLVER_SHADE
#undef LUXEL_SOLVER_RADIANCE
#undef LUXEL_SOLVER_AIR_EXITS

#define LUXEL_SOLVER_REFLECTED reflectedLight1
#define LUXEL_SOLVER_FOLLOW shadeSurface2
#include "voxel/solver_reflected.glsl"
#undef LUXEL_SOLVER_REFLECTED
#undef LUXEL_SOLVER_FOLLOW
#define LUXEL_SOLVER_SHADE shadeSurface1
#define LUXEL_SOLVER_RADIANCE reflectedLight1
#define LUXEL_SOLVER_AIR_EXITS LUXEL_PICTURE_FOLLOWED_AIR_EXITS
#include "voxel/solver_shade.glsl"
#undef LUXEL_SOLVER_SHADE
#undef LUXEL_SOLVER_RADIANCE
#undef LUXEL_SOLVER_AIR_EXITS

// The camera's surface (level 0) takes its near emitters' highlight light-sampled; its GGX
// rays count those emitters by the share left (RadianceCascades::pixelRadiance's nearHighlight
// and glossyAlong): the surface's face and point, and whether the ray being followed is one of
// them.
int pictureNearFace;
vec3 pictureNearPoint;
bool pictureGlossyRay;
// Whether the camera's surface is rough: its GGX rays then follow no glass or polished metal
// (RadianceCascades::pixelRadiance, §4.2 "Rough lobes follow no face").
bool pictureRoughLobe;
// The lamps beyond, light-sampled and weighed against the GGX rays (glossy_emitters.glsl).
#include "voxel/glossy_emitters.glsl"
#define LUXEL_SOLVER_NEAR
#define LUXEL_SOLVER_REFLECTED reflectedLight0
#define LUXEL_SOLVER_FOLLOW shadeSurface1
#define LUXEL_SOLVER_ROUGH_LAMBERTIAN
#include "voxel/solver_reflected.glsl"
#undef LUXEL_SOLVER_REFLECTED
#undef LUXEL_SOLVER_FOLLOW
#undef LUXEL_SOLVER_ROUGH_LAMBERTIAN
#define LUXEL_SOLVER_SHADE shadeSurface0
#define LUXEL_SOLVER_RADIANCE reflectedLight0
#define LUXEL_SOLVER_AIR_EXITS LUXEL_PICTURE_CAMERA_AIR_EXITS
#include "voxel/solver_shade.glsl"
#undef LUXEL_SOLVER_SHADE
#undef LUXEL_SOLVER_RADIANCE
#undef LUXEL_SOLVER_AIR_EXITS
#undef LUXEL_SOLVER_NEAR

// The picture's radiance along one camera ray.
vec3 pixelRadiance(vec3 origin, vec3 direction, inout uvec2 rng) {
    const SurfaceHit s = castToSurface(origin, direction);
    if (!s.hit.hit) return skyColor(direction);
    if (s.hit.normal == ivec3(0)) return vec3(0.0);  // the camera is inside a solid voxel
    // The emitters near the pixel taken exactly at it, the rest of their light interpolated.
    const vec3 irradiance = interpolatedIrradiance(s.hit, true) + nearEmitterLight(s.hit);
    pictureNearFace = findFace(s.hit.voxel, normalIndex(s.hit.normal));
    pictureNearPoint = s.hit.point;
    pictureGlossyRay = false;
    pictureRoughLobe = solverRoughLobe(s);
    pictureLampCount = 0;
    return shadeSurface0(s, direction, irradiance * LUXEL_SOLVER_INV_PI, int(path.sunRays),
                         int(path.specularRays), true, rng);
}

void main() {
    uint x = gl_GlobalInvocationID.x, y = gl_GlobalInvocationID.y;
    if (x >= params.width) return;
    uint pixel = y * params.width + x;
    const uint entry = pixel;
    int n = int(clamp(params.samplesPerPixel, 1u, uint(LUXEL_MAX_SAMPLES_PER_PIXEL)));
    if (path.refineCount > 0u) {
        // The adaptive pass: this invocation's entry of the list, with more rays.
        if (entry >= path.refineCount) return;
        pixel = refinePixels[3u * path.refineCount + entry];
        x = pixel % params.width;
        y = pixel / params.width;
        n = int(clamp(path.refineSamples, 1u, uint(LUXEL_MAX_SAMPLES_PER_PIXEL)));
    } else if (y >= params.height) {
        return;
    }
    const vec3 forward = vec3(params.forwardX, params.forwardY, params.forwardZ);
    const vec3 right = vec3(params.rightX, params.rightY, params.rightZ);
    const vec3 up = vec3(params.upX, params.upY, params.upZ);
    const vec3 origin = vec3(params.positionX, params.positionY, params.positionZ);
    // One random stream per pixel, drawn on through its samples (as on the CPU).
    uvec2 rng = pathRngKey(uvec2(path.seedLow, path.seedHigh), pixel, 0u);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < n; ++k) {
        // Camera::rayAt at the sample's position (shared/pixel_samples.h).
        const vec2 o = pixelSampleOffset(x, y, k, n);
        const float sx = (2.0 * (float(x) + o.x) / float(params.width) - 1.0) * params.tanHalf *
                         params.aspect;
        const float sy = (1.0 - 2.0 * (float(y) + o.y) / float(params.height)) * params.tanHalf;
        sum += pixelRadiance(origin, normalize(forward + right * sx + up * sy), rng);
    }
    const vec3 radiance = n == 1 ? sum : sum * (1.0 / float(n));
    if (path.refineCount > 0u) {
        // Beside the list, so that only the refined pixels come back to the CPU.
        refinePixels[3u * entry] = floatBitsToUint(radiance.x);
        refinePixels[3u * entry + 1u] = floatBitsToUint(radiance.y);
        refinePixels[3u * entry + 2u] = floatBitsToUint(radiance.z);
        return;
    }
    picture[3u * pixel] = radiance.x;
    picture[3u * pixel + 1u] = radiance.y;
    picture[3u * pixel + 2u] = radiance.z;
}
