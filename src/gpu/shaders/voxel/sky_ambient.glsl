// Sky ambient with occlusion on the GPU: the twin of src/voxel/sky_ambient.cpp (sky_ambient.h),
// in float in the same order, drawing the same numbers (shared/path_rng.h) and directions
// (shared/sky_ambient.h). Included by voxel_physical.glsl after castToSurface and skyColor.
#include "shared/path_rng.h"
#include "shared/sky_ambient.h"

struct SkyAmbient {
    float visible;  // the share of the rays that reach the sky
    vec3 sky;       // the sky's radiance along them, summed and divided by all the rays
};

// params.skyAmbientRays rays from `point` on the face of normal `normal`: a ray reaches the sky
// when castToSurface meets nothing (cutout texels let it through, every other solid stops it).
SkyAmbient traceSkyAmbient(vec3 point, ivec3 normal, inout uvec2 rng) {
    const int n = clamp(int(params.skyAmbientRays), 1, LUXEL_SKY_AMBIENT_MAX_RAYS);
    int escaped = 0;
    vec3 sky = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        const float u1 = pathRngNext(rng);
        const float u2 = pathRngNext(rng);
        const vec3 d = skyAmbientDirection(normal, u1, u2);
        if (castToSurface(point, d).hit.hit) continue;
        ++escaped;
        sky += skyColor(d);
    }
    return SkyAmbient(float(escaped) / float(n), sky * (1.0 / float(n)));
}
