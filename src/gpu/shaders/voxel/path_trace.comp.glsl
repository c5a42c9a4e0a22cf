// The voxel path tracer on the GPU: one invocation per pixel of a band of rows traces samples
// firstSample .. firstSample + samples - 1 with the estimator of src/voxel/path_trace.cpp (its CPU
// reference, tracePath and PathTracer::addSamples) and the same random numbers (shared/path_rng.h),
// in float, and writes or adds their shifted sums (shared/path_trace_layout.h). The traversal,
// cutouts, sky and textures are the ray caster's (voxel_shading.glsl); the surface response is
// path_surface.glsl.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_layout.h"
#include "shared/path_trace_layout.h"

layout(local_size_x = LUXEL_PATH_GROUP_X, local_size_y = LUXEL_PATH_GROUP_Y) in;
// Bindings 0-14 as voxel_render's (6, its image, and 10 are not read here).
layout(std430, set = 0, binding = 0) readonly buffer Params { VoxelRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Voxels { uint voxels[]; };
layout(std430, set = 0, binding = 2) readonly buffer ChunkSolid { uint chunkSolid[]; };
layout(std430, set = 0, binding = 3) readonly buffer TextureInfos { VoxelTextureInfo textureInfo[]; };
layout(std430, set = 0, binding = 4) readonly buffer Texels { vec4 texels[]; };
layout(std430, set = 0, binding = 5) readonly buffer SrgbTable { float srgbTable[]; };
layout(std430, set = 0, binding = 7) readonly buffer BrickMasks { uvec2 brickMasks[]; };
layout(std430, set = 0, binding = 8) readonly buffer BrickReach { uint brickReach[]; };
layout(std430, set = 0, binding = 9) readonly buffer Materials { VoxelMaterial materials[]; };
layout(std430, set = 0, binding = 15) readonly buffer Emitters { PathEmitterVoxel emitters[]; };
layout(std430, set = 0, binding = 16) buffer Sums { PathPixelSums sums[]; };
layout(push_constant) uniform Push { PathTracePush path; };
// Bindings 11-14: the sun visibility arrays, declared by the include (the ray caster's shading
// code reads them; the path tracer's sun is a shadow ray).
#include "voxel/sun_visibility.glsl"

#include "voxel/voxel_world_access.glsl"
#include "voxel/texture_sample.glsl"
#include "voxel/voxel_shading.glsl"
#include "shared/path_rng.h"
#include "voxel/path_emitters.glsl"
#include "voxel/path_surface.glsl"

float maxComponent(vec3 c) {
    return max(c.x, max(c.y, c.z));
}

// Power-heuristic weight of a strategy of density `mine` against one of density `other`, as a
// ratio so that large densities do not overflow float.
float powerHeuristic(float mine, float other) {
    if (!(mine > 0.0)) return 0.0;
    const float r = other / mine;
    return 1.0 / (1.0 + r * r);
}

// Next event estimation towards the sun: a delta light, found only by this shadow ray.
vec3 sunLight(Hit hit, PathSurface surface, vec3 towardsEye) {
    const vec3 irradiance = vec3(path.sunIrradianceR, path.sunIrradianceG, path.sunIrradianceB);
    if (!(maxComponent(irradiance) > 0.0)) return vec3(0.0);
    const vec3 sun = vec3(path.sunX, path.sunY, path.sunZ);
    if (!(dot(vec3(hit.normal), sun) > 0.0) || castToSurface(hit.point, sun).hit.hit) {
        return vec3(0.0);
    }
    return pathSurfaceReflect(surface, hit.normal, towardsEye, sun) * irradiance;
}

// Next event estimation towards the emissive voxels, weighted against the bounce ray that could
// have found the same point (multiple importance sampling).
vec3 emitterLight(Hit hit, PathSurface surface, vec3 towardsEye, inout uvec2 rng) {
    const float u0 = pathRngNext(rng), u1 = pathRngNext(rng);
    const float u2 = pathRngNext(rng), u3 = pathRngNext(rng);
    const PathLightSample s = pathSampleEmitter(hit.point, u0, u1, u2, u3);
    if (!(s.pdf > 0.0) || !(dot(vec3(hit.normal), s.direction) > 0.0)) return vec3(0.0);
    // Visible when the shadow ray first meets the sampled face itself.
    const Hit seen = castToSurface(hit.point, s.direction).hit;
    if (!seen.hit || seen.voxel != s.voxel || seen.normal != s.normal) return vec3(0.0);
    const VoxelMaterial m = materials[materialIndex(voxelValue(s.voxel))];
    const float bouncePdf = pathSurfacePdf(surface, hit.normal, towardsEye, s.direction);
    const float weight = powerHeuristic(s.pdf, bouncePdf);
    return pathSurfaceReflect(surface, hit.normal, towardsEye, s.direction) *
           vec3(m.emissionR, m.emissionG, m.emissionB) * (weight / s.pdf);
}

// tracePath (path_trace.cpp): one path sample along the camera ray.
vec3 tracePath(vec3 origin, vec3 direction, inout uvec2 rng) {
    vec3 radiance = vec3(0.0), throughput = vec3(1.0);
    vec3 o = origin, d = direction;
    vec3 bounceOrigin = vec3(0.0);
    float bouncePdf = 0.0;  // the last bounce ray's density (0: the camera ray)
    const bool sampleEmitters = path.emitters > 0u;
    // Vertex k of the path is reached after k reflections.
    for (int k = 0;; ++k) {
        const SurfaceHit s = castToSurface(o, d);
        if (!s.hit.hit) {  // left the world (or ran past the step cap): the sky
            radiance += throughput * skyColor(d);
            break;
        }
        const Hit hit = s.hit;
        if (hit.normal == ivec3(0)) break;  // started inside a solid voxel: no light
        const PathSurface surface = pathSurfaceAt(s);
        if (maxComponent(surface.emission) > 0.0) {
            float weight = 1.0;
            if (sampleEmitters && k > 0) {
                weight = powerHeuristic(
                    bouncePdf, pathEmitterPdf(bounceOrigin, hit.voxel, hit.normal, hit.point));
            }
            radiance += throughput * surface.emission * weight;
        }
        if (k == int(path.maxBounces)) break;
        const vec3 towardsEye = -d;
        radiance += throughput * sunLight(hit, surface, towardsEye);
        if (sampleEmitters) radiance += throughput * emitterLight(hit, surface, towardsEye, rng);
        // The roulette number, then the bounce's two, as the CPU draws them (a path that ends
        // here draws nothing more).
        const bool roulette = k + 1 >= int(path.rouletteAfter);
        const float survive = roulette ? pathRngNext(rng) : 0.0;
        const float u1 = pathRngNext(rng), u2 = pathRngNext(rng);
        const PathBounce bounce = pathSurfaceBounce(surface, hit.normal, towardsEye, u1, u2);
        throughput = throughput * bounce.weight;
        if (!(maxComponent(throughput) > 0.0)) break;
        if (roulette) {
            const float q = min(1.0, maxComponent(throughput));
            if (survive >= q) break;
            throughput = throughput * (1.0 / q);
        }
        o = hit.point;
        d = bounce.direction;
        bounceOrigin = hit.point;
        bouncePdf = bounce.pdf;
    }
    return radiance;
}

void main() {
    const uint x = gl_GlobalInvocationID.x;
    const uint y = path.rowOffset + gl_GlobalInvocationID.y;
    if (x >= params.width || gl_GlobalInvocationID.y >= path.rows || y >= params.height) return;
    const uint pixel = y * params.width + x;
    const float w = float(params.width), h = float(params.height);
    const vec3 forward = vec3(params.forwardX, params.forwardY, params.forwardZ);
    const vec3 right = vec3(params.rightX, params.rightY, params.rightZ);
    const vec3 up = vec3(params.upX, params.upY, params.upZ);
    const vec3 origin = vec3(params.positionX, params.positionY, params.positionZ);
    const uvec2 seed = uvec2(path.seedLow, path.seedHigh);
    vec4 shift = vec4(0.0), sum = vec4(0.0), squares = vec4(0.0);
    if (path.accumulate != 0u) {
        const PathPixelSums p = sums[pixel];
        shift = vec4(p.shiftR, p.shiftG, p.shiftB, p.shiftL);
        sum = vec4(p.sumR, p.sumG, p.sumB, p.sumL);
        squares = vec4(p.squaresR, p.squaresG, p.squaresB, p.squaresL);
    }
    for (uint i = 0u; i < path.samples; ++i) {
        uvec2 rng = pathRngKey(seed, pixel, path.firstSample + i);
        const float jx = pathRngNext(rng), jy = pathRngNext(rng);  // uniform in the pixel
        // Camera::rayAt at (x + jx, y + jy).
        const float sx = (2.0 * (float(x) + jx) / w - 1.0) * params.tanHalf * params.aspect;
        const float sy = (1.0 - 2.0 * (float(y) + jy) / h) * params.tanHalf;
        const vec3 c = tracePath(origin, normalize(forward + right * sx + up * sy), rng);
        const vec4 v = vec4(c, 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z);
        if (i == 0u && path.accumulate == 0u) shift = v;
        const vec4 dv = v - shift;
        sum += dv;
        squares += dv * dv;
    }
    sums[pixel] = PathPixelSums(shift.x, shift.y, shift.z, shift.w, sum.x, sum.y, sum.z, sum.w,
                                squares.x, squares.y, squares.z, squares.w);
}
