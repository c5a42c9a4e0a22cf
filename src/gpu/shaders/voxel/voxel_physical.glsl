// Physical lighting on the GPU: the twin of src/voxel/shading_physical.cpp in float, with the
// same explicit stack of pending rays, ray cones, depth budget and 1/255 weight threshold. The
// per-hit terms are the shared kernels (shared/optics.h, shared/voxel_shading.h). Sun visibility
// is sunVisibility (sun_visibility.glsl) for the map and field methods, else one hard shadow ray;
// textures are filtered over the cone's footprint and normal maps bend the shading normal
// (texture_sample.glsl). Light from emissive voxels is emitter_light.glsl's, in the ray caster
// alone (LUXEL_VOXEL_EMITTER_BINDINGS). Sky ambient with occlusion (params.skyAmbientRays) is
// sky_ambient.glsl's, its numbers keyed by the camera sample. Included by voxel_shading.glsl
// after castToSurface, skyColor and textureFactor.
#include "shared/face_frame.h"

struct PathRay {
    vec3 origin;
    vec3 direction;  // unit length
    vec3 weight;
    int depth;  // reflections and refractions left
    bool inside;  // travelling through the medium of `cell`
    ivec3 cell;
    float coneWidth;  // RayCone width at `origin` (its spread is params.coneSpread throughout)
    bool primary;     // the camera's ray: the shadow footprint is the camera distance
};

// The face's tangent frame, matching castRay's (u, v): x faces use (z, y), y faces (x, z), z faces
// (x, y), whatever the normal's sign (faceTangents in shading_physical.cpp).
void faceTangents(ivec3 normal, out vec3 tu, out vec3 tv) {
    tu = faceTangentU(normal);
    tv = faceTangentV(normal);
}

// sunVisibility in shading_physical.cpp: 0 facing away, 1 without shadows, else the options'
// method (footprint: camera distance for primary rays, cone width for secondary ones).
float physicalSunVisibility(Hit h, vec3 sun, float footprint) {
    if (dot(vec3(h.normal), sun) <= 0.0) return 0.0;
    if ((params.flags & LUXEL_VOXEL_SHADOWS) == 0u) return 1.0;
    if ((params.flags & LUXEL_VOXEL_SUN_VISIBILITY) != 0u) {
        return sunVisibility(h.point, h.normal, footprint);
    }
    return castToSurface(h.point, sun).hit.hit ? 0.0 : 1.0;
}

// Voxel alpha 1..254 selects slot a - 1; plain blocks use the last entry.
int materialIndex(uint packed) {
    const int a = int(packed >> 24);
    return a >= 1 && a <= 254 ? a - 1 : LUXEL_VOXEL_PLAIN_MATERIAL;
}

float fresnelDielectric(float cosI, float nI, float nT) {
    return (params.flags & LUXEL_VOXEL_FRESNEL_EXACT) != 0u ? fresnelDielectricExact(cosI, nI, nT)
                                                             : fresnelDielectricSchlick(cosI, nI, nT);
}

bool insideWorld(ivec3 c) {
    return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < int(params.sizeX) &&
           c.y < int(params.sizeY) && c.z < int(params.sizeZ);
}

// walkMedium (shading_physical.cpp): the exact DDA through the voxels sharing `cell`'s alpha
// byte, to the face where the ray leaves them.
struct MediumExit {
    float distance;
    vec3 point;
    ivec3 cell;
    ivec3 outward;
    bool intoSolid;
};

MediumExit walkMedium(ivec3 cell, vec3 origin, vec3 dir) {
    const uint medium = voxelValue(cell) >> 24;
    MediumExit e = MediumExit(0.0, origin, cell, ivec3(0), false);
    const int cap = int(params.sizeX + params.sizeY + params.sizeZ) + 3;
    for (int step = 0; step < cap; ++step) {
        int axis = -1;
        float tExit = LUXEL_INFINITY;
        for (int a = 0; a < 3; ++a) {
            if (dir[a] == 0.0) continue;
            const float boundary = float(e.cell[a] + (dir[a] > 0.0 ? 1 : 0));
            const float t = max((boundary - origin[a]) / dir[a], 0.0);
            if (t < tExit) {
                tExit = t;
                axis = a;
            }
        }
        if (axis < 0) break;
        ivec3 outward = ivec3(0);
        outward[axis] = dir[axis] > 0.0 ? 1 : -1;
        const ivec3 next = e.cell + outward;
        const bool inWorld = insideWorld(next);
        const uint v = inWorld ? voxelValue(next) : 0u;
        if (inWorld && (v >> 24) == medium) {
            e.cell = next;
            continue;
        }
        e.distance = tExit;
        e.outward = outward;
        e.intoSolid = (v >> 24) != 0u;
        for (int a = 0; a < 3; ++a) {
            e.point[a] = clamp(origin[a] + tExit * dir[a], float(e.cell[a]), float(e.cell[a] + 1));
        }
        e.point[axis] = float(e.cell[axis] + (outward[axis] > 0 ? 1 : 0));
        return e;
    }
    return e;
}

#ifdef LUXEL_VOXEL_EMITTER_BINDINGS
#include "voxel/emitter_light.glsl"
#endif
#include "voxel/sky_ambient.glsl"

#define LUXEL_PUSH_PATH(ray)                                                                   \
    {                                                                                          \
        const PathRay pushed = ray;                                                            \
        if (max(pushed.weight.x, max(pushed.weight.y, pushed.weight.z)) >= 1.0 / 255.0 &&      \
            size < LUXEL_VOXEL_PATH_STACK) {                                                   \
            stack[size++] = pushed;                                                            \
        }                                                                                      \
    }

// pixel (y * width + x) and sampleIndex key the sky ambient rays' numbers (shadePhysical in
// shading_physical.cpp).
vec3 shadePhysical(vec3 o, vec3 d, uint pixel, uint sampleIndex) {
    const float len = length(d);
    if (!(len > 0.0) || isinf(len)) return skyColor(d);
    const vec3 sun = normalize(vec3(params.sunX, params.sunY, params.sunZ));
    const vec3 sunE = vec3(params.sunIrradianceR, params.sunIrradianceG, params.sunIrradianceB);
    const int model = int(params.specular);
    const bool textures = (params.flags & LUXEL_VOXEL_PROCEDURAL_TEXTURE) != 0u;
    const bool refraction = (params.flags & LUXEL_VOXEL_REFRACTION) != 0u;
    PathRay stack[LUXEL_VOXEL_PATH_STACK];
    int size = 0;
    LUXEL_PUSH_PATH(PathRay(o, d / len, vec3(1.0),
                            min(int(params.maxReflections), LUXEL_VOXEL_MAX_DEPTH), false,
                            ivec3(0), 0.0, true));
    vec3 sum = vec3(0.0);
#ifdef LUXEL_VOXEL_EMITTER_BINDINGS
    int emitterBudget = LUXEL_EMITTER_PATH_RAYS;
#endif
    // One stream for the sky ambient rays of all the path's hits, in the order the stack pops them.
    uvec2 rng = pathRngKey(uvec2(LUXEL_SKY_AMBIENT_SEED, 0u), pixel, sampleIndex);
    while (size > 0) {
        const PathRay r = stack[--size];
        if (r.inside) {
            const VoxelMaterial m = materials[materialIndex(voxelValue(r.cell))];
            const MediumExit e = walkMedium(r.cell, r.origin, r.direction);
            const vec3 w =
                r.weight * voxelTransmittance(vec3(m.absorptionR, m.absorptionG, m.absorptionB),
                                              e.distance);
            const float exitCone = r.coneWidth + params.coneSpread * e.distance;
            if (e.intoSolid) {
                // Another solid behind the glass: seen directly.
                LUXEL_PUSH_PATH(
                    PathRay(e.point, r.direction, w, r.depth, false, ivec3(0), exitCone, false));
                continue;
            }
            if (r.depth - 1 < 0) continue;
            const vec3 nIn = -vec3(e.outward);
            const float cosI = -dot(nIn, r.direction);
            const float k = opticsRefractK(cosI, m.ior);
            const vec3 reflected = normalize(opticsReflect(r.direction, nIn));
            float reflectance = 1.0;
            if (!(k < 0.0)) reflectance = fresnelDielectric(cosI, m.ior, 1.0);
            LUXEL_PUSH_PATH(PathRay(e.point, reflected, w * reflectance, r.depth - 1, true, e.cell,
                                    exitCone, false));
            if (!(k < 0.0)) {
                const vec3 refracted = normalize(opticsRefract(r.direction, nIn, m.ior, cosI, k));
                LUXEL_PUSH_PATH(PathRay(e.point, refracted, w * (1.0 - reflectance), r.depth - 1,
                                        false, ivec3(0), exitCone, false));
            }
            continue;
        }
        const SurfaceHit s = castToSurface(r.origin, r.direction);
        if (!s.hit.hit) {
            sum += r.weight * skyColor(r.direction);
            continue;
        }
        const Hit h = s.hit;
        if (h.normal == ivec3(0)) continue;  // started inside a solid voxel
        const uint packed = voxelValue(h.voxel);
        const int materialSlot = materialIndex(packed);
        const VoxelMaterial m = materials[materialSlot];
        const bool own = (m.flags & LUXEL_VOXEL_MATERIAL_OWN) != 0u;
        const bool proceduralFlag = (m.flags & LUXEL_VOXEL_MATERIAL_PROCEDURAL) != 0u;

        // RayCone at the hit; castToSurface restarts past cutouts, so t from the ray's origin.
        const float t = length(h.point - r.origin);
        const float width = r.coneWidth + params.coneSpread * t;
        const float footprint = r.primary ? t : width;
        const TexelFootprint texelArea = textureFootprint(width, r.direction, h.normal);

        vec3 colour = albedo(packed) * vec3(m.albedoR, m.albedoG, m.albedoB);
        const bool procedural =
            textures && (s.slot < 0 ? !own || proceduralFlag : own && proceduralFlag);
        if (s.slot >= 0) colour = colour * sampleTexture(s.slot, h.u, h.v, texelArea).rgb;
        if (procedural) colour = colour * textureFactor(h);

        // Shading normal: the face normal, bent by the slot's normal map.
        const vec3 ng = vec3(h.normal);
        vec3 sn = ng;
        if (s.slot >= 0 && (params.flags & LUXEL_VOXEL_NORMAL_MAPS) != 0u) {
            const vec3 tn = sampleNormal(s.slot, h.u, h.v, texelArea);
            vec3 tu, tv;
            faceTangents(h.normal, tu, tv);
            sn = normalize(tu * tn.x + tv * tn.y + ng * tn.z);
        }
        const vec3 view = -r.direction;
        // Shading normals facing away from the eye fall back to the face normal.
        const vec3 n = dot(sn, view) > 0.0 ? sn : ng;
        const float cosV = clamp(dot(n, view), 0.0, 1.0);
        const bool transmissive = refraction && m.transmission > 0.0;
        const float kd = (1.0 - m.metallic) * (1.0 - (transmissive ? m.transmission : 0.0));
        const vec3 f0 = mix(vec3(fresnelF0(1.0, m.ior)), colour, m.metallic);
        const float alpha = max(m.roughness * m.roughness, params.alphaMin);
        const float vis = physicalSunVisibility(h, sun, footprint);
        // Sky ambient: the assumed share along the shading normal, or what rays about the face
        // normal find (the visible share then weighs the rough reflection).
        vec3 ambient;
        float skyShare = params.skyAmbient;
        if (params.skyAmbientRays > 0u) {
            const SkyAmbient a = traceSkyAmbient(h.point, h.normal, rng);
            ambient = a.sky * LUXEL_OPTICS_PI;
            skyShare = a.visible;
        } else {
            ambient = skyColor(n) * (LUXEL_OPTICS_PI * params.skyAmbient);
        }
        sum += r.weight * vec3(m.emissionR, m.emissionG, m.emissionB) +
               r.weight * voxelSurfaceLight(colour * kd, f0, alpha, model, n, view, sun, sunE, vis,
                                            ambient);

        vec3 reflected = opticsReflect(r.direction, n);
        if (dot(reflected, ng) <= 0.0) reflected = opticsReflect(r.direction, ng);
        const float fDielectric = fresnelDielectric(cosV, 1.0, m.ior);
        const vec3 fMirror = mix(vec3(fDielectric), fresnelSchlickRgb(colour, cosV), m.metallic);
        const float g = voxelMirrorWeight(m.roughness);
#ifdef LUXEL_VOXEL_EMITTER_BINDINGS
        if ((params.flags & LUXEL_VOXEL_EMITTER_LIGHT) != 0u) {
            // The highlight of a lamp takes the rough share: mirror rays see lamps themselves.
            sum += r.weight * emitterLight(h.point, h.normal, n, view, colour * kd, f0, alpha,
                                           model, 1.0 - g, emitterBudget);
        }
#endif
        if (g < 1.0) {
            sum += r.weight * voxelRoughFresnel(f0, cosV, m.roughness) *
                   ((1.0 - g) * skyShare) * skyColor(reflected);
        }
        if (r.depth <= 0) continue;
        if (g > 0.0) {
            LUXEL_PUSH_PATH(PathRay(h.point, normalize(reflected), r.weight * (fMirror * g),
                                    r.depth - 1, false, ivec3(0), width, false));
        }
        if (transmissive) {
            const float cosI = -dot(ng, r.direction);
            const float eta = 1.0 / m.ior;
            const float k = opticsRefractK(cosI, eta);
            const float fEntry = fresnelDielectric(cosI, 1.0, m.ior);
            if (k >= 0.0) {
                LUXEL_PUSH_PATH(PathRay(h.point, normalize(opticsRefract(r.direction, ng, eta, cosI, k)),
                                        r.weight * ((1.0 - fEntry) * m.transmission),
                                        r.depth - 1, true, h.voxel, width, false));
            }
        }
    }
    return sum;
}
