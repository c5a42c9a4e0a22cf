// The voxel radiance cascades' picture (radiance_cascades.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2): render.samples primary rays per pixel, the
// pixel centre by default (cutouts honoured), then the pixels of strong contrast again with
// render.adaptive_samples rays (adaptive_samples.h), the sun by sky visibility's shadow rays over
// its disk, the faces' irradiance interpolated; cascade_picture_gpu.cpp draws the same on the GPU.
// (Casting rows several rays at a time, castRayBatch and occludedBatch, measured no faster here:
// 45-47 ms against 40-46 ms of CPU at 640x360; castCameraRays' frustum walk from outside the
// world, and from inside over open space, does pay, docs/performance.md "The glass frame at the
// goal's edge" and "Camera rays cast together from inside".)
#include "cascade_picture.h"

#include <algorithm>

#include "../path_trace_surface.h"
#include "../solver_sun.h"
#include "../solver_surface.h"
#include "adaptive_samples.h"
#include "cascade_near_rays.h"
#include "cascade_state.h"
#include "glossy_emitters.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel {

namespace {
constexpr float kInvPi = float(1.0 / 3.14159265358979323846);
}  // namespace

using cascades::kPictureCameraAirExits;
using cascades::kPictureFollowedAirExits;
using cascades::kPictureSpecularRays;
using cascades::kPictureSunRays;
using cascades::kReflectionSeed;

Rgb RadianceCascades::reflectedLight(const Ray& r, bool delta, int depth, PathRng& rng,
                                     cascades::GlossyRay* glossy) const {
    const VoxelWorld& world = *state_->world;
    const ShadeOptions& shading = state_->shading;
    const SurfaceHit s = castToSurface(world, state_->textures, r, shading.stepCap);
    if (!s.hit.hit) {
        return skyColor(r.direction, shading) +
               (delta ? sunDiskAlong(r.direction, shading) : Rgb{});
    }
    if (s.hit.normal == Int3{}) return {};
    // The hit voxel read once, for its material and its surface below (and early: its line is
    // seldom in cache yet, and the face lookups can wait beside it).
    const Voxel voxel = world.get(s.hit.voxel.x, s.hit.voxel.y, s.hit.voxel.z);
    // indirectIrradiance, keeping the face's id for its sun below.
    int face = -1;
    const Rgb irradiance =
        cascades::interpolatedIrradiance(state_->faces, state_->faces.emitterIrradiance,
                                         s.hit.voxel, s.hit.normal, s.hit.point, &face);
    if (depth < kSolverFollowDepth &&
        solverFollows(shading.materials.forSlot(textureSlotOf(voxel)), shading)) {
        // Glass or polished metal: shaded with its material, what lies behind it or what it
        // reflects followed as for the camera's ray; of the light reflected inside glass, what
        // leaves at its first exit into the air (§4.2).
        SolverLight behind{
            irradiance * kInvPi,
            [&](const Ray& q, bool d) { return reflectedLight(q, d && delta, depth + 1, rng); }, 1,
            1, &state_->sunRayMap};
        behind.mediumAirExits = kPictureFollowedAirExits;
        return shadeSolverSurface(world, state_->textures, s, r, shading, behind, rng);
    }
    // The face met, Lambertian: its emission, the sun its face's rays found when the cascades
    // were lit (no shadow rays per pixel: a reflection is blurred by its lobe anyway) and the
    // cascades' irradiance.
    const PathSurface surface = pathSurfaceAt(voxel, s, shading);
    // The face was found by this normal: its record need not be read for it.
    const Rgb sun = face >= 0 ? cascades::faceDirectSun(*state_, face, s.hit.normal) : Rgb{};
    Rgb emission = surface.emission;
    if (glossy && emission.maxComponent() > 0.0f) {
        emission =
            emission * (1.0f - cascades::nearEmitterShare(*state_, *glossy->at, glossy->atFace,
                                                          s.hit.voxel, s.hit.normal));
        // A lamp the surface's light samples could have found: handed back for the balance
        // heuristic, out of the split sum.
        const double density =
            glossy->lamps ? glossy->lamps->density(s.hit.voxel, s.hit.normal, s.hit.point) : 0.0;
        if (density > 0.0) {
            glossy->met = {emission, density};
            emission = Rgb{};
        }
    }
    return emission + surface.albedo * (sun + irradiance) * kInvPi;
}

void RadianceCascades::setPictureSamples(int samplesPerPixel) {
    state_->shading.samplesPerPixel = std::clamp(samplesPerPixel, 1, kMaxSamplesPerPixel);
}

void RadianceCascades::setPictureAdaptiveSamples(int adaptiveSamples, double adaptiveContrast) {
    state_->shading.adaptiveSamples = std::clamp(adaptiveSamples, 0, kMaxSamplesPerPixel);
    state_->shading.adaptiveContrast = adaptiveContrast;
}

Rgb RadianceCascades::pixelRadiance(const Ray& ray, PathRng& rng, const Hit* primary) const {
    const VoxelWorld& world = *state_->world;
    const ShadeOptions& shading = state_->shading;
    const SurfaceHit s =
        castToSurface(world, state_->textures, ray, shading.stepCap, kInfinity, primary);
    if (!s.hit.hit) return skyColor(ray.direction, shading);
    if (s.hit.normal == Int3{}) return {};  // the camera is inside a solid voxel
    // The emitters near the pixel taken exactly at it, the rest of their light (emitterFar)
    // interpolated with the faces' irradiance; their visibility lines cast once for this light
    // and the highlight below (§5).
    const cascades::FaceData& faces = state_->faces;
    int face = -1;
    const Rgb far = cascades::interpolatedIrradiance(faces, faces.emitterFar, s.hit.voxel,
                                                     s.hit.normal, s.hit.point, &face);
    cascades::NearEmitterRays nearRays(*state_, s.hit, face);
    const Rgb irradiance = far + cascades::nearEmitterLight(*state_, nearRays);
    // The near emitters' glossy highlight light-sampled, their GGX rays keeping the rest; the
    // lamps beyond, light-sampled and met by the GGX rays, weighed by the balance heuristic.
    cascades::GlossyLampChoice lamps(*state_, s.hit, face);
    struct Glossy {
        const RadianceCascades* cascades;
        PathRng* rng;
        // Where the surface's GGX rays start following glass and polished metal: a rough
        // surface's follow none, for what a rough lobe sees through glass or in a mirror is
        // blurred by it, and they take such a face as Lambertian (§4.2, "Rough lobes follow no
        // face").
        int depth;
        cascades::GlossyRay ray;  // each GGX ray's start: the surface, nothing met yet
    } glossy{this,
             &rng,
             solverRoughLobe(world, s, shading) ? kSolverFollowDepth : 0,
             {&s.hit, face, faces.glossy.empty() ? nullptr : &lamps, {}}};
    // The callbacks capture one or two pointers each, which std::function keeps without
    // allocating.
    SolverLight light{irradiance * kInvPi,
                      [&glossy](const Ray& r, bool delta) {
                          return glossy.cascades->reflectedLight(r, delta, delta ? 0 : glossy.depth,
                                                                 *glossy.rng);
                      },
                      kPictureSunRays, kPictureSpecularRays, &state_->sunRayMap};
    light.mediumAirExits = kPictureCameraAirExits;
    // The disk's rays share one walk through glass (§4.2, "Sun rays through glass").
    light.sunRaysShareMedia = true;
    // A polished metal's or glass's sharp GGX lobe takes one direction (§4.2, "Sharp lobes take
    // one ray"), and so does a very rough one ("Very rough lobes take one ray").
    light.sharpLobeOneRay = true;
    light.roughLobeOneRay = true;
    if (!faces.nearOffset.empty() || glossy.ray.lamps) {
        if (!faces.nearOffset.empty()) {
            light.nearHighlight = [this, &nearRays](const PathBsdf& specular) {
                return cascades::nearEmitterHighlight(*state_, nearRays, specular);
            };
        }
        light.glossyAlong = [&glossy](const Ray& r) {
            cascades::GlossyRay g = glossy.ray;
            const Rgb rest =
                glossy.cascades->reflectedLight(r, false, glossy.depth, *glossy.rng, &g);
            return GlossyAlong{rest, g.met.emission, g.met.lightDensity};
        };
    }
    if (glossy.ray.lamps) {
        light.glossyLamps = [&glossy](const PathBsdf& specular, int lobeRays, PathRng& r) {
            return glossy.ray.lamps->sample(specular, lobeRays, r);
        };
    }
    return shadeSolverSurface(world, state_->textures, s, ray, shading, light, rng);
}

Result<Image> RadianceCascades::render(const Camera& camera, int* refinedPixels) const {
    const int width = camera.width(), height = camera.height();
    if (std::int64_t(width) * height > kMaxPathPixels) {
        return Error("radiance cascades: image " + std::to_string(width) + "x" +
                     std::to_string(height) + " has more than " + std::to_string(kMaxPathPixels) +
                     " pixels");
    }
    const VoxelWorld& world = *state_->world;
    const ShadeOptions& shading = state_->shading;
    Image out(width, height, 3);
    // Pixel (x, y) from n stratified rays: one random stream per pixel, drawn on through its
    // samples (as on the GPU), from its start again when the pixel is drawn again.
    const auto draw = [&](int x, int y, int n) {
        PathRng rng(kReflectionSeed, std::uint64_t(y) * width + x, 0);
        Rgb sum;
        for (int k = 0; k < n; ++k) sum += pixelRadiance(pixelSampleRay(camera, x, y, k, n), rng);
        const Rgb radiance = n == 1 ? sum : sum * (1.0f / float(n));
        for (int c = 0; c < 3; ++c) out.at(x, y, c) = radiance[c];
    };
    const int samples = samplesPerPixel(shading);
    parallelForRange(height, 1, [&](int begin, int end) {
        if (samples > 1) {
            for (int y = begin; y < end; ++y)
                for (int x = 0; x < width; ++x) draw(x, y, samples);
            return;
        }
        // One ray per pixel centre: a row's camera rays cast together first, tiles of them
        // sharing one frustum walk to where their solids begin (castCameraRays,
        // docs/algorithms/voxel-traversal.md §4.6; castRay's hits, so the same picture), then
        // each pixel shaded with its hit. From inside the world it pays where the camera looks
        // over open space (the terrain, the garden) and costs thin-walls' closed room nothing
        // measurable (docs/performance.md, "Camera rays cast together from inside").
        std::vector<Ray> rays(std::size_t(width), Ray{});
        std::vector<Hit> hits(rays.size());
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x)
                rays[std::size_t(x)] = pixelSampleRay(camera, x, y, 0, 1);
            castCameraRays(world, rays, hits, kInfinity, shading.stepCap);
            for (int x = 0; x < width; ++x) {
                PathRng rng(kReflectionSeed, std::uint64_t(y) * width + x, 0);
                const Rgb radiance =
                    pixelRadiance(rays[std::size_t(x)], rng, &hits[std::size_t(x)]);
                for (int c = 0; c < 3; ++c) out.at(x, y, c) = radiance[c];
            }
        }
    });
    // The pixels of strong contrast again with more rays, their mean replacing the first value
    // (the first pass's centre ray is not one of the stratified positions; §4.2).
    const int refine = cascades::adaptiveSamples(shading);
    const std::vector<std::uint32_t> pixels =
        refine > 0 ? cascades::adaptivePixels(out, shading.adaptiveContrast)
                   : std::vector<std::uint32_t>{};
    parallelForRange(int(pixels.size()), 4, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            draw(int(pixels[i] % width), int(pixels[i] / width), refine);
    });
    if (refinedPixels) *refinedPixels = int(pixels.size());
    return out;
}

}  // namespace luxel::voxel
