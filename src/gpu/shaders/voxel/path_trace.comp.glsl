// The voxel path tracer on the GPU: one invocation per pixel of a band of rows traces samples
// firstSample .. firstSample + samples - 1 with the estimator of src/voxel/path_trace.cpp (its CPU
// reference, tracePath and PathTracer::addSamples) and the same random numbers (shared/path_rng.h),
// in float, and writes or adds their shifted sums (shared/path_trace_layout.h). The traversal,
// cutouts, sky, textures and the walk through transmissive voxels are the ray caster's
// (voxel_shading.glsl, voxel_physical.glsl); the surface response is path_surface.glsl.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_layout.h"
#include "shared/path_trace_layout.h"

layout(local_size_x = LUXEL_PATH_GROUP_X, local_size_y = LUXEL_PATH_GROUP_Y) in;
// Bindings 0-14 as voxel_render's (6, its image, and 10 are not read here).
#include "voxel/world_bindings.glsl"
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
#include "shared/path_bsdf.h"
#include "voxel/path_emitters.glsl"
#include "voxel/path_surface.glsl"

float maxComponent(vec3 c) {
    return max(c.x, max(c.y, c.z));
}

vec3 sunAxis() {
    return vec3(path.sunX, path.sunY, path.sunZ);
}

// crossMedium (path_trace.cpp): through the transmissive voxels of `cell`'s medium to where the
// ray leaves them, dimmed by Beer-Lambert; the ray's origin moves to the exit.
MediumExit crossMedium(ivec3 cell, inout vec3 o, vec3 d, inout vec3 throughput,
                       out float ior) {
    const VoxelMaterial m = materials[materialIndex(voxelValue(cell))];
    const MediumExit e = walkMedium(cell, o, d);
    throughput = throughput *
                 voxelTransmittance(vec3(m.absorptionR, m.absorptionG, m.absorptionB), e.distance);
    o = e.point;
    ior = m.ior;
    return e;
}

// turnAtExit (path_trace.cpp, splitAtExit in shading_physical.cpp): total internal reflection,
// or reflect back inside with the Fresnel reflectance and refract out otherwise. Draws one number
// unless the reflection is total. Whether the ray stays inside.
bool turnAtExit(MediumExit e, float ior, inout vec3 d, inout ivec3 cell, inout uvec2 rng) {
    const vec3 nIn = -vec3(e.outward);
    const float cosI = -dot(nIn, d);
    const float kk = opticsRefractK(cosI, ior);
    const bool total = kk < 0.0;
    bool reflect = total;
    if (!total) reflect = pathRngNext(rng) < pathFresnel(cosI, ior, 1.0);
    d = reflect ? normalize(opticsReflect(d, nIn))
                : normalize(opticsRefract(d, nIn, ior, cosI, kk));
    cell = e.cell;
    return reflect;
}

// meetsSun (path_trace.cpp): inside the disk, or along a delta sun's axis to rounding.
bool meetsSun(vec3 d) {
    if (path.sunOneMinusCos > 0.0) return pathConeContains(sunAxis(), path.sunOneMinusCos, d);
    const vec3 chord = d - sunAxis();
    return 0.5 * dot(chord, chord) <= LUXEL_PATH_DELTA_SUN_CHORD;
}

// sunReaching (path_trace.cpp): what of the sun's light arrives along l, through at most
// maxEvents delta surfaces (glass and mirrors met as a bounce ray meets them); maxEvents < 0:
// the plain shadow ray.
vec3 sunReaching(vec3 origin, vec3 l, int maxEvents, inout uvec2 rng) {
    if (maxEvents < 0) return castToSurface(origin, l).hit.hit ? vec3(0.0) : vec3(1.0);
    vec3 o = origin, d = l, throughput = vec3(1.0);
    bool inside = false;
    ivec3 cell = ivec3(0);
    for (int events = 0;;) {
        if (inside) {
            float ior;
            const MediumExit e = crossMedium(cell, o, d, throughput, ior);
            if (e.intoSolid) {
                inside = false;
                continue;
            }
            if (events == maxEvents) return vec3(0.0);
            inside = turnAtExit(e, ior, d, cell, rng);
            ++events;
            continue;
        }
        const SurfaceHit s = castToSurface(o, d);
        if (!s.hit.hit) return meetsSun(normalize(d)) ? throughput : vec3(0.0);
        const Hit hit = s.hit;
        if (hit.normal == ivec3(0) || events == maxEvents) return vec3(0.0);
        const PathSurface surface = pathSurfaceAt(s);
        const PathBsdf b = pathBsdfAt(surface, hit.normal, normalize(d));
        if (pathSmooth(b)) return vec3(0.0);
        const PathBounce next = pathSampleBsdf(b, rng);
        if (next.lobe == LUXEL_PATH_LOBE_NONE) return vec3(0.0);
        throughput = throughput * next.weight;
        if (!(maxComponent(throughput) > 0.0)) return vec3(0.0);
        o = hit.point;
        d = next.direction;
        if (next.lobe == LUXEL_PATH_LOBE_TRANSMISSION) {
            inside = true;
            cell = hit.voxel;
        }
        ++events;
    }
    return vec3(0.0);
}

// Next event estimation towards the sun (sunLight in path_trace.cpp): its centre (a delta light)
// or a uniform direction in its disk, weighted against the bounce rays that can meet the disk;
// through at most maxEvents delta surfaces. Draws two numbers when the disk has a size, whatever
// the surface.
vec3 sunLight(Hit hit, PathBsdf b, int maxEvents, inout uvec2 rng) {
    vec3 l = sunAxis();
    const bool delta = !(path.sunOneMinusCos > 0.0);
    if (!delta) {
        const float u0 = pathRngNext(rng), u1 = pathRngNext(rng);
        l = pathConeDirection(l, vec3(path.sunTangentX, path.sunTangentY, path.sunTangentZ),
                              vec3(path.sunBitangentX, path.sunBitangentY, path.sunBitangentZ),
                              u0 * path.sunOneMinusCos, 2.0 * LUXEL_PATH_PI * u1);
    }
    const vec3 irradiance = vec3(path.sunIrradianceR, path.sunIrradianceG, path.sunIrradianceB);
    if (!(maxComponent(irradiance) > 0.0) || !pathSmooth(b)) return vec3(0.0);
    if (!(dot(vec3(hit.normal), l) > 0.0)) return vec3(0.0);
    const vec3 reaching = sunReaching(hit.point, l, maxEvents, rng);
    if (!(maxComponent(reaching) > 0.0)) return vec3(0.0);
    if (delta) return reaching * pathBsdfLight(b, l, irradiance, 0.0);
    return reaching * pathBsdfLight(b, l, irradiance * path.sunRadianceScale, path.sunPdf);
}

// Next event estimation towards the emissive voxels, weighted against the bounce ray that could
// have found the same point (multiple importance sampling). Draws four numbers.
vec3 emitterLight(Hit hit, PathBsdf b, inout uvec2 rng) {
    const float u0 = pathRngNext(rng), u1 = pathRngNext(rng);
    const float u2 = pathRngNext(rng), u3 = pathRngNext(rng);
    if (!pathSmooth(b)) return vec3(0.0);
    const PathLightSample s = pathSampleEmitter(hit.point, u0, u1, u2, u3);
    if (!(s.pdf > 0.0) || !(dot(vec3(hit.normal), s.direction) > 0.0)) return vec3(0.0);
    // Visible when the shadow ray first meets the sampled face itself.
    const Hit seen = castToSurface(hit.point, s.direction).hit;
    if (!seen.hit || seen.voxel != s.voxel || seen.normal != s.normal) return vec3(0.0);
    const VoxelMaterial m = materials[materialIndex(voxelValue(s.voxel))];
    return pathBsdfLight(b, s.direction, vec3(m.emissionR, m.emissionG, m.emissionB), s.pdf);
}

// Whether Russian roulette ends the path at vertex k with the number u (drawn once roulette has
// started); else the throughput is divided by the survival probability.
bool rouletteEnds(int k, float u, inout vec3 throughput) {
    if (k + 1 < int(path.rouletteAfter)) return false;
    const float q = min(1.0, maxComponent(throughput));
    if (u >= q) return true;
    throughput = throughput * (1.0 / q);
    return false;
}

// tracePath (path_trace.cpp): one path sample along the camera ray, the same random numbers in
// the same order.
vec3 tracePath(vec3 origin, vec3 direction, inout uvec2 rng) {
    vec3 radiance = vec3(0.0), throughput = vec3(1.0);
    vec3 o = origin, d = direction;
    vec3 bounceOrigin = vec3(0.0);
    float bouncePdf = 0.0;  // the last bounce ray's density (0: the camera ray or a delta lobe)
    // Sun light sampling through delta surfaces (tracePath's chainPdf and chainDirection): the
    // density and direction of the last smooth vertex's bounce.
    const bool sunChains = (path.materialFlags & LUXEL_PATH_SUN_CHAINS) != 0u;
    float chainPdf = 0.0;
    vec3 chainDirection = vec3(0.0);
    bool inside = false;    // the ray travels through the medium of `cell`
    ivec3 cell = ivec3(0);
    const bool sampleEmitters = path.emitters > 0u;
    const int maxBounces = int(path.maxBounces);
    // Vertex k of the path is reached after k reflections or refractions.
    for (int k = 0;;) {
        if (inside) {
            // Through the transmissive voxels to where the ray leaves them (walkMedium,
            // voxel_physical.glsl), dimmed by Beer-Lambert.
            float ior;
            const MediumExit e = crossMedium(cell, o, d, throughput, ior);
            if (e.intoSolid) {  // another solid behind the glass: seen directly
                inside = false;
                continue;
            }
            if (k == maxBounces) break;
            const bool roulette = k + 1 >= int(path.rouletteAfter);
            const float uRoulette = roulette ? pathRngNext(rng) : 0.0;
            inside = turnAtExit(e, ior, d, cell, rng);
            bouncePdf = 0.0;
            if (rouletteEnds(k, uRoulette, throughput)) break;
            ++k;
            continue;
        }
        const SurfaceHit s = castToSurface(o, d);
        if (!s.hit.hit) {  // left the world (or ran past the step cap): the sky
            radiance += throughput * skyColor(d);
            // The sun's disk, where a reflected or refracted ray meets it (the camera sees the
            // sky without it, as in the ray caster).
            if (k > 0 && pathConeContains(sunAxis(), path.sunOneMinusCos, d)) {
                float weight = 1.0;
                if (bouncePdf > 0.0) {
                    weight = pathPowerHeuristic(bouncePdf, path.sunPdf);
                } else if (chainPdf > 0.0) {
                    const bool sampled =
                        pathConeContains(sunAxis(), path.sunOneMinusCos, chainDirection);
                    weight = pathPowerHeuristic(chainPdf, sampled ? path.sunPdf : 0.0);
                }
                radiance += throughput *
                            vec3(path.sunIrradianceR, path.sunIrradianceG, path.sunIrradianceB) *
                            path.sunRadianceScale * weight;
            }
            break;
        }
        const Hit hit = s.hit;
        if (hit.normal == ivec3(0)) break;  // started inside a solid voxel: no light
        const PathSurface surface = pathSurfaceAt(s);
        if (maxComponent(surface.emission) > 0.0) {
            // Seen by a bounce ray that emitter sampling could also have found: MIS-weighted.
            float weight = 1.0;
            if (sampleEmitters && bouncePdf > 0.0) {
                weight = pathPowerHeuristic(
                    bouncePdf, pathEmitterPdf(bounceOrigin, hit.voxel, hit.normal, hit.point));
            }
            radiance += throughput * surface.emission * weight;
        }
        if (k == maxBounces) break;
        const PathBsdf b = pathBsdfAt(surface, hit.normal, normalize(d));
        // Next event estimation (the smooth lobes only; a delta lobe counts what its ray meets).
        radiance += throughput * sunLight(hit, b, sunChains ? maxBounces - k - 1 : -1, rng);
        if (sampleEmitters) radiance += throughput * emitterLight(hit, b, rng);
        const float uRoulette = k + 1 >= int(path.rouletteAfter) ? pathRngNext(rng) : 0.0;
        const PathBounce next = pathSampleBsdf(b, rng);
        if (next.lobe == LUXEL_PATH_LOBE_NONE) break;
        throughput = throughput * next.weight;
        if (!(maxComponent(throughput) > 0.0)) break;
        if (rouletteEnds(k, uRoulette, throughput)) break;
        o = hit.point;
        d = next.direction;
        bounceOrigin = hit.point;
        bouncePdf = next.pdf;
        if (next.pdf > 0.0) {
            chainPdf = sunChains ? next.pdf : 0.0;
            chainDirection = next.direction;
        } else if (pathSmooth(b)) {
            chainPdf = 0.0;  // sun light sampling stops at this surface
        }
        if (next.lobe == LUXEL_PATH_LOBE_TRANSMISSION) {
            inside = true;
            cell = hit.voxel;
        }
        ++k;
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
