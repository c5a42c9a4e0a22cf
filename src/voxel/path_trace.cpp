// The path estimator of the voxel path tracer (path_trace.h;
// docs/algorithms/voxel-path-tracing.md): one path per call; at each surface the material's BSDF
// (path_trace_bsdf.h) is lit by next event estimation towards the sun's disk and the emissive
// voxels (multiple importance sampling) and sampled for the next direction; refracted rays walk
// the transmissive voxels with Beer-Lambert absorption; Russian roulette.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "gpu/shaders/shared/path_bsdf.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/sky_model.h"
#include "luxel/voxel/surface_cast.h"
#include "path_trace_surface.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/shading_physical.h"
#include "voxel/sun_disk.h"

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

// Beer-Lambert over a path inside a medium: the ray caster's kernel (voxel_shading.h).
Rgb mediumTransmittance(Rgb absorption, double distance) {
    const gpu::shared::vec3 t = gpu::shared::voxelTransmittance(
        {absorption.r, absorption.g, absorption.b}, float(distance));
    return {t.x, t.y, t.z};
}

// Through the transmissive voxels of `cell`'s medium to where the ray leaves them: the ray's
// origin moves to the exit and the throughput is dimmed by Beer-Lambert. Its material in `m`.
MediumExit crossMedium(const VoxelWorld& world, const ShadeOptions& o, Int3 cell, Ray& ray,
                       Rgb& throughput, const Material*& m) {
    m = &o.materials.forSlot(textureSlotOf(world.get(cell.x, cell.y, cell.z)));
    const MediumExit exit = walkMedium(world, cell, ray.origin, ray.direction);
    throughput = throughput * mediumTransmittance(m->absorption, exit.distance);
    ray.origin = exit.point;
    return exit;
}

// Where the ray meets the medium's face from inside: reflect back inside with the Fresnel
// reflectance (always under total internal reflection), else refract out; the choice carries
// the weight. Draws one number unless the reflection is total. Whether the ray stays inside.
bool turnAtExit(const MediumExit& exit, const Material& m, const ShadeOptions& o, Ray& ray,
                Int3& cell, PathRng& rng) {
    const ExitSplit split = splitAtExit(ray.direction, exit.outward, m.ior, o.fresnel);
    const bool reflect = split.total || rng.next() < split.reflectance;
    ray.direction = reflect ? split.reflected : split.refracted;
    cell = exit.cell;
    return reflect;
}

// Next event estimation towards the emissive voxels: one point on one facing face of one
// emitter, weighted against the bounce ray that could have found it (multiple importance
// sampling, power heuristic).
Rgb emitterLight(const VoxelWorld& world, const TextureSet* textures, const PathEmitters& emitters,
                 const Hit& hit, const PathBsdf& bsdf, const ShadeOptions& o, PathRng& rng) {
    const float u0 = rng.next(), u1 = rng.next(), u2 = rng.next(), u3 = rng.next();
    if (!bsdf.smooth()) return {};
    const PathEmitters::Sample s = emitters.sample(hit.point, u0, u1, u2, u3);
    if (!(s.pdf > 0.0)) return {};
    if (!(dot(toDouble(hit.normal), s.direction) > 0.0)) return {};
    // Visible when the shadow ray first meets the sampled face itself.
    const Hit seen = castToSurface(world, textures, {hit.point, s.direction}, o.stepCap).hit;
    if (!seen.hit || seen.voxel != s.voxel || seen.normal != s.normal) return {};
    const Voxel v = world.get(s.voxel.x, s.voxel.y, s.voxel.z);
    const Rgb emission = o.materials.forSlot(textureSlotOf(v)).emission;
    return bsdfLight(bsdf, s.direction, emission, s.pdf);
}

// Whether a ray leaving the world along unit d meets the sun: inside its disk, or for a delta
// sun along its axis to rounding (a ray that glass with parallel faces gave back its direction).
bool meetsSun(const SunDisk& sun, Vec3d d) {
    if (!sun.delta()) return sun.contains(d);
    const Vec3d chord = d - sun.axis;
    return 0.5 * dot(chord, chord) <= LUXEL_PATH_DELTA_SUN_CHORD;
}

// What of the sun's light reaches a surface along unit l. Plain (maxEvents < 0): 1 unless the
// shadow ray meets a solid. Through delta surfaces (maxEvents >= 0): the shadow ray meets glass
// and mirrors (surfaces without a smooth lobe) as a bounce ray would, with the same lobe choices
// and Beer-Lambert inside, at most maxEvents times, and brings its throughput if it leaves the
// world towards the sun; a surface with a smooth lobe stops it. Through a pane with parallel
// faces the ray leaves as it came, so sunlight through a window converges like direct light.
Rgb sunReaching(const VoxelWorld& world, const TextureSet* textures, Vec3d origin, Vec3d l,
                const SunDisk& sun, const ShadeOptions& o, int maxEvents, PathRng& rng) {
    if (maxEvents < 0) {
        return surfaceRayBlocked(world, textures, {origin, l}, kInfinity, o.stepCap) ? Rgb()
                                                                                     : Rgb(1.0f);
    }
    Ray ray{origin, l};
    Rgb throughput(1.0f);
    bool inside = false;  // the ray travels through the medium of `cell`
    Int3 cell;
    // The counts and checks of tracePath's loop, so both strategies reach the same paths.
    for (int events = 0;;) {
        if (inside) {
            const Material* m = nullptr;
            const MediumExit exit = crossMedium(world, o, cell, ray, throughput, m);
            if (exit.intoSolid) {
                inside = false;
                continue;
            }
            if (events == maxEvents) return {};
            inside = turnAtExit(exit, *m, o, ray, cell, rng);
            ++events;
            continue;
        }
        const SurfaceHit s = castToSurface(world, textures, ray, o.stepCap);
        if (!s.hit.hit) return meetsSun(sun, normalize(ray.direction)) ? throughput : Rgb();
        const Hit& hit = s.hit;
        if (hit.normal == Int3{} || events == maxEvents) return {};
        const PathSurface surface = pathSurfaceAt(world, s, o);
        const PathBsdf bsdf =
            pathBsdf(*surface.material, surface.albedo, hit.normal, normalize(ray.direction), o);
        if (bsdf.smooth()) return {};
        const BsdfSample next = sampleBsdf(bsdf, rng);
        if (next.lobe == BsdfSample::Lobe::None) return {};
        throughput = throughput * next.weight;
        if (!(throughput.maxComponent() > 0.0f)) return {};
        ray = {hit.point, next.direction};
        if (next.lobe == BsdfSample::Lobe::Transmission) {
            inside = true;
            cell = hit.voxel;
        }
        ++events;
    }
}

// Next event estimation towards the sun: its centre (a delta light) or a uniform direction in
// its disk, weighted against the bounce rays that can meet the disk; through at most maxEvents
// delta surfaces (sunReaching). Draws two numbers when the disk has a size.
Rgb sunLight(const VoxelWorld& world, const TextureSet* textures, const Hit& hit,
             const PathBsdf& bsdf, const SunDisk& sun, const ShadeOptions& o, int maxEvents,
             PathRng& rng) {
    Vec3d l = sun.axis;
    if (!sun.delta()) {
        const float u0 = rng.next(), u1 = rng.next();
        l = sun.sample(u0, u1);
    }
    if (!(o.sunIrradiance.maxComponent() > 0.0f) || !bsdf.smooth()) return {};
    // Rays start on the face; castRay's start-cell rule puts them in the cell in front.
    if (!(dot(toDouble(hit.normal), l) > 0.0)) return {};
    const Rgb reaching = sunReaching(world, textures, hit.point, l, sun, o, maxEvents, rng);
    if (!(reaching.maxComponent() > 0.0f)) return {};
    if (sun.delta()) return reaching * bsdfLight(bsdf, l, o.sunIrradiance, 0.0);
    return reaching * bsdfLight(bsdf, l, sun.radiance(o.sunIrradiance), sun.pdf());
}

// Whether Russian roulette ends the path at vertex k; else the throughput is divided by the
// survival probability. Draws one number once roulette has started.
bool rouletteEnds(int k, const PathTraceOptions& p, float u, Rgb& throughput) {
    if (k + 1 < p.rouletteAfter) return false;
    const float q = std::min(1.0f, throughput.maxComponent());
    if (u >= q) return true;
    throughput = throughput * (1.0f / q);
    return false;
}

}  // namespace

namespace {

// srgbToLinear(byte / 255) for every byte, computed once: a voxel's colour is three bytes, and a
// powf per channel at every surface was 4% of the radiance cascades' picture
// (docs/algorithms/voxel-radiance-cascades.md §5). The same values, so nothing changes. Made when
// the library loads rather than at the first call, so that a read is a load and not a call
// that checks a guard first (1% of the picture's instructions).
const std::array<float, 256> kLinearOfByte = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = srgbToLinear(float(i) / 255.0f);
    return t;
}();

float linearOfByte(std::uint8_t byte) {
    return kLinearOfByte[byte];
}

}  // namespace

PathSurface pathSurfaceAt(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& o) {
    const Hit& hit = s.hit;
    return pathSurfaceAt(world.get(hit.voxel.x, hit.voxel.y, hit.voxel.z), s, o);
}

PathSurface pathSurfaceAt(Voxel voxel, const SurfaceHit& s, const ShadeOptions& o) {
    const Hit& hit = s.hit;
    const int materialSlot = textureSlotOf(voxel);
    const Material& m = o.materials.forSlot(materialSlot);
    Rgb colour =
        Rgb(linearOfByte(voxel.r), linearOfByte(voxel.g), linearOfByte(voxel.b)) * m.albedo;
    if (s.slot >= 0) colour = colour * Rgb(s.texel.r, s.texel.g, s.texel.b);
    const bool procedural =
        o.textures && (s.slot < 0 ? !o.materials.hasSlot(materialSlot) || m.proceduralTexture
                                  : o.materials.hasSlot(s.slot) && m.proceduralTexture);
    if (procedural) colour = colour * textureFactor(hit, o);
    return {colour, m.emission, &m};
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
    if (o.skyModel == ShadeOptions::SkyModel::Preetham) {
        if (!(o.skyTurbidity >= kPreethamMinTurbidity && o.skyTurbidity <= kPreethamMaxTurbidity)) {
            return Error("sky turbidity must be in [2, 10], got " + text(o.skyTurbidity));
        }
        if (!(o.skyZenithLuminance >= 0.0f) || !std::isfinite(o.skyZenithLuminance)) {
            return Error("sky zenith luminance must be finite and non-negative, got " +
                         text(o.skyZenithLuminance));
        }
    }
    return Ok{};
}

Rgb tracePath(const VoxelWorld& world, const TextureSet* textures, const Ray& cameraRay,
              const ShadeOptions& o, const PathTraceOptions& p, PathRng& rng,
              const PathEmitters* emitters) {
    if (emitters && emitters->empty()) emitters = nullptr;
    const SunDisk sun = SunDisk::make(o.sunDirection, o.sunAngularRadius);
    Rgb radiance, throughput(1.0f);
    Ray ray = cameraRay;
    Vec3d bounceOrigin;      // where the last bounce ray started
    double bouncePdf = 0.0;  // its density in solid angle (0: the camera ray or a delta lobe)
    // Sun light sampling follows shadow rays through delta surfaces (sunReaching). Then a
    // bounce ray that meets the disk after only such surfaces is weighted against it by the
    // direction it left its last smooth vertex in: chainPdf its density (0: no such vertex, or
    // a surface with a smooth lobe since), chainDirection that direction (a smooth lobe's
    // directions all leave above the face, as sun light sampling's do).
    const bool sunChains = p.sunThroughGlass && o.lightPassesMedia();
    double chainPdf = 0.0;
    Vec3d chainDirection;
    bool inside = false;  // the ray travels through the medium of `cell`
    Int3 cell;
    // Vertex k of the path is reached after k reflections or refractions.
    for (int k = 0;;) {
        if (inside) {
            const Material* m = nullptr;
            const MediumExit exit = crossMedium(world, o, cell, ray, throughput, m);
            if (exit.intoSolid) {  // another solid behind the glass: seen directly, as in the ray
                inside = false;    // caster (no interface, no vertex)
                continue;
            }
            if (k == p.maxBounces) break;
            const float uRoulette = k + 1 >= p.rouletteAfter ? rng.next() : 0.0f;
            inside = turnAtExit(exit, *m, o, ray, cell, rng);
            bouncePdf = 0.0;
            if (rouletteEnds(k, p, uRoulette, throughput)) break;
            ++k;
            continue;
        }
        const SurfaceHit s = castToSurface(world, textures, ray, o.stepCap);
        if (!s.hit.hit) {  // left the world (or ran past the step cap): the sky
            radiance += throughput * skyColor(ray.direction, o);
            // The sun's disk, where a reflected or refracted ray meets it (the camera sees the
            // sky without it, as in the ray caster).
            if (k > 0 && sun.contains(ray.direction)) {
                double weight = 1.0;
                if (bouncePdf > 0.0) {
                    weight = powerHeuristic(bouncePdf, sun.pdf());
                } else if (chainPdf > 0.0) {
                    const bool sampled = sun.contains(chainDirection);
                    weight = powerHeuristic(chainPdf, sampled ? sun.pdf() : 0.0);
                }
                radiance += throughput * sun.radiance(o.sunIrradiance) * float(weight);
            }
            break;
        }
        const Hit& hit = s.hit;
        if (hit.normal == Int3{}) break;  // started inside a solid voxel: no light
        const PathSurface surface = pathSurfaceAt(world, s, o);
        if (surface.emission.maxComponent() > 0.0f) {
            // Seen by a bounce ray that emitter sampling could also have found: MIS-weighted.
            double weight = 1.0;
            if (emitters && bouncePdf > 0.0) {
                const double lightPdf =
                    emitters->pdf(bounceOrigin, hit.voxel, hit.normal, hit.point);
                weight = powerHeuristic(bouncePdf, lightPdf);
            }
            radiance += throughput * surface.emission * float(weight);
        }
        if (k == p.maxBounces) break;
        const PathBsdf bsdf =
            pathBsdf(*surface.material, surface.albedo, hit.normal, normalize(ray.direction), o);
        // Next event estimation (the smooth lobes only; a delta lobe counts what its ray meets).
        radiance += throughput * sunLight(world, textures, hit, bsdf, sun, o,
                                          sunChains ? p.maxBounces - k - 1 : -1, rng);
        if (emitters) {
            radiance += throughput * emitterLight(world, textures, *emitters, hit, bsdf, o, rng);
        }
        const float uRoulette = k + 1 >= p.rouletteAfter ? rng.next() : 0.0f;
        const BsdfSample next = sampleBsdf(bsdf, rng);
        if (next.lobe == BsdfSample::Lobe::None) break;
        throughput = throughput * next.weight;
        if (!(throughput.maxComponent() > 0.0f)) break;
        if (rouletteEnds(k, p, uRoulette, throughput)) break;
        ray = {hit.point, next.direction};
        bounceOrigin = hit.point;
        bouncePdf = next.pdf;
        if (next.pdf > 0.0) {
            chainPdf = sunChains ? next.pdf : 0.0;
            chainDirection = next.direction;
        } else if (bsdf.smooth()) {
            chainPdf = 0.0;  // sun light sampling stops at this surface
        }
        if (next.lobe == BsdfSample::Lobe::Transmission) {
            inside = true;
            cell = hit.voxel;
        }
        ++k;
    }
    return radiance;
}

}  // namespace luxel::voxel
