// Physical lighting (shading_physical.h): a Whitted tracer over voxel faces with a shared depth
// budget, run from an explicit stack like its GPU twin (voxel_shading.glsl). The per-hit terms
// (Fresnel, Snell, the BRDFs, the lighting sum) are the shared kernels of
// src/gpu/shaders/shared/optics.h and voxel_shading.h.
#include "voxel/shading_physical.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gpu/shaders/shared/face_frame.h"
#include "gpu/shaders/shared/sky_ambient.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texel_footprint.h"
#include "voxel/sky_ambient.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

constexpr float kPi = 3.14159265358979f;
// Paths whose weight falls below one 8-bit step are not continued.
constexpr float kMinWeight = 1.0f / 255.0f;
// Enough for the deepest budget (16): each step pops one entry and pushes at most two.
constexpr int kStackSize = 20;

shared::vec3 v3(Rgb c) {
    return {c.r, c.g, c.b};
}
shared::vec3 v3(Vec3d v) {
    return {float(v.x), float(v.y), float(v.z)};
}
Rgb rgb(shared::vec3 v) {
    return {v.x, v.y, v.z};
}
Vec3d toDouble(Int3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}
Vec3d toDouble(shared::vec3 v) {
    return {v.x, v.y, v.z};
}

Rgb colourOf(Voxel v) {
    return {srgbToLinear(v.r / 255.0f), srgbToLinear(v.g / 255.0f), srgbToLinear(v.b / 255.0f)};
}

// The face's tangent frame, matching the (u, v) of castRay (voxel_walk.h; shared/face_frame.h).
void faceTangents(Int3 normal, Vec3d& tu, Vec3d& tv) {
    const shared::vec3 u = shared::faceTangentU({normal.x, normal.y, normal.z});
    const shared::vec3 v = shared::faceTangentV({normal.x, normal.y, normal.z});
    tu = {u.x, u.y, u.z}, tv = {v.x, v.y, v.z};
}

struct PathRay {
    Vec3d origin, direction;  // direction unit length
    Rgb weight;
    int depth = 0;  // reflections and refractions left
    RayCone cone;
    bool primary = false;
    bool inside = false;  // travelling through the medium of `cell`
    Int3 cell;
};

struct Stack {
    PathRay rays[kStackSize];
    int size = 0;
    void push(const PathRay& r) {
        if (r.weight.maxComponent() >= kMinWeight && size < kStackSize) rays[size++] = r;
    }
};

float sunVisibility(const VoxelWorld& world, const TextureSet* textures, const ShadeOptions& o,
                    const Hit& hit, Vec3d sun, double footprint) {
    if (dot(toDouble(hit.normal), sun) <= 0.0) return 0.0f;
    if (!o.shadows) return 1.0f;
    if (o.sunVisibility) return o.sunVisibility->visibility({hit.point, hit.normal, footprint});
    return castToSurface(world, textures, {hit.point, sun}, o.stepCap).hit.hit ? 0.0f : 1.0f;
}

// A ray leaving a transmissive medium at `exit`: refracts out, reflects back (both weighted by
// Fresnel), or reflects totally.
void leaveMedium(const PathRay& r, const MediumExit& exit, const Material& m, Rgb weight,
                 const ShadeOptions& o, Stack& stack) {
    PathRay next = r;
    next.origin = exit.point;
    next.depth = r.depth - 1;
    next.cone = r.cone.after(exit.distance);
    next.primary = false;
    if (exit.intoSolid) {
        // Another solid behind the glass: seen directly (the interface is not refracted).
        next.inside = false;
        next.depth = r.depth;
        next.weight = weight;
        stack.push(next);
        return;
    }
    if (next.depth < 0) return;
    const ExitSplit split = splitAtExit(r.direction, exit.outward, m.ior, o.fresnel);
    PathRay back = next;
    back.direction = split.reflected;
    back.weight = weight * split.reflectance;
    back.cell = exit.cell;
    stack.push(back);
    if (split.total) return;
    next.inside = false;
    next.direction = split.refracted;
    next.weight = weight * (1.0f - split.reflectance);
    stack.push(next);
}

}  // namespace

ExitSplit splitAtExit(Vec3d direction, Int3 outward, float ior,
                      ShadeOptions::FresnelModel fresnel) {
    const shared::vec3 d = v3(direction);
    const shared::vec3 nIn = -v3(toDouble(outward));  // faces the incident (inside) side
    const float cosI = -dot(nIn, d);
    const float k = shared::opticsRefractK(cosI, ior);
    ExitSplit split;
    split.reflected = normalize(toDouble(shared::opticsReflect(d, nIn)));
    split.total = k < 0.0f;
    if (split.total) return split;
    split.reflectance = fresnel == ShadeOptions::FresnelModel::Exact
                            ? shared::fresnelDielectricExact(cosI, ior, 1.0f)
                            : shared::fresnelDielectricSchlick(cosI, ior, 1.0f);
    split.refracted = normalize(toDouble(shared::opticsRefract(d, nIn, ior, cosI, k)));
    return split;
}

MediumExit walkMedium(const VoxelWorld& world, Int3 cell, Vec3d origin, Vec3d direction) {
    const std::uint8_t medium = world.get(cell.x, cell.y, cell.z).a;
    const Int3 size = world.size();
    MediumExit e;
    e.cell = cell;
    const int cap = size.x + size.y + size.z + 3;
    // Exit t of the current cell on each axis, from the fixed origin (no drift); a step moves
    // the cell on one axis only, so only that axis's exit is found again.
    double exitT[3];
    const auto exitAlong = [&](int a) {
        if (direction[a] == 0.0) return kInfinity;
        const double boundary = e.cell[a] + (direction[a] > 0.0 ? 1 : 0);
        return std::max((boundary - origin[a]) / direction[a], 0.0);
    };
    for (int a = 0; a < 3; ++a) exitT[a] = exitAlong(a);
    for (int step = 0; step < cap; ++step) {
        int axis = -1;
        double tExit = kInfinity;
        for (int a = 0; a < 3; ++a) {
            if (exitT[a] < tExit) tExit = exitT[a], axis = a;  // ties: the lowest axis, as the DDA
        }
        if (axis < 0) break;
        // Vectors made whole, not stored into a component picked at run time (a stall of the
        // store forwarding when they are read next).
        const int sign = direction[axis] > 0.0 ? 1 : -1;
        const Int3 outward{axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0};
        const Int3 next{e.cell.x + outward.x, e.cell.y + outward.y, e.cell.z + outward.z};
        const Voxel v = world.get(next.x, next.y, next.z);
        if (world.inside(next.x, next.y, next.z) && v.a == medium) {
            e.cell = next;
            exitT[axis] = exitAlong(axis);
            continue;
        }
        e.distance = tExit;
        e.outward = outward;
        e.intoSolid = v.solid();
        double p[3];
        for (int a = 0; a < 3; ++a) {
            p[a] = std::clamp(origin[a] + tExit * direction[a], double(e.cell[a]),
                              double(e.cell[a] + 1));
        }
        const double face = e.cell[axis] + (sign > 0 ? 1 : 0);
        e.point = {axis == 0 ? face : p[0], axis == 1 ? face : p[1], axis == 2 ? face : p[2]};
        return e;
    }
    // Unreachable for finite directions: every walk leaves the world.
    e.distance = 0;
    e.point = origin;
    return e;
}

Rgb shadePhysical(const VoxelWorld& world, const Ray& ray, const RayCone& cone,
                  const ShadeOptions& o, const TextureSet* textures, RaySample raySample) {
    Vec3d unit;
    if (!physicalRayDirection(ray.direction, unit)) return skyColor(ray.direction, o);
    const Vec3d sun = normalize(Vec3d{o.sunDirection.x, o.sunDirection.y, o.sunDirection.z});
    const shared::vec3 l = v3(sun);
    const int model = o.specular == ShadeOptions::Specular::Ggx ? LUXEL_VOXEL_SPECULAR_GGX
                      : o.specular == ShadeOptions::Specular::BlinnPhong
                          ? LUXEL_VOXEL_SPECULAR_BLINN_PHONG
                          : LUXEL_VOXEL_SPECULAR_NONE;
    // The sun is a disk: the smoothest highlight is as wide as its image in a mirror.
    const float alphaMin = std::max(0.5f * float(o.sunAngularRadius), 1e-3f);

    Stack stack;
    PathRay first;
    first.origin = ray.origin;
    first.direction = unit;
    first.weight = Rgb(1.0f);
    first.depth = std::clamp(o.maxReflections, 0, 16);
    first.cone = cone;
    first.primary = true;
    stack.push(first);
    Rgb sum;
    int emitterBudget = kEmitterPathRays;  // shadow rays the path's hits may cast in all
    // The sky ambient rays of all the path's hits draw from one stream, in the order the stack
    // pops them (voxel_physical.glsl draws the same).
    PathRng rng(LUXEL_SKY_AMBIENT_SEED, raySample.pixel, raySample.sample);
    const bool traceAmbient = o.skyAmbientRays > 0;
    const Hit* primaryCast = raySample.primary;
    while (stack.size > 0) {
        const PathRay r = stack.rays[--stack.size];
        if (r.inside) {
            const Voxel v = world.get(r.cell.x, r.cell.y, r.cell.z);
            const Material& m = o.materials.forSlot(textureSlotOf(v));
            const MediumExit exit = walkMedium(world, r.cell, r.origin, r.direction);
            const Rgb tint =
                rgb(shared::voxelTransmittance(v3(m.absorption), float(exit.distance)));
            leaveMedium(r, exit, m, r.weight * tint, o, stack);
            continue;
        }
        // The camera ray's cast may be made already (RaySample::primary): the first ray popped.
        const Hit* cast = std::exchange(primaryCast, nullptr);
        const SurfaceHit s =
            castToSurface(world, textures, {r.origin, r.direction}, o.stepCap, kInfinity, cast);
        if (!s.hit.hit) {
            sum += r.weight * skyColor(r.direction, o);
            continue;
        }
        const Hit& hit = s.hit;
        if (hit.normal == Int3{}) continue;  // the ray started inside a solid voxel: black
        const Voxel voxel = world.get(hit.voxel.x, hit.voxel.y, hit.voxel.z);
        // The alpha byte selects the material whether or not a texture fills its slot.
        const int slot = s.slot;
        const int materialSlot = textureSlotOf(voxel);
        const Material& m = o.materials.forSlot(materialSlot);
        const double footprint = r.primary ? hit.t : r.cone.widthAt(hit.t);
        const TexelFootprint texelArea = texelFootprint(r.cone, hit.t, r.direction, hit.normal);

        // Surface colour: voxel colour x texel x procedural texture x material albedo.
        Rgb colour = colourOf(voxel) * m.albedo;
        const bool procedural =
            o.textures && (slot < 0 ? !o.materials.hasSlot(materialSlot) || m.proceduralTexture
                                    : o.materials.hasSlot(slot) && m.proceduralTexture);
        if (slot >= 0) {
            const Texel t =
                textures->sample(slot, hit.u, hit.v, texelArea, o.textureFilter, o.maxAnisotropy);
            colour = colour * Rgb(t.r, t.g, t.b);
        }
        if (procedural) colour = colour * textureFactor(hit, o);

        // Shading normal: the face normal, bent by the slot's normal map.
        const Vec3d ng = toDouble(hit.normal);
        Vec3d n = ng;
        if (slot >= 0 && o.normalMaps) {
            const Vec3 t =
                textures->normalAt(slot, hit.u, hit.v, texelArea, o.textureFilter, o.maxAnisotropy);
            Vec3d tu, tv;
            faceTangents(hit.normal, tu, tv);
            n = normalize(tu * double(t.x) + tv * double(t.y) + ng * double(t.z));
        }
        const shared::vec3 sn = v3(n);
        const shared::vec3 d = v3(r.direction);
        const shared::vec3 view = -d;
        // Shading normals facing away from the eye fall back to the face normal.
        const shared::vec3 nShade = dot(sn, view) > 0.0f ? sn : v3(ng);
        const float cosV = std::clamp(dot(nShade, view), 0.0f, 1.0f);

        const bool transmissive = o.refraction && m.transmission > 0.0f;
        const float kd = (1.0f - m.metallic) * (1.0f - (transmissive ? m.transmission : 0.0f));
        const shared::vec3 base = v3(colour);
        const shared::vec3 f0 =
            shared::mix(shared::vec3(shared::fresnelF0(1.0f, m.ior)), base, m.metallic);
        const float alpha = std::max(m.roughness * m.roughness, alphaMin);
        const float vis = sunVisibility(world, textures, o, hit, sun, footprint);
        // Sky ambient: the assumed share of the sky along the shading normal, or the sky that
        // rays about the face normal find (the visible share then weighs the rough reflection).
        shared::vec3 ambient;
        float skyShare = o.skyAmbient;
        if (traceAmbient) {
            const SkyAmbient a = traceSkyAmbient(world, textures, hit.point, hit.normal, o, rng);
            ambient = v3(a.sky) * kPi;
            skyShare = a.visible;
        } else {
            ambient = v3(skyColor(toDouble(nShade), o)) * (kPi * o.skyAmbient);
        }
        sum += r.weight * m.emission +
               r.weight * rgb(shared::voxelSurfaceLight(base * kd, f0, alpha, model, nShade, view,
                                                        l, v3(o.sunIrradiance), vis, ambient));

        // Environment reflection: Fresnel-weighted, a mirror ray for smooth surfaces, the sky's
        // colour in the reflected direction for rough ones.
        shared::vec3 reflected = shared::opticsReflect(d, nShade);
        if (dot(reflected, v3(ng)) <= 0.0f) reflected = shared::opticsReflect(d, v3(ng));
        const float fDielectric = o.fresnel == ShadeOptions::FresnelModel::Exact
                                      ? shared::fresnelDielectricExact(cosV, 1.0f, m.ior)
                                      : shared::fresnelDielectricSchlick(cosV, 1.0f, m.ior);
        const shared::vec3 fMirror = shared::mix(shared::vec3(fDielectric),
                                                 shared::fresnelSchlickRgb(base, cosV), m.metallic);
        const float g = shared::voxelMirrorWeight(m.roughness);
        if (o.emitterLight && o.emitterLights) {
            // The highlight of a lamp takes the rough share: mirror rays see lamps themselves.
            EmitterLights::Surface es;
            es.point = hit.point;
            es.faceNormal = hit.normal;
            es.shadingNormal = {nShade.x, nShade.y, nShade.z};
            es.view = {view.x, view.y, view.z};
            es.diffuseAlbedo = colour * kd;
            es.f0 = {f0.x, f0.y, f0.z};
            es.alpha = alpha;
            es.specularModel = model;
            es.specularWeight = 1.0f - g;
            sum += r.weight *
                   o.emitterLights->light(world, textures, es, o, o.emitterRays, emitterBudget);
        }
        if (g < 1.0f) {
            const shared::vec3 fRough = shared::voxelRoughFresnel(f0, cosV, m.roughness);
            sum +=
                r.weight * rgb(fRough * (1.0f - g) * skyShare) * skyColor(toDouble(reflected), o);
        }
        if (r.depth <= 0) continue;
        PathRay child;
        child.origin = hit.point;
        child.depth = r.depth - 1;
        child.cone = r.cone.after(hit.t);
        if (g > 0.0f) {
            child.direction = normalize(toDouble(reflected));
            child.weight = r.weight * rgb(fMirror * g);
            stack.push(child);
        }
        if (transmissive) {
            // Entering the denser medium: never total reflection.
            const shared::vec3 nIn = v3(ng);
            const float cosI = -dot(nIn, d);
            const float eta = 1.0f / m.ior;
            const float k = shared::opticsRefractK(cosI, eta);
            const float fEntry = o.fresnel == ShadeOptions::FresnelModel::Exact
                                     ? shared::fresnelDielectricExact(cosI, 1.0f, m.ior)
                                     : shared::fresnelDielectricSchlick(cosI, 1.0f, m.ior);
            if (k >= 0.0f) {
                child.direction = normalize(toDouble(shared::opticsRefract(d, nIn, eta, cosI, k)));
                child.weight = r.weight * ((1.0f - fEntry) * m.transmission);
                child.inside = true;
                child.cell = hit.voxel;
                stack.push(child);
            }
        }
    }
    return sum;
}

}  // namespace luxel::voxel
