// EmitterLights::light (src/voxel/emitter_light.cpp) on the GPU: the light of emissive voxel faces
// at a point of the ray caster, from the grid's lists (shared/emitter_light.h, bindings 15..17),
// with the same float arithmetic and the same shadow rays (line_transmittance.glsl). Included by
// voxel_physical.glsl where the includer defines LUXEL_VOXEL_EMITTER_BINDINGS (the ray caster);
// needs castToSurface, walkMedium, materialIndex and fresnelDielectric.
#include "shared/emitter_light.h"

layout(std430, set = 0, binding = 15) readonly buffer EmitterCellOffsets { uint emitterOffset[]; };
layout(std430, set = 0, binding = 16) readonly buffer EmitterCellFaces { uint emitterList[]; };
layout(std430, set = 0, binding = 17) readonly buffer EmitterFaces {
    CascadeNearEmitter emitterFaces[];
};

// Shadow rays pass glass and water as the CPU's faceRayTransmittance does, with the ray
// caster's refraction switch and Fresnel model.
bool lineMedia() {
    return (params.flags & LUXEL_VOXEL_REFRACTION) != 0u;
}

float lineTransmission(VoxelMaterial m) {
    return (params.flags & LUXEL_VOXEL_REFRACTION) != 0u ? m.transmission : 0.0;
}

float lineFresnel(float cosI, float ior) {
    return ior == 1.0 ? 0.0 : fresnelDielectric(cosI, 1.0, ior);
}

#include "voxel/line_transmittance.glsl"

vec3 emitterLight(vec3 p, ivec3 faceNormal, vec3 sn, vec3 view, vec3 diffuseAlbedo, vec3 f0,
                  float alpha, int model, float specularWeight, inout int budget) {
    const bool glossy = specularWeight > 0.0 && model != LUXEL_VOXEL_SPECULAR_NONE;
    // Nothing to reflect (clear glass, a mirror): no rays.
    if (!(maxComponent(diffuseAlbedo) > 0.0) && !glossy) return vec3(0.0);
    if (budget < 1) return vec3(0.0);
    const int side = LUXEL_EMITTER_CELL;
    const ivec3 cells = ivec3((int(params.sizeX) + side - 1) / side,
                              (int(params.sizeY) + side - 1) / side,
                              (int(params.sizeZ) + side - 1) / side);
    const int cell = emitterCellIndex(p, cells);
    const vec3 ng = vec3(faceNormal);
    const float threshold = params.emitterFloor;
    // The strongest emitters by unoccluded light, strongest first (ties: the earlier in the list).
    int kept = 0;
    uint keptFace[LUXEL_EMITTER_MAX_FACES], keptRank[LUXEL_EMITTER_MAX_FACES];
    float keptLight[LUXEL_EMITTER_MAX_FACES], keptFormFactor[LUXEL_EMITTER_MAX_FACES];
    for (uint i = emitterOffset[cell]; i < emitterOffset[cell + 1]; ++i) {
        const CascadeNearEmitter e = emitterFaces[emitterList[i]];
        const EmitterSpan span = emitterSpanInFront(p, ng, e);
        const float formFactor = emitterFormFactor(p, ng, e, span);
        const float e0 = formFactor * max(e.r, max(e.g, e.b));
        if (!(emitterFade(e0, threshold) > 0.0)) continue;
        const uint rank = emitterRank(e0);
        if (kept == LUXEL_EMITTER_MAX_FACES && !(rank > keptRank[kept - 1])) continue;
        int j = min(kept, LUXEL_EMITTER_MAX_FACES - 1);
        while (j > 0 && rank > keptRank[j - 1]) {
            keptFace[j] = keptFace[j - 1];
            keptRank[j] = keptRank[j - 1];
            keptLight[j] = keptLight[j - 1];
            keptFormFactor[j] = keptFormFactor[j - 1];
            --j;
        }
        keptFace[j] = emitterList[i];
        keptRank[j] = rank;
        keptLight[j] = e0;
        keptFormFactor[j] = formFactor;
        kept = min(kept + 1, LUXEL_EMITTER_MAX_FACES);
    }
    const int n = clamp(int(params.emitterRays), 1, LUXEL_EMITTER_MAX_RAYS);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    for (int k = 0; k < kept; ++k) {
        const CascadeNearEmitter e = emitterFaces[keptFace[k]];
        const EmitterSpan span = emitterSpanInFront(p, ng, e);
        // Strongest first, each emitter its rays while the path's budget lasts.
        if (n > budget) break;
        budget -= n;
        const float scale = keptFormFactor[k] * emitterFade(keptLight[k], threshold);
        const vec3 share = vec3(e.r, e.g, e.b) * (scale / float(n));
        const ivec3 voxel = ivec3(e.x, e.y, e.z), normal = ivec3(nearEmitterNormal(e.normal));
        for (int i = 0; i < n; ++i) {
            const vec3 d = normalize(emitterRayTarget(e, span, i, n) - p);
            const vec3 t = lineTransmittance(p, d, true, voxel, normal, e.extent);
            if (!(maxComponent(t) > 0.0)) continue;
            diffuse += share * t;
            if (glossy) specular += share * t * voxelSpecularBrdf(model, sn, view, d, alpha, f0);
        }
    }
    return diffuseAlbedo * diffuse * (1.0 / LUXEL_OPTICS_PI) + specular * specularWeight;
}
