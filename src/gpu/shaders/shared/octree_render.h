// One pixel of an octree render, shared by the CPU twin (octree::renderOctree) and the GPU pass
// (octree/octree_render.comp.glsl); the model is docs/algorithms/sparse-voxel-octree.md §5.
//
// Opacity: a leaf of value v lets through (1 - a)^s of the light over a path of s voxels, with
// a = min(v / 255 * opacityScale, 1) the opacity per voxel length (a = 1: opaque).
// Modes: surface (first leaf at least `threshold`, Lambert with sky light and sun shadows, hard or
// soft over a cone of the sun's angular radius); volume (front-to-back compositing with early
// termination; with scattering, sunlight scattered once by a Henyey-Greenstein phase function plus
// multiple-scattering octaves); additive (the WebGL octree design's transparency: an
// emission-like sum with no occlusion).
//
// The includer defines what octree_walk.h needs and
//   vec3 octreeLeafSrgb(LUXEL_OCTREE tree, uint index): the colour at `index` (a leaf's
//   OctreeLeaf::colourIndex: its entry, or its leaf order), sRGB in [0, 1] (a light grey when the
//   tree has no colours).
#ifndef LUXEL_GPU_SHARED_OCTREE_RENDER_H
#define LUXEL_GPU_SHARED_OCTREE_RENDER_H

#include "glsl_compat.h"
#include "octree_layout.h"
#include "octree_light_cache.h"
#include "octree_walk.h"
#include "voxel_shading.h"

// Early termination: below this transmittance the rest of a ray cannot show (8-bit output).
#define LUXEL_OCTREE_MIN_TRANSMITTANCE (1.0f / 512.0f)
// Volume lighting is evaluated at least once per this many voxels of a leaf's chord.
#define LUXEL_OCTREE_LIGHT_STEP 0.5f
#define LUXEL_OCTREE_MAX_LIGHT_STEPS 64

LUXEL_SHARED_BEGIN

LUXEL_FUNC float octreeSrgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

// The albedo of the leaf with this colour index, in linear RGB.
LUXEL_FUNC vec3 octreeLeafColour(LUXEL_OCTREE tree, uint colourIndex) {
    const vec3 c = octreeLeafSrgb(tree, colourIndex);
    return vec3(octreeSrgbToLinear(c.x), octreeSrgbToLinear(c.y), octreeSrgbToLinear(c.z));
}

// The transfer function: values at or below windowLow are clear, at or above windowHigh full
// strength, linear between (the window of CT viewers); times opacityScale, capped at 1. The
// default window 0..255 is value / 255.
LUXEL_FUNC float octreeAlpha(uint value, LUXEL_IN(OctreeRenderParams) p) {
    const float low = float(p.windowLow);
    const float w = clamp((float(value) - low) / (float(p.windowHigh) - low), 0.0f, 1.0f);
    return min(w * p.opacityScale, 1.0f);
}

// Transmittance of `length` voxels in a leaf of per-voxel opacity `alpha`.
LUXEL_FUNC float octreeSegmentTransmittance(float alpha, float length) {
    if (alpha >= 1.0f) return length > 0.0f ? 0.0f : 1.0f;
    return pow(1.0f - alpha, length);
}

LUXEL_FUNC ivec3 octreeParamsSize(LUXEL_IN(OctreeRenderParams) p) {
    return ivec3(int(p.sizeX), int(p.sizeY), int(p.sizeZ));
}

// Transmittance along o + t d, t in [0, tMax], d unit length; 0 once below the cut-off.
LUXEL_FUNC float octreeTransmittance(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                     LUXEL_REAL3 o, LUXEL_REAL3 d, LUXEL_REAL tMax) {
    OctreeRay r;
    if (!octreeRayStart(r, int(p.depth), octreeParamsSize(p), o, d, tMax)) return 1.0f;
    float transmittance = 1.0f;
    for (int steps = 0; steps < int(p.stepCap); ++steps) {
        const OctreeLeaf leaf = octreeLocate(tree, int(p.depth), r.cursor, r.walk.cell);
        if (leaf.value > 0u) {
            const LUXEL_REAL exitT = min(octreeLeafExitT(r, leaf), tMax);
            transmittance *=
                octreeSegmentTransmittance(octreeAlpha(leaf.value, p), float(exitT - r.walk.t));
            if (transmittance < LUXEL_OCTREE_MIN_TRANSMITTANCE) return 0.0f;
        }
        if (!octreeRayLeave(r, leaf, tMax)) break;
    }
    return transmittance;
}

// One corner of the light cache (octree_light_cache.h): the optical depth toward the sun, from
// T_sun traced exactly from its point.
LUXEL_FUNC float octreeLightCacheCorner(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                        uint corner) {
    const vec3 q = octreeLightCacheCornerPoint(p, corner);
    return octreeLightCacheDepth(octreeTransmittance(tree, p, LUXEL_REAL3(q),
                                                     LUXEL_REAL3(vec3(p.sunX, p.sunY, p.sunZ)),
                                                     LUXEL_REAL(LUXEL_INFINITY)));
}

// The sun's transmittance from `point`: interpolated in the light cache when there is one, else
// traced (the exact answer the cache approximates).
LUXEL_FUNC float octreeSunTransmittance(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                        LUXEL_REAL3 point) {
    const LUXEL_REAL3 sun = LUXEL_REAL3(vec3(p.sunX, p.sunY, p.sunZ));
    if (p.lightStride == 0u) {
        return octreeTransmittance(tree, p, point, sun, LUXEL_REAL(LUXEL_INFINITY));
    }
    // The near field traced exactly (the cache blurs the sharpest change, the medium just in
    // front), the far field read from the cache; past the box nothing is in the way.
    const LUXEL_REAL nearT =
        LUXEL_REAL(max(LUXEL_OCTREE_LIGHT_CACHE_NEAR_STRIDES * float(p.lightStride),
                       LUXEL_OCTREE_LIGHT_CACHE_NEAR_VOXELS));
    const float nearTransmittance = octreeTransmittance(tree, p, point, sun, nearT);
    const LUXEL_REAL3 far = point + sun * nearT;
    const vec3 f = vec3(far);
    if (f.x < 0.0f || f.y < 0.0f || f.z < 0.0f || f.x > float(p.sizeX) || f.y > float(p.sizeY) ||
        f.z > float(p.sizeZ)) {
        return nearTransmittance;
    }
    return nearTransmittance * octreeLightCacheLookup(tree, p, f);
}

// A uniform number in [0, 1) from a hash of three integers.
LUXEL_FUNC float octreeRandom(uint a, uint b, uint c) {
    const uint h = voxelMixHash(a * 0x9e3779b9u ^ voxelMixHash(b * 0x85ebca6bu ^ voxelMixHash(c)));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

// A direction in the cone of half-angle `radius` around unit `axis`, from (u, v) in [0, 1)^2.
LUXEL_FUNC vec3 octreeConeDirection(vec3 axis, float radius, float u, float v) {
    const vec3 helper = abs(axis.x) > 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
    const vec3 t = normalize(cross(axis, helper));
    const vec3 b = cross(axis, t);
    const float cosTheta = 1.0f - u * (1.0f - cos(radius));
    const float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 6.2831853f * v;
    return normalize(axis * cosTheta + t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)));
}

// Visible fraction of the sun from `point`: 1 without shadows; the transmittance toward the sun
// (hard), or its mean over shadowSamples directions in the sun's cone (soft).
LUXEL_FUNC float octreeSunVisibility(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                     LUXEL_REAL3 point, uint pixel) {
    const vec3 sun = vec3(p.sunX, p.sunY, p.sunZ);
    const int samples = max(int(p.shadowSamples), 1);
    if (p.sunRadius <= 0.0f || samples == 1) {
        return octreeTransmittance(tree, p, point, LUXEL_REAL3(sun), LUXEL_REAL(LUXEL_INFINITY));
    }
    float sum = 0.0f;
    for (int s = 0; s < samples; ++s) {
        const vec3 dir = octreeConeDirection(sun, p.sunRadius, octreeRandom(pixel, uint(s), 1u),
                                             octreeRandom(pixel, uint(s), 2u));
        sum += octreeTransmittance(tree, p, point, LUXEL_REAL3(dir), LUXEL_REAL(LUXEL_INFINITY));
    }
    return sum / float(samples);
}

// Henyey-Greenstein phase function (1/sr) for the cosine between the light's and the scattered
// light's directions of travel.
LUXEL_FUNC float octreePhaseHG(float cosTheta, float g) {
    const float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
    return (1.0f - g * g) / (12.566371f * denominator * sqrt(denominator));
}

// Sunlight scattered toward the viewer at `point` per unit scattering: single scattering
// (E T_sun p) plus octaves i = 1..octaves-1 of multiple scattering, each with the light's
// transmittance raised to 0.5^i, the phase anisotropy halved and the weight multiplied by
// octaveWeight^i (Wrenninge 2015's
// art-directable multiple scattering, applied on the light path as real-time cloud renderers do).
LUXEL_FUNC vec3 octreeInScatter(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                LUXEL_REAL3 point, vec3 viewDir) {
    const vec3 sun = vec3(p.sunX, p.sunY, p.sunZ);
    const float sunT = octreeSunTransmittance(tree, p, point);
    const float cosTheta = dot(viewDir, sun);  // light travels along -sun, seen along -viewDir
    float sum = 0.0f;
    float weight = 1.0f;
    float g = p.phaseG;
    float exponent = 1.0f;
    for (int i = 0; i < max(int(p.octaves), 1); ++i) {
        sum += weight * octreePhaseHG(cosTheta, g) * pow(sunT, exponent);
        weight *= p.octaveWeight;
        g *= 0.5f;
        exponent *= 0.5f;
    }
    return vec3(p.sunR, p.sunG, p.sunB) * sum;
}

LUXEL_FUNC vec3 octreeSky(LUXEL_IN(OctreeRenderParams) p) {
    return vec3(p.skyR, p.skyG, p.skyB);
}

// Surface mode: the first leaf at least `threshold`, lit by the sky and the sun.
LUXEL_FUNC vec3 octreeShadeSurface(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p, LUXEL_REAL3 o,
                                   LUXEL_REAL3 d, uint pixel) {
    uint entry = 0u;
    uint colourIndex = 0u;
    const VoxelTrace trace = octreeTraverseLeaf(tree, int(p.depth), octreeParamsSize(p), o, d,
                                                LUXEL_REAL(LUXEL_INFINITY), int(p.stepCap),
                                                p.threshold, entry, colourIndex);
    if (!trace.hit) return octreeSky(p);
    const vec3 albedo = octreeLeafColour(tree, colourIndex);
    const VoxelSurface surface = voxelSurface(o, d, trace);
    vec3 normal = vec3(0.0f);
    if (trace.axis >= 0) normal[trace.axis] = -float(trace.stp[trace.axis]);
    const vec3 sun = vec3(p.sunX, p.sunY, p.sunZ);
    const float cosine = trace.axis >= 0 ? max(dot(normal, sun), 0.0f) : 1.0f;
    float visibility = 1.0f;
    if (cosine > 0.0f && (p.flags & LUXEL_OCTREE_SHADOWS) != 0u) {
        visibility = octreeSunVisibility(tree, p, surface.point, pixel);
    }
    return albedo *
           (octreeSky(p) * p.ambient + vec3(p.sunR, p.sunG, p.sunB) * (cosine * visibility));
}

// Volume and additive modes: the leaves along the ray, front to back.
LUXEL_FUNC vec3 octreeShadeVolume(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p, LUXEL_REAL3 o,
                                  LUXEL_REAL3 d) {
    const bool additive = p.mode == LUXEL_OCTREE_MODE_ADDITIVE;
    const bool scattering = (p.flags & LUXEL_OCTREE_SCATTERING) != 0u;
    const vec3 viewDir = vec3(float(d.x), float(d.y), float(d.z));
    vec3 radiance = vec3(0.0f);
    float transmittance = 1.0f;
    OctreeRay r;
    if (octreeRayStart(r, int(p.depth), octreeParamsSize(p), o, d, LUXEL_REAL(LUXEL_INFINITY))) {
        for (int steps = 0; steps < int(p.stepCap); ++steps) {
            const OctreeLeaf leaf = octreeLocate(tree, int(p.depth), r.cursor, r.walk.cell);
            if (leaf.value > 0u) {
                const float alpha = octreeAlpha(leaf.value, p);
                const vec3 colour = octreeLeafColour(
                    tree, octreeColourIndex(tree, int(p.depth), r.walk.cell, leaf.entry));
                const LUXEL_REAL t0 = r.walk.t;
                const float chord = float(octreeLeafExitT(r, leaf) - t0);
                if (additive) {
                    radiance += colour * (alpha * chord);
                } else {
                    // Split long chords so the lighting follows the light's transmittance.
                    const int parts = clamp(int(ceil(chord / LUXEL_OCTREE_LIGHT_STEP)), 1,
                                            LUXEL_OCTREE_MAX_LIGHT_STEPS);
                    const float part = chord / float(parts);
                    const float partT = octreeSegmentTransmittance(alpha, part);
                    for (int k = 0; k < parts; ++k) {
                        vec3 light = octreeSky(p) * p.ambient;
                        if (scattering) {
                            const LUXEL_REAL tMid = t0 + LUXEL_REAL((float(k) + 0.5f) * part);
                            light += octreeInScatter(tree, p, o + d * tMid, viewDir);
                        }
                        const vec3 source = scattering ? colour * p.albedo * light : colour;
                        radiance += source * (transmittance * (1.0f - partT));
                        transmittance *= partT;
                        if (transmittance < LUXEL_OCTREE_MIN_TRANSMITTANCE) break;
                    }
                    if (transmittance < LUXEL_OCTREE_MIN_TRANSMITTANCE) {
                        transmittance = 0.0f;
                        break;
                    }
                }
            }
            if (!octreeRayLeave(r, leaf, LUXEL_REAL(LUXEL_INFINITY))) break;
        }
    }
    // Additive is emission only: no background behind the sum.
    return additive ? radiance : radiance + octreeSky(p) * transmittance;
}

// The linear RGB of pixel (px, py), rows top to bottom.
// The primary ray o + t d of pixel (px, py), rows top to bottom; the tile passes
// (octree_tiles.h) follow the same rays, so the two renderers' hits compare cell for cell.
LUXEL_FUNC void octreePixelRay(LUXEL_IN(OctreeRenderParams) p, int px, int py,
                               LUXEL_INOUT(LUXEL_REAL3) o, LUXEL_INOUT(LUXEL_REAL3) d) {
    const float sx = 2.0f * (float(px) + 0.5f) / float(p.width) - 1.0f;
    const float sy = 1.0f - 2.0f * (float(py) + 0.5f) / float(p.height);
    const vec3 dir =
        normalize(vec3(p.forwardX, p.forwardY, p.forwardZ) +
                  vec3(p.rightX, p.rightY, p.rightZ) * sx + vec3(p.upX, p.upY, p.upZ) * sy);
    o = LUXEL_REAL3(LUXEL_REAL(p.originX), LUXEL_REAL(p.originY), LUXEL_REAL(p.originZ));
    d = LUXEL_REAL3(LUXEL_REAL(dir.x), LUXEL_REAL(dir.y), LUXEL_REAL(dir.z));
}

LUXEL_FUNC vec3 octreeRenderPixel(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p, int px,
                                  int py) {
    LUXEL_REAL3 o = LUXEL_REAL3(LUXEL_REAL(0));
    LUXEL_REAL3 d = LUXEL_REAL3(LUXEL_REAL(0));
    octreePixelRay(p, px, py, o, d);
    if (p.mode == LUXEL_OCTREE_MODE_SURFACE) {
        return octreeShadeSurface(tree, p, o, d, uint(py) * p.width + uint(px));
    }
    return octreeShadeVolume(tree, p, o, d);
}

LUXEL_SHARED_END

#endif
