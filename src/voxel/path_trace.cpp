// The path estimator of the voxel path tracer (path_trace.h;
// docs/algorithms/voxel-path-tracing.md): one path per call, Lambertian bounces, next event
// estimation towards the sun and the emissive voxels (with multiple importance sampling), Russian
// roulette.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "luxel/core/tonemap.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/surface_cast.h"
#include "path_trace_surface.h"

namespace luxel::voxel {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3d toDouble(Int3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}

std::string text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

Status finiteNonNegative(const char* field, Rgb c) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(c[i]) || c[i] < 0.0f) {
            return Error(std::string(field) + " must be finite and >= 0, got (" + text(c.r) + ", " +
                         text(c.g) + ", " + text(c.b) + ")");
        }
    }
    return Ok{};
}

// Power-heuristic weight of a strategy of density `mine` against one of density `other`.
double powerHeuristic(double mine, double other) {
    const double a = mine * mine, b = other * other;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

// Next event estimation towards the emissive voxels: one point on one facing face of one
// emitter, weighted against the bounce ray that could have found it (multiple importance
// sampling, power heuristic).
Rgb emitterLight(const VoxelWorld& world, const TextureSet* textures, const PathEmitters& emitters,
                 const Hit& hit, Rgb albedo, const ShadeOptions& o, PathRng& rng) {
    const float u0 = rng.next(), u1 = rng.next(), u2 = rng.next(), u3 = rng.next();
    const PathEmitters::Sample s = emitters.sample(hit.point, u0, u1, u2, u3);
    if (!(s.pdf > 0.0)) return {};
    const double cosSurface = dot(toDouble(hit.normal), s.direction);
    if (!(cosSurface > 0.0)) return {};
    // Visible when the shadow ray first meets the sampled face itself.
    const Hit seen = castToSurface(world, textures, {hit.point, s.direction}, o.stepCap).hit;
    if (!seen.hit || seen.voxel != s.voxel || seen.normal != s.normal) return {};
    const Voxel v = world.get(s.voxel.x, s.voxel.y, s.voxel.z);
    const Rgb emission = o.materials.forSlot(textureSlotOf(v)).emission;
    const double bouncePdf = cosSurface / kPi;
    const double weight = powerHeuristic(s.pdf, bouncePdf);
    return albedo * emission * float(cosSurface / kPi * weight / s.pdf);
}

}  // namespace

PathSurface pathSurfaceAt(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& o) {
    const Hit& hit = s.hit;
    const Voxel voxel = world.get(hit.voxel.x, hit.voxel.y, hit.voxel.z);
    const int materialSlot = textureSlotOf(voxel);
    const Material& m = o.materials.forSlot(materialSlot);
    Rgb colour = Rgb(srgbToLinear(voxel.r / 255.0f), srgbToLinear(voxel.g / 255.0f),
                     srgbToLinear(voxel.b / 255.0f)) *
                 m.albedo;
    if (s.slot >= 0) colour = colour * Rgb(s.texel.r, s.texel.g, s.texel.b);
    const bool procedural =
        o.textures && (s.slot < 0 ? !o.materials.hasSlot(materialSlot) || m.proceduralTexture
                                  : o.materials.hasSlot(s.slot) && m.proceduralTexture);
    if (procedural) colour = colour * textureFactor(hit, o);
    return {colour, m.emission};
}

bool surfaceRayBlocked(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                       double tMax, int stepCap) {
    // Cutout texels let light through, as they let camera rays through.
    if (textures && !textures->empty()) {
        const Hit hit = castToSurface(world, textures, ray, stepCap).hit;
        return hit.hit && hit.t <= tMax;
    }
    return occluded(world, ray, tMax, stepCap);
}

Rgb directSunLight(const VoxelWorld& world, const TextureSet* textures, const Hit& hit, Rgb albedo,
                   const ShadeOptions& o) {
    if (!(o.sunIrradiance.maxComponent() > 0.0f)) return {};
    const Vec3d sun = normalize(Vec3d{o.sunDirection.x, o.sunDirection.y, o.sunDirection.z});
    const double cosSun = dot(toDouble(hit.normal), sun);
    // Rays start on the face; castRay's start-cell rule puts them in the cell in front.
    if (!(cosSun > 0.0) ||
        surfaceRayBlocked(world, textures, {hit.point, sun}, kInfinity, o.stepCap)) {
        return {};
    }
    return albedo * o.sunIrradiance * float(cosSun / kPi);
}

Vec3d cosineDirection(Int3 normal, float u1, float u2) {
    const Vec3d n = toDouble(normal);
    Vec3d tu{0, 0, 1}, tv{0, 1, 0};
    if (normal.y != 0) {
        tu = {1, 0, 0}, tv = {0, 0, 1};
    } else if (normal.z != 0) {
        tu = {1, 0, 0}, tv = {0, 1, 0};
    }
    const double r = std::sqrt(double(u1)), phi = 2.0 * kPi * double(u2);
    // u1 < 1, so the normal component is > 0: the ray leaves the face.
    const double z = std::sqrt(1.0 - double(u1));
    return tu * (r * std::cos(phi)) + tv * (r * std::sin(phi)) + n * z;
}

Status validatePathTrace(const ShadeOptions& o, const PathTraceOptions& p) {
    if (p.samplesPerPixel < 1 || p.samplesPerPixel > kMaxPathSamples) {
        return Error("samples per pixel must be in 1.." + std::to_string(kMaxPathSamples) +
                     ", got " + std::to_string(p.samplesPerPixel));
    }
    if (p.maxBounces < 0 || p.maxBounces > kMaxPathBounces) {
        return Error("max bounces must be in 0.." + std::to_string(kMaxPathBounces) + ", got " +
                     std::to_string(p.maxBounces));
    }
    if (p.rouletteAfter < 0) {
        return Error("roulette start must be >= 0, got " + std::to_string(p.rouletteAfter));
    }
    const Vec3 sun = o.sunDirection;
    const bool finiteSun = std::isfinite(sun.x) && std::isfinite(sun.y) && std::isfinite(sun.z);
    if (!finiteSun || (sun.x == 0.0f && sun.y == 0.0f && sun.z == 0.0f)) {
        return Error("sun direction must be finite and non-zero, got (" + text(sun.x) + ", " +
                     text(sun.y) + ", " + text(sun.z) + ")");
    }
    for (Status s :
         {finiteNonNegative("sun irradiance", o.sunIrradiance),
          finiteNonNegative("sky top", o.skyTop), finiteNonNegative("sky horizon", o.skyHorizon)}) {
        if (!s) return s;
    }
    return Ok{};
}

Rgb tracePath(const VoxelWorld& world, const TextureSet* textures, const Ray& cameraRay,
              const ShadeOptions& o, const PathTraceOptions& p, PathRng& rng,
              const PathEmitters* emitters) {
    if (emitters && emitters->empty()) emitters = nullptr;
    Rgb radiance, throughput(1.0f);
    Ray ray = cameraRay;
    Vec3d bounceOrigin;      // where the last bounce ray started
    double bouncePdf = 0.0;  // its density in solid angle (0: the camera ray)
    // Vertex k of the path is reached after k reflections.
    for (int k = 0;; ++k) {
        const SurfaceHit s = castToSurface(world, textures, ray, o.stepCap);
        if (!s.hit.hit) {  // left the world (or ran past the step cap): the sky
            radiance += throughput * skyColor(ray.direction, o);
            break;
        }
        const Hit& hit = s.hit;
        if (hit.normal == Int3{}) break;  // started inside a solid voxel: no light
        const PathSurface surface = pathSurfaceAt(world, s, o);
        if (surface.emission.maxComponent() > 0.0f) {
            // Seen by a bounce ray that emitter sampling could also have found: MIS-weighted.
            double weight = 1.0;
            if (emitters && k > 0) {
                const double lightPdf =
                    emitters->pdf(bounceOrigin, hit.voxel, hit.normal, hit.point);
                weight = powerHeuristic(bouncePdf, lightPdf);
            }
            radiance += throughput * surface.emission * float(weight);
        }
        if (k == p.maxBounces) break;
        // Next event estimation: the sun is a delta light, reached only by this shadow ray.
        radiance += throughput * directSunLight(world, textures, hit, surface.albedo, o);
        if (emitters) {
            radiance +=
                throughput * emitterLight(world, textures, *emitters, hit, surface.albedo, o, rng);
        }
        // Lambertian bounce by cosine sampling: f cos / pdf = albedo.
        throughput = throughput * surface.albedo;
        if (!(throughput.maxComponent() > 0.0f)) break;
        if (k + 1 >= p.rouletteAfter) {
            const float q = std::min(1.0f, throughput.maxComponent());
            if (rng.next() >= q) break;
            throughput = throughput * (1.0f / q);
        }
        const float u1 = rng.next(), u2 = rng.next();
        ray = {hit.point, cosineDirection(hit.normal, u1, u2)};
        bounceOrigin = hit.point;
        bouncePdf = dot(toDouble(hit.normal), ray.direction) / kPi;
    }
    return radiance;
}

}  // namespace luxel::voxel
