// The real-time solvers' sun (solver_sun.h): shadow rays through transmissive voxels along the
// straight line, and the sun's disk behind delta lobes.
#include "solver_sun.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "gpu/shaders/shared/near_emitters.h"
#include "gpu/shaders/shared/optics.h"
#include "gpu/shaders/shared/path_bsdf.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/shading_physical.h"
#include "voxel/shadow_blockers.h"
#include "voxel/sun_disk.h"

namespace luxel::voxel {

// The share of the light that enters the medium of `m` through a face with outward normal
// `normal` along `direction`: its transmission lobe weight (0 for opaque materials).
float mediumEntryTransmission(const Material& m, Int3 normal, Vec3d direction,
                              const ShadeOptions& shading) {
    return pathBsdf(m, Rgb(1.0f), normal, direction, shading).transmission;
}

// 1 - F where a straight line leaves the medium through a face with outward normal `outward`:
// the Fresnel reflectance at the line's angle to the face, as if it came in from the air (for a
// slab this is the exit's reflectance after refraction, by symmetry).
float mediumExitTransmission(const Material& m, Vec3d direction, Int3 outward,
                             const ShadeOptions& shading) {
    const Vec3d n{double(outward.x), double(outward.y), double(outward.z)};
    const float cosI = float(std::clamp(dot(direction, n), 0.0, 1.0));
    return 1.0f - dielectricFresnel(cosI, m.ior, shading.fresnel);
}

Rgb mediumAbsorption(const Material& m, double distance) {
    const gpu::shared::vec3 a = gpu::shared::voxelTransmittance(
        {m.absorption.r, m.absorption.g, m.absorption.b}, float(distance));
    return Rgb(a.x, a.y, a.z);
}

namespace {

constexpr double kPi = 3.14159265358979323846;
// Below this the light that is left counts as none (and the walk stops).
constexpr float kDarkTransmittance = 1e-4f;

// Through the run of transmissive voxels entered at `hit` (the face the ray met; with `inside`,
// the ray starts in hit.voxel at hit.point and crosses no entry face); returns the transmittance
// and moves `origin` to where the line leaves into the air (0: blocked inside).
Rgb throughMedia(const VoxelWorld& world, const Hit& hit, Vec3d direction,
                 const ShadeOptions& shading, Vec3d& origin, int& media, bool inside = false) {
    Rgb t(1.0f);
    Int3 cell = hit.voxel, normal = hit.normal;
    Vec3d point = hit.point;
    for (;;) {
        const Voxel v = world.get(cell.x, cell.y, cell.z);
        const Material& m = shading.materials.forSlot(textureSlotOf(v));
        if (!inside) t = t * mediumEntryTransmission(m, normal, direction, shading);
        inside = false;
        if (!(t.maxComponent() > kDarkTransmittance) || ++media > kMaxSunRayMedia) return {};
        const MediumExit exit = walkMedium(world, cell, point, direction);
        t = t * mediumAbsorption(m, exit.distance);
        if (!exit.intoSolid) {
            origin = exit.point;
            return t * mediumExitTransmission(m, direction, exit.outward, shading);
        }
        // Another solid touches the medium: entered directly, with no interface to the air.
        cell = {exit.cell.x + exit.outward.x, exit.cell.y + exit.outward.y,
                exit.cell.z + exit.outward.z};
        normal = {-exit.outward.x, -exit.outward.y, -exit.outward.z};
        point = exit.point;
    }
}

}  // namespace

namespace {

// Whether `voxel` is one of the target's faces (its rectangle, on the target's plane).
bool targetHolds(const FaceTarget& target, Int3 voxel) {
    const int axis = target.normal.x != 0 ? 0 : (target.normal.y != 0 ? 1 : 2);
    return gpu::shared::emitterRectHolds({target.voxel.x, target.voxel.y, target.voxel.z}, axis,
                                         target.extent, {voxel.x, voxel.y, voxel.z});
}

// Along `ray` until it leaves the world (target null: the sky's share) or meets the face
// (target->voxel, target->normal) (that face's share; 0 if it leaves the world or meets another
// opaque face first).
Rgb lineTransmittance(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                      const ShadeOptions& shading, const FaceTarget* target) {
    const bool media = shading.lightPassesMedia();
    if (!media && !target) {
        const bool blocked = surfaceRayBlocked(world, textures, ray, kInfinity, shading.stepCap);
        return blocked ? Rgb{} : Rgb(1.0f);
    }
    Rgb t(1.0f);
    Vec3d origin = ray.origin;
    int passed = 0;
    for (;;) {
        const SurfaceHit s =
            castToSurface(world, textures, {origin, ray.direction}, shading.stepCap);
        if (!s.hit.hit) return target ? Rgb{} : t;  // the sky (or past the step cap)
        if (s.hit.normal == Int3{}) return {};      // started inside a solid voxel
        if (target && s.hit.normal == target->normal && targetHolds(*target, s.hit.voxel)) return t;
        if (!media) return {};
        // Starting on the face of an opaque voxel under glass or water, the ray is inside the
        // medium at once: no interface with the air to enter through.
        const Int3 behind{s.hit.voxel.x + s.hit.normal.x, s.hit.voxel.y + s.hit.normal.y,
                          s.hit.voxel.z + s.hit.normal.z};
        const bool inside =
            passed == 0 && !(s.hit.t > 1e-9) && world.solid(behind.x, behind.y, behind.z);
        t = t * throughMedia(world, s.hit, ray.direction, shading, origin, passed, inside);
        if (!(t.maxComponent() > kDarkTransmittance)) return {};
    }
}

}  // namespace

Rgb sunRayTransmittance(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                        const ShadeOptions& shading) {
    return lineTransmittance(world, textures, ray, shading, nullptr);
}

Rgb faceRayTransmittance(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                         const ShadeOptions& shading, const FaceTarget& target) {
    return lineTransmittance(world, textures, ray, shading, &target);
}

namespace {

// The sun's disk and its spiral's directions for `rays` rays, kept per thread for the last sun
// asked for: they are the same at every pixel, and making them at each (a frame, a square root,
// a sine and a cosine per ray) was 6% of the radiance cascades' picture
// (docs/algorithms/voxel-radiance-cascades.md §5). The same values, so nothing changes.
struct SunSpiral {
    Vec3 direction{};
    double angularRadius = -1.0;
    int rays = 0;
    SunDisk sun;
    std::vector<Vec3d> directions;
};

// Compared bit for bit: -0 and 0 give the disk different tangents (copysign).
bool sameSun(const SunSpiral& c, const ShadeOptions& shading, int sunRays) {
    const Vec3 d = shading.sunDirection;
    return c.rays == sunRays &&
           std::bit_cast<std::uint64_t>(c.angularRadius) ==
               std::bit_cast<std::uint64_t>(shading.sunAngularRadius) &&
           std::bit_cast<std::uint32_t>(c.direction.x) == std::bit_cast<std::uint32_t>(d.x) &&
           std::bit_cast<std::uint32_t>(c.direction.y) == std::bit_cast<std::uint32_t>(d.y) &&
           std::bit_cast<std::uint32_t>(c.direction.z) == std::bit_cast<std::uint32_t>(d.z);
}

// Two kept: the camera's surface and the followed glass behind it ask for different counts.
const SunSpiral& sunSpiral(const ShadeOptions& shading, int sunRays) {
    thread_local SunSpiral cached[2];
    thread_local int next = 0;
    for (const SunSpiral& c : cached) {
        if (sameSun(c, shading, sunRays)) return c;
    }
    SunSpiral& c = cached[next];
    next ^= 1;
    c.direction = shading.sunDirection;
    c.angularRadius = shading.sunAngularRadius;
    c.rays = sunRays;
    c.sun = SunDisk::make(c.direction, shading.sunAngularRadius);
    // A delta sun: one shadow ray; a disk: the spiral's rays.
    const int rays = c.sun.delta() ? 1 : std::max(sunRays, 1);
    c.directions.resize(std::size_t(rays));
    for (int i = 0; i < rays; ++i) c.directions[std::size_t(i)] = c.sun.spiral(i, rays);
    return c;
}

// The GGX highlight of one of the sun's rays on a specular-only lobe: bsdfLight(specular, l,
// radiance, 0) (a delta light: S D Vis cos_l radiance) in float with the GPU's arithmetic
// (pathBsdfLight, path_surface.glsl), the lobe's values converted once for the surface's rays
// (docs/algorithms/voxel-radiance-cascades.md §5).
class SunHighlight {
  public:
    explicit SunHighlight(const PathBsdf& b)
        : on_(b.pSpecular > 0.0 && !b.mirror() && b.cosView > 0.0),
          n_{float(b.normal.x), float(b.normal.y), float(b.normal.z)},
          view_{float(b.view.x), float(b.view.y), float(b.view.z)},
          alpha_(b.alpha),
          cosView_(float(b.cosView)),
          specular_(b.specular) {}

    Rgb light(Vec3d l, Rgb radiance) const {
        const gpu::shared::vec3 lf(float(l.x), float(l.y), float(l.z));
        const float cosL = dot(n_, lf);
        if (!on_ || !(cosL > 0.0f)) return {};
        const float reflectance =
            gpu::shared::pathGgxReflectance(n_, view_, lf, cosView_, cosL, alpha_);
        return specular_ * radiance * (reflectance * cosL);
    }

  private:
    bool on_;
    gpu::shared::vec3 n_, view_;
    float alpha_, cosView_;
    Rgb specular_;
};

}  // namespace

bool sunRaysStopAtSolids(const TextureSet* textures, const ShadeOptions& shading) {
    return !shading.lightPassesMedia() && shadowBlockersHold(textures, shading.stepCap);
}

Rgb solverSunLobes(const VoxelWorld& world, const TextureSet* textures, const Hit& hit, Rgb diffuse,
                   const PathBsdf* specular, const ShadeOptions& shading, int sunRays,
                   const SunRayMap* map, bool shareMedia) {
    if (!(shading.sunIrradiance.maxComponent() > 0.0f)) return {};
    if (!(diffuse.maxComponent() > 0.0f) && !specular) return {};
    const SunSpiral& spiral = sunSpiral(shading, sunRays);
    const SunDisk& sun = spiral.sun;
    const Vec3d n{double(hit.normal.x), double(hit.normal.y), double(hit.normal.z)};
    // Each of the spiral's rays brings radiance / pdf.
    const int rays = int(spiral.directions.size());
    const Rgb perRay = sun.radianceOverPdf(shading.sunIrradiance) * float(1.0 / rays);
    Rgb cosines, glossy;  // the sum of cos x transmittance; the smooth lobes' light
    const SunHighlight highlight = specular ? SunHighlight(*specular) : SunHighlight(PathBsdf{});
    // Whether the disk's shadow rays may share blockers (ShadowBlockers) and take the map's
    // proofs of blocked rays.
    const bool shareBlockers = sunRaysStopAtSolids(textures, shading);
    // Whether the rays' start cells are empty, found when a map's proof of an open ray first
    // needs it (-1: not yet).
    int mapped = -1;
    ShadowBlockers blockers;
    // With shareMedia, the first ray's transmittance where it passed glass or water, which the
    // rays after it take without their walks (docs/algorithms/voxel-radiance-cascades.md §4.2,
    // "Sun rays through glass"; negative: none).
    Rgb throughMedia(-1.0f);
    for (int i = 0; i < rays; ++i) {
        const Vec3d& l = spiral.directions[std::size_t(i)];
        const double cosSun = dot(n, l);
        // Rays start on the face; castRay's start-cell rule puts them in the cell in front.
        if (!(cosSun > 0.0)) continue;
        const Ray ray{hit.point, l};
        Rgb t(1.0f);
        const bool shared = throughMedia.r >= 0.0f;
        const SunRayProof proof =
            map && !shared ? map->prove(world, hit, l, mapped) : SunRayProof::None;
        if (shared) {
            t = throughMedia;
        } else if (proof == SunRayProof::Open) {
            // Proven to reach the sky: transmittance 1, as the walk finds it.
        } else if (shareBlockers) {
            // The same answer as sunRayTransmittance's walk, which the map or an earlier ray's
            // blocker often gives without one.
            if (proof == SunRayProof::Blocked) continue;
            if (blockers.blocked(world, textures, ray, shading.stepCap)) continue;
        } else {
            t = sunRayTransmittance(world, textures, ray, shading);
            // Strictly between none and all: the line passed a medium (its Fresnel factors).
            if (shareMedia && i == 0 && t.maxComponent() > 0.0f && t.maxComponent() < 1.0f) {
                throughMedia = t;
            }
            if (!(t.maxComponent() > 0.0f)) continue;
        }
        cosines += t * float(cosSun);
        // Each ray of the disk is a delta light of its share (lightPdf 0: no MIS weight).
        if (specular) glossy += highlight.light(l, perRay) * t;
    }
    return diffuse * perRay * cosines * float(1.0 / kPi) + glossy;
}

Rgb sunDiskAlong(Vec3d direction, const ShadeOptions& shading) {
    const SunDisk sun = SunDisk::make(shading.sunDirection, shading.sunAngularRadius);
    return sun.contains(direction) ? sun.radiance(shading.sunIrradiance) : Rgb{};
}

}  // namespace luxel::voxel
