// The material model at a real-time solver's visible surface (solver_surface.h). Every lobe
// weight, the GGX reflectance and the GGX sampling are the path tracer's (path_trace_bsdf.h).
#include "solver_surface.h"

#include <algorithm>
#include <cmath>

#include "gpu/shaders/shared/glossy_emitters.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "path_trace_surface.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/shading_physical.h"
#include "voxel/solver_sun.h"

namespace luxel::voxel {
namespace {

Vec3d toDouble(Int3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}

// What the transmission lobe shows: the camera ray refracted into the medium of the hit voxel
// and followed as the path tracer follows it (walkMedium, Beer-Lambert, the Fresnel split at each
// exit), every exit's refracted part bringing the solver's light along its direction; the part
// reflected inside goes on, up to kMaxMediumExits interfaces and light.mediumAirExits exits into
// the air.
Rgb transmitted(const VoxelWorld& world, const SurfaceHit& s, const PathBsdf& b,
                const ShadeOptions& shading, const SolverLight& light, PathRng& rng) {
    PathBsdf entering = b;
    entering.pSpecular = entering.pDiffuse = 0.0;
    entering.pTransmission = 1.0;
    const BsdfSample in = sampleBsdf(entering, rng);  // a delta lobe: draws no numbers
    Rgb weight(b.transmission), out;
    Ray ray{s.hit.point, in.direction};
    Int3 cell = s.hit.voxel;
    int airExits = 0;
    for (int exits = 0; exits < kMaxMediumExits && weight.maxComponent() > 1e-4f; ++exits) {
        const Voxel v = world.get(cell.x, cell.y, cell.z);
        const Material& m = shading.materials.forSlot(textureSlotOf(v));
        const MediumExit exit = walkMedium(world, cell, ray.origin, ray.direction);
        const gpu::shared::vec3 t = gpu::shared::voxelTransmittance(
            {m.absorption.r, m.absorption.g, m.absorption.b}, float(exit.distance));
        weight = weight * Rgb(t.x, t.y, t.z);
        // Another solid behind the medium: seen directly, as the path tracer sees it.
        if (exit.intoSolid) {
            return out + weight * light.radianceAlong({exit.point, ray.direction}, true);
        }
        const ExitSplit split = splitAtExit(ray.direction, exit.outward, m.ior, shading.fresnel);
        if (!split.total) {
            out += weight * (1.0f - split.reflectance) *
                   light.radianceAlong({exit.point, split.refracted}, true);
            weight = weight * split.reflectance;
            if (++airExits >= light.mediumAirExits) return out;
        }
        ray = {exit.point, split.reflected};
        cell = exit.cell;
    }
    return out;
}

}  // namespace

bool solverFollows(const Material& m, const ShadeOptions& shading) {
    const bool passes = shading.refraction && m.transmission > 0.0f && m.metallic < 1.0f;
    return passes || (m.metallic > 0.0f && m.roughness <= kSolverFollowRoughness);
}

bool solverFollows(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& shading) {
    const Voxel v = world.get(s.hit.voxel.x, s.hit.voxel.y, s.hit.voxel.z);
    return solverFollows(shading.materials.forSlot(textureSlotOf(v)), shading);
}

bool solverRoughLobe(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& shading) {
    const Voxel v = world.get(s.hit.voxel.x, s.hit.voxel.y, s.hit.voxel.z);
    return shading.materials.forSlot(textureSlotOf(v)).roughness > kSolverFollowRoughness;
}

bool solverFollowsAny(const ShadeOptions& shading) {
    const MaterialTable& table = shading.materials;
    if (solverFollows(table.plain(), shading)) return true;
    for (int slot = 0; slot < table.slotCount(); ++slot) {
        if (table.hasSlot(slot) && solverFollows(table.forSlot(slot), shading)) return true;
    }
    return false;
}

Rgb shadeSolverSurface(const VoxelWorld& world, const TextureSet* textures, const SurfaceHit& s,
                       const Ray& ray, const ShadeOptions& shading, const SolverLight& light,
                       PathRng& rng) {
    const PathSurface surface = pathSurfaceAt(world, s, shading);
    const Vec3d direction = normalize(ray.direction);
    const PathBsdf b =
        pathBsdf(*surface.material, surface.albedo, s.hit.normal, direction, shading);
    const bool glossy = b.pSpecular > 0.0 && b.cosView > 0.0;
    // The specular lobe alone, for the sun's highlight (the diffuse lobe is lit apart).
    PathBsdf specular = specularLobe(b);
    Rgb out = surface.emission +
              solverSunLobes(world, textures, s.hit, b.diffuse,
                             glossy && !b.mirror() ? &specular : nullptr, shading, light.sunRays,
                             light.sunRayMap, light.sunRaysShareMedia) +
              b.diffuse * light.diffuseRadiance;
    if (b.transmission > 0.0f && b.cosView > 0.0) {
        out += transmitted(world, s, b, shading, light, rng);
    }
    if (!glossy) return out;
    const Vec3d n = toDouble(s.hit.normal);
    if (b.mirror()) {
        const Vec3d r = direction - n * (2.0 * dot(n, direction));
        return out + b.specular * light.radianceAlong({s.hit.point, r}, true);
    }
    if (light.nearHighlight) out += light.nearHighlight(specular);
    const PathBsdf lobe = specular;  // with its S, for the lamps' light samples
    // Split sum: S A(cos_v, alpha) times the weighted mean radiance of GGX-sampled directions.
    specular.specular = Rgb(1.0f);
    specular.pSpecular = 1.0;
    Rgb weighted, lamps;
    double weights = 0.0;
    const GgxSampler ggx(specular);
    const int rays = (light.sharpLobeOneRay && b.alpha <= kSolverSharpAlpha) ||
                             (light.roughLobeOneRay && b.alpha >= kSolverRoughAlpha)
                         ? std::min(light.specularRays, 1)
                         : light.specularRays;
    // A sharp lobe's light samples of the lamps would almost all fall outside it and count
    // nothing: its GGX direction finds a lamp alone, weighed against no light sample.
    const bool lampSamples = light.glossyLamps && !(b.alpha <= kSolverSharpAlpha);
    const float lightSamples = lampSamples ? float(LUXEL_GLOSSY_LIGHT_SAMPLES) : 0.0f;
    for (int k = 0; k < rays; ++k) {
        const BsdfSample sample = ggx.sample(rng);
        if (sample.lobe != BsdfSample::Lobe::Specular) continue;
        const double w = sample.weight.r;
        const Ray r{s.hit.point, sample.direction};
        if (!light.glossyAlong) {
            weighted += light.radianceAlong(r, false) * float(w);
        } else {
            const GlossyAlong g = light.glossyAlong(r);
            weighted += g.rest * float(w);
            if (g.lightDensity > 0.0) {
                // A lamp the light samples could have found: f cos L / (n_l p_l + n_b p_b), the
                // weight w being f cos / (S p_b) (§4.2, "Far lamps in the glossy lobe").
                const float lobePdf = float(ggxDensity(specular, sample.direction));
                lamps += g.lamp * float(w) *
                         (lobePdf * gpu::shared::glossyBalance(float(g.lightDensity), lobePdf,
                                                               lightSamples, float(rays)));
            }
        }
        weights += w;
    }
    if (lampSamples) out += light.glossyLamps(lobe, rays, rng);
    out += b.specular * lamps;
    // One direction of a rough lobe: the split sum's mean of one direction, S A L, leans towards
    // what GGX sampling favours, as w = G2 / G1 is smaller at grazing angles. It is counted
    // unbiased, S (A C + w (L - C)): the mean of w is A, so any constant C keeps the mean at the
    // lobe's light, and C = E / pi, the light the diffuse lobe sees, takes most of L's
    // variation with it (a control variate; §4.2, "Very rough lobes take one ray").
    if (rays == 1 && b.alpha >= kSolverRoughAlpha) {
        const Rgb& c = light.diffuseRadiance;
        const float albedo = float(directionalAlbedoGgx(b.cosView, b.alpha));
        return out + b.specular * (c * albedo + weighted - c * float(weights));
    }
    if (!(weights > 0.0)) return out;
    const double albedo = directionalAlbedoGgx(b.cosView, b.alpha);
    return out + b.specular * weighted * float(albedo / weights);
}

}  // namespace luxel::voxel
