// Voxel shading after the Unity voxel ray tracer (ChunkTracer4): face term, sky, reflections; plus
// shadows/texture.
#include "luxel/voxel/shading.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gpu/shaders/shared/sky_preetham.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/sky_model.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texel_footprint.h"
#include "voxel/shading_physical.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

shared::vec3 toVec3(Rgb c) {
    return {c.r, c.g, c.b};
}
Rgb toRgb(shared::vec3 v) {
    return {v.x, v.y, v.z};
}
shared::ivec3 toIvec3(Int3 v) {
    return {v.x, v.y, v.z};
}

Vec3d toDouble(Vec3 v) {
    return {v.x, v.y, v.z};
}
shared::vec3 toFloat(Vec3d v) {
    return {float(v.x), float(v.y), float(v.z)};
}

shared::SkyPerez perezOf(const std::array<float, 5>& p) {
    return {p[0], p[1], p[2], p[3], p[4]};
}

// The Preetham sky of the options, made again only when its turbidity, zenith or sun change (once
// per thread and scene, not per ray).
const shared::PreethamSky& preethamSkyOf(const ShadeOptions& o) {
    struct Made {
        float turbidity = -1.0f, zenith = -1.0f;
        Vec3 sun;
        shared::PreethamSky sky;
    };
    thread_local Made made;
    if (made.turbidity != o.skyTurbidity || made.zenith != o.skyZenithLuminance ||
        !(made.sun == o.sunDirection)) {
        const PreethamCoefficients c =
            preethamSky(o.skyTurbidity, o.sunDirection, o.skyZenithLuminance);
        made = {o.skyTurbidity, o.skyZenithLuminance, o.sunDirection,
                shared::PreethamSky(
                    perezOf(c.luminance), perezOf(c.x), perezOf(c.y),
                    shared::vec3(c.zenithOverF0[0], c.zenithOverF0[1], c.zenithOverF0[2]))};
    }
    return made.sky;
}
Vec3d toDouble(Int3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}

Rgb albedo(Voxel v) {
    return {srgbToLinear(v.r / 255.0f), srgbToLinear(v.g / 255.0f), srgbToLinear(v.b / 255.0f)};
}

// One ray: what it sees (sky or a shaded voxel) and, on a hit, the reflected ray.
struct Sample {
    Rgb colour;
    SurfaceHit surface;
    bool reflects = false;
    Ray next;
};

Sample sample(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
              const RayCone& cone, const ShadeOptions& options, const Hit* cast = nullptr) {
    Sample s;
    s.surface = castToSurface(world, textures, ray, options.stepCap, kInfinity, cast);
    // A capped ray (world larger than the cap allows) reads as sky rather than the Unity tracer's
    // yellow.
    if (!s.surface.hit.hit) {
        s.colour = skyColor(ray.direction, options);
        return s;
    }
    const Hit& hit = s.surface.hit;
    const Vec3d n = toDouble(hit.normal);
    const bool hasNormal = hit.normal != Int3{};
    Rgb colour = albedo(world.get(hit.voxel.x, hit.voxel.y, hit.voxel.z));
    if (s.surface.slot >= 0) {
        Texel t = s.surface.texel;  // the nearest texel decided the cutout
        if (options.textureFilter != TextureFilter::Nearest) {
            t = textures->sample(s.surface.slot, hit.u, hit.v,
                                 texelFootprint(cone, hit.t, ray.direction, hit.normal),
                                 options.textureFilter, options.maxAnisotropy);
        }
        colour = colour * Rgb(t.r, t.g, t.b);  // the texel tints the voxel colour
    } else if (options.textures) {
        colour = colour * textureFactor(hit, options);
    }
    // Secondary rays start exactly on the face (castRay snaps hit.point onto its plane): the
    // start-cell rule of castRay puts a ray leaving a face in the cell in front of it, and that
    // cell is entered through this face (no offset that would move it inside, changing its UVs).
    if (options.faceShading) {
        bool inShadow = false;
        const Vec3d sun = toDouble(options.sunDirection);
        if (options.shadows && hasNormal && dot(n, sun) > 0.0) {
            // Cutout texels let sunlight through: leaves cast dappled shadows.
            const Ray shadowRay{hit.point, normalize(sun)};
            inShadow = castToSurface(world, textures, shadowRay, options.stepCap).hit.hit;
        }
        colour = colour * faceFactor(hit.normal, options.sunDirection, options.ambient, inShadow);
    }
    s.colour = colour;
    if (hasNormal) {
        const Vec3d d = normalize(ray.direction);
        s.next = {hit.point, d - n * (2.0 * dot(d, n))};
        s.reflects = true;
    }
    return s;
}

// A texture's own reflectivity, else the callback's, else the default.
float reflectivityOf(const VoxelWorld& world, const TextureSet* textures, const SurfaceHit& s,
                     const ShadeOptions& options) {
    const Int3 v = s.hit.voxel;
    float r = options.reflectivity;
    if (s.slot >= 0 && (*textures)[s.slot].reflectivity) {
        r = *(*textures)[s.slot].reflectivity;
    } else if (options.materialReflectivity) {
        r = options.materialReflectivity(world.get(v.x, v.y, v.z));
    }
    return std::isfinite(r) ? std::clamp(r, 0.0f, 1.0f) : 0.0f;
}

}  // namespace

float faceFactor(Int3 normal, Vec3 sunDirection, float ambient, bool inShadow) {
    return shared::voxelFaceFactor(
        toIvec3(normal), {sunDirection.x, sunDirection.y, sunDirection.z}, ambient, inShadow);
}

Rgb skyColor(Vec3d direction, const ShadeOptions& options) {
    const double len = length(direction);
    if (options.skyModel == ShadeOptions::SkyModel::Preetham) {
        const Vec3 sun = options.sunDirection;
        const float sunLength = std::sqrt(sun.x * sun.x + sun.y * sun.y + sun.z * sun.z);
        const shared::vec3 w = len > 0.0 ? toFloat(direction * (1.0 / len)) : shared::vec3(0.0f);
        const shared::vec3 s = sunLength > 0.0f
                                   ? shared::vec3(sun.x, sun.y, sun.z) * (1.0f / sunLength)
                                   : shared::vec3(0.0f, 1.0f, 0.0f);
        return toRgb(shared::preethamSkyColor(preethamSkyOf(options), w, s));
    }
    const float s = len > 0.0 ? static_cast<float>(std::clamp(direction.y / len, 0.0, 1.0)) : 0.0f;
    return toRgb(shared::voxelSkyColor(toVec3(options.skyHorizon), toVec3(options.skyTop), s));
}

float textureFactor(const Hit& hit, const ShadeOptions& options) {
    return shared::voxelTextureFactor(toIvec3(hit.voxel), toIvec3(hit.normal), hit.u, hit.v,
                                      options.textureTexels, options.textureStrength);
}

Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const ShadeOptions& options,
             const TextureSet* textures) {
    return shadeRay(world, ray, RayCone{}, options, textures);
}

Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const RayCone& rayCone,
             const ShadeOptions& options, const TextureSet* textures) {
    return shadeRay(world, ray, rayCone, options, textures, RaySample{});
}

Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const RayCone& rayCone,
             const ShadeOptions& options, const TextureSet* textures, RaySample raySample) {
    if (options.lighting == ShadeOptions::Lighting::Physical) {
        return shadePhysical(world, ray, rayCone, options, textures, raySample);
    }
    RayCone cone = rayCone;
    const int bounces = std::max(options.maxReflections, 0);
    Ray current = ray;
    Rgb sum;
    if (options.reflectionMode == ShadeOptions::ReflectionMode::RunningAverage) {
        // The Unity tracer's loop: hit k (1-based) adds colour / k, then the sum is scaled by k /
        // (k + 1).
        for (int k = 1; k <= bounces + 1; ++k) {
            const Sample s = sample(world, textures, current, cone, options,
                                    k == 1 ? raySample.primary : nullptr);
            if (k == 1) {
                sum = s.colour;
            } else {
                sum = toRgb(shared::voxelRunningAverage(toVec3(sum), toVec3(s.colour), k));
            }
            if (!s.reflects) break;
            current = s.next;
            cone = cone.after(s.surface.hit.t);
        }
        return sum;
    }
    float weight = 1.0f;
    for (int k = 0; k <= bounces; ++k) {
        const Sample s =
            sample(world, textures, current, cone, options, k == 0 ? raySample.primary : nullptr);
        if (!s.reflects || k == bounces) {
            sum += s.colour * weight;
            break;
        }
        const float r = reflectivityOf(world, textures, s.surface, options);
        sum += s.colour * (weight * (1.0f - r));
        weight *= r;
        if (weight == 0.0f) break;
        current = s.next;
        cone = cone.after(s.surface.hit.t);
    }
    return sum;
}

}  // namespace luxel::voxel
