// Shading, the GPU side of src/voxel/shading.cpp and surface_cast.cpp in float: the terms
// (face factor, sky, procedural texture and its hash, texel addressing, running average) are the
// shared header shared/voxel_shading.h and the cutout restart point is voxelContinueThrough in
// shared/voxel_dda.h; this file holds the buffer glue, the cutout loop and the bounce loop.
// Needs voxel_world_access.glsl and the texture buffers.
#include "shared/sky_preetham.h"
#include "shared/voxel_shading.h"

vec3 albedo(uint packed) {
    return vec3(srgbTable[packed & 0xffu], srgbTable[(packed >> 8) & 0xffu],
                srgbTable[(packed >> 16) & 0xffu]);
}

SkyPerez skyPerezAt(int first) {
    return SkyPerez(params.skyPerez[first], params.skyPerez[first + 1], params.skyPerez[first + 2],
                    params.skyPerez[first + 3], params.skyPerez[first + 4]);
}

vec3 skyColor(vec3 direction) {
    if (params.skyModel == LUXEL_SKY_PREETHAM) {
        const PreethamSky sky = PreethamSky(
            skyPerezAt(0), skyPerezAt(5), skyPerezAt(10),
            vec3(params.skyZenithOverF0[0], params.skyZenithOverF0[1], params.skyZenithOverF0[2]));
        const float len = length(direction);
        const vec3 w = len > 0.0 ? direction * (1.0 / len) : vec3(0.0);
        const vec3 sun = vec3(params.sunX, params.sunY, params.sunZ);
        const float sunLength = length(sun);
        return preethamSkyColor(sky, w, sunLength > 0.0 ? sun * (1.0 / sunLength)
                                                        : vec3(0.0, 1.0, 0.0));
    }
    const vec3 top = vec3(params.skyTopR, params.skyTopG, params.skyTopB);
    const vec3 horizon = vec3(params.skyHorizonR, params.skyHorizonG, params.skyHorizonB);
    const float len = length(direction);
    const float s = len > 0.0 ? clamp(direction.y / len, 0.0, 1.0) : 0.0;
    return voxelSkyColor(horizon, top, s);
}

float textureFactor(Hit h) {
    return voxelTextureFactor(h.voxel, h.normal, h.u, h.v, int(params.textureTexels),
                              params.textureStrength);
}

vec4 lookupTexel(int slot, float u, float v) {
    const VoxelTextureInfo info = textureInfo[slot];
    const int w = int(info.width), h = int(info.height);
    const int column = voxelTexelIndex(u, w);
    const int row = h - 1 - voxelTexelIndex(v, h);
    return texels[info.texelOffset + uint(row * w + column)];
}

struct SurfaceHit {
    Hit hit;
    int slot;
    vec4 texel;
};

// castToSurface (surface_cast.cpp): past cutout texels, at most LUXEL_VOXEL_MAX_CUTOUTS times.
SurfaceHit castToSurface(vec3 o, vec3 d) {
    SurfaceHit s = SurfaceHit(missHit(), -1, vec4(1.0));
    vec3 origin = o;
    for (int continuations = 0;; ++continuations) {
        s.hit = castRay(origin, d);
        if (!s.hit.hit) return s;
        const int slot = int(voxelValue(s.hit.voxel) >> 24) - 1;
        if (slot < 0 || slot >= 254 || slot >= int(params.textureCount)) {
            s.slot = -1;
            s.texel = vec4(1.0);
            return s;
        }
        s.slot = slot;
        s.texel = lookupTexel(slot, s.hit.u, s.hit.v);
        if (!(s.texel.a < 0.5)) return s;
        if (continuations == LUXEL_VOXEL_MAX_CUTOUTS) {
            s.hit = missHit();
            s.slot = -1;
            return s;
        }
        origin = voxelContinueThrough(o, d, s.hit.voxel);
    }
    return s;
}

struct Sample {
    vec3 colour;
    SurfaceHit surface;
    bool reflects;
    vec3 nextOrigin, nextDirection;
};

// coneWidth: the ray cone's width at o (its spread is params.coneSpread), for texture filtering.
Sample shadeSample(vec3 o, vec3 d, float coneWidth) {
    Sample s;
    s.surface = castToSurface(o, d);
    s.reflects = false;
    s.nextOrigin = vec3(0.0);
    s.nextDirection = vec3(0.0);
    if (!s.surface.hit.hit) {
        s.colour = skyColor(d);
        return s;
    }
    const Hit h = s.surface.hit;
    const vec3 n = vec3(h.normal);
    const bool hasNormal = h.normal != ivec3(0);
    vec3 colour = albedo(voxelValue(h.voxel));
    if (s.surface.slot >= 0) {
        vec4 texel = s.surface.texel;  // the nearest texel decided the cutout
        if (params.textureFilter != LUXEL_TEXTURE_NEAREST) {
            texel = sampleTexture(
                s.surface.slot, h.u, h.v,
                textureFootprint(coneWidth + params.coneSpread * length(h.point - o), d,
                                 h.normal));
        }
        colour = colour * texel.rgb;
    } else if ((params.flags & LUXEL_VOXEL_PROCEDURAL_TEXTURE) != 0u) {
        colour = colour * textureFactor(h);
    }
    if ((params.flags & LUXEL_VOXEL_FACE_SHADING) != 0u) {
        bool inShadow = false;
        const vec3 sun = vec3(params.sunX, params.sunY, params.sunZ);
        if ((params.flags & LUXEL_VOXEL_SHADOWS) != 0u && hasNormal && dot(n, sun) > 0.0) {
            inShadow = castToSurface(h.point, normalize(sun)).hit.hit;
        }
        colour = colour * voxelFaceFactor(h.normal, sun, params.ambient, inShadow);
    }
    s.colour = colour;
    if (hasNormal) {
        const vec3 dn = normalize(d);
        s.nextOrigin = h.point;
        s.nextDirection = dn - n * (2.0 * dot(dn, n));
        s.reflects = true;
    }
    return s;
}

float reflectivityOf(SurfaceHit s) {
    float r = params.reflectivity;
    if (s.slot >= 0 && textureInfo[s.slot].reflectivity >= 0.0) r = textureInfo[s.slot].reflectivity;
    return (isnan(r) || isinf(r)) ? 0.0 : clamp(r, 0.0, 1.0);
}

#include "voxel/voxel_physical.glsl"

// shadeRay (shading.cpp) for camera sample sampleIndex of pixel y * width + x.
vec3 shadeRay(vec3 o, vec3 d, uint pixel, uint sampleIndex) {
    if ((params.flags & LUXEL_VOXEL_PHYSICAL) != 0u) return shadePhysical(o, d, pixel, sampleIndex);
    const int bounces = int(params.maxReflections);
    vec3 sum = vec3(0.0);
    float coneWidth = 0.0;  // RayCone::after at each bounce
    if ((params.flags & LUXEL_VOXEL_ENERGY_CONSERVING) == 0u) {
        for (int k = 1; k <= bounces + 1; ++k) {
            const Sample s = shadeSample(o, d, coneWidth);
            if (k == 1) {
                sum = s.colour;
            } else {
                sum = voxelRunningAverage(sum, s.colour, k);
            }
            if (!s.reflects) break;
            coneWidth += params.coneSpread * length(s.nextOrigin - o);
            o = s.nextOrigin;
            d = s.nextDirection;
        }
        return sum;
    }
    float weight = 1.0;
    for (int k = 0; k <= bounces; ++k) {
        const Sample s = shadeSample(o, d, coneWidth);
        if (!s.reflects || k == bounces) {
            sum += s.colour * weight;
            break;
        }
        const float r = reflectivityOf(s.surface);
        sum += s.colour * (weight * (1.0 - r));
        weight *= r;
        if (weight == 0.0) break;
        coneWidth += params.coneSpread * length(s.nextOrigin - o);
        o = s.nextOrigin;
        d = s.nextDirection;
    }
    return sum;
}
