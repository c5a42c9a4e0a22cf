// Shading for the voxel ray caster: the face shading of the Unity voxel ray tracer, hard sun
// shadows, a procedural face texture, a sky gradient and recursive mirror reflections (two
// weighting modes).
//
// Output is linear radiance (voxel RGBA8 colours are sRGB-encoded and decoded here); the caller
// tonemaps. Every pixel is computed independently, so images do not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>

#include "luxel/core/vec.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/ray_cone.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

class EmitterLights;

// Most sky ambient rays per shaded point (ShadeOptions::skyAmbientRays; LUXEL_SKY_AMBIENT_MAX_RAYS
// in shared/sky_ambient.h).
inline constexpr int kMaxSkyAmbientRays = 256;

struct ShadeOptions {
    // How reflected colours are combined.
    enum class ReflectionMode {
        // The Unity tracer's running sum: hit k contributes 1/k, then the sum is scaled by k/(k+1),
        // so the
        // weights of hits 1..n sum to 1 (n = 2: 2/3, 1/3; n = 3: 1/2, 1/4, 1/4).
        RunningAverage,
        // colour = (1 - r) * local + r * reflected, r = reflectivity of the hit voxel; the last
        // bounce (or a miss) contributes its full colour.
        EnergyConserving,
    };

    // Towards the sun. The face term uses it as given, like the Unity tracer's unnormalised (0, 1,
    // 0.5); shadow rays use its direction.
    Vec3 sunDirection{0.0f, 1.0f, 0.5f};
    Rgb skyTop{0.20f, 0.40f, 0.85f};      // linear, straight up
    Rgb skyHorizon{0.75f, 0.85f, 1.00f};  // linear, at and below the horizon
    // The sky's model (sky_model.h): the gradient of skyTop and skyHorizon, or the Preetham clear
    // sky around sunDirection, of turbidity skyTurbidity (2..10) and zenith luminance
    // skyZenithLuminance (the default: about the default skyTop's).
    enum class SkyModel { Gradient, Preetham };
    SkyModel skyModel = SkyModel::Gradient;
    float skyTurbidity = 3.0f;
    float skyZenithLuminance = 0.4f;
    int maxReflections = 2;  // 0: no reflection rays
    ReflectionMode reflectionMode = ReflectionMode::RunningAverage;
    float reflectivity = 0.3f;  // EnergyConserving, for every voxel unless overridden below
    // EnergyConserving: per-voxel reflectivity in [0, 1] (empty: `reflectivity` everywhere). A
    // texture's own reflectivity (texture_set.h) takes precedence. CPU only.
    std::function<float(const Voxel&)> materialReflectivity;
    bool faceShading = true;  // the Unity tracer's dot-product face term
    float ambient = 0.1f;     // the Unity tracer's +0.1 in that term
    bool shadows = true;      // hard shadows from a shadow ray towards the sun
    bool textures = true;     // procedural per-texel modulation of plain blocks (not PNG textures)
    int textureTexels = 8;    // texels per face side
    float textureStrength = 0.15f;  // darkest texel is (1 - strength) of the voxel colour
    int stepCap = 0;                // castRay step cap (0: its default)

    // How surfaces are lit (docs/algorithms/voxel-surfaces.md).
    enum class Lighting {
        Classic,   // the Unity tracer's face term above, hard shadows, mirror reflections
        Physical,  // materials, sun visibility by `shadowSettings`, specular, refraction
    };
    Lighting lighting = Lighting::Classic;
    Rgb sunIrradiance{3.0f, 2.9f, 2.7f};  // Physical: linear, on a face square to the sun
    enum class Specular { None, BlinnPhong, Ggx };
    Specular specular = Specular::Ggx;
    enum class FresnelModel { Schlick, Exact };
    FresnelModel fresnel = FresnelModel::Exact;
    bool refraction = true;  // transmissive materials refract (else they render opaque)
    // Sun visibility (Physical). render() builds it from these when `sunVisibility` is null.
    double sunAngularRadius = 0.0047;  // radians
    ShadowSettings shadowSettings;
    const SunVisibility* sunVisibility = nullptr;
    // Texture filtering from ray cones, normal maps and anti-aliasing.
    TextureFilter textureFilter = TextureFilter::Nearest;
    int maxAnisotropy = 16;
    bool normalMaps = true;
    int samplesPerPixel = 1;  // stratified within the pixel
    // The radiance cascades' picture draws the pixels whose luminance differs from a neighbour's
    // by more than adaptiveContrast x the image's mean luminance again with adaptiveSamples
    // stratified rays (0, or no more than samplesPerPixel: off; src/voxel/cascades/
    // adaptive_samples.h, docs/algorithms/voxel-radiance-cascades.md §4.2): a bright emitter's
    // silhouette, not the sunlit scenes' edges (contrast 12 measured best on thin-walls).
    int adaptiveSamples = 16;
    double adaptiveContrast = 12.0;
    // Physical: materials by texture slot (material.h; plain blocks use materials.plain()), and
    // the share of the sky a face is assumed to see for ambient light when no rays trace it.
    MaterialTable materials;
    float skyAmbient = 0.5f;
    // Physical: sky ambient with occlusion (docs/algorithms/voxel-surfaces.md, "Sky ambient with
    // occlusion"). 0: the constant share skyAmbient above, walls or no walls. 1..
    // kMaxSkyAmbientRays: each shaded point casts that many cosine-distributed rays; the ambient
    // irradiance is π x the mean of the sky along the rays that reach it (0 for the others), the
    // rough reflection's sky is weighted by the share that reaches it, and skyAmbient is unused.
    int skyAmbientRays = 0;
    // Physical: light from emissive voxels onto other surfaces (emitter_light.h), with
    // `emitterRays` shadow rays per face (1..kMaxEmitterRays). render() builds the faces'
    // lists when `emitterLights` is null; shadeRay without them draws no such light.
    bool emitterLight = true;
    int emitterRays = 4;
    const EmitterLights* emitterLights = nullptr;

    // Whether light passes some voxel's medium (glass, water): refraction on and a material
    // that transmits; else every solid voxel stops a ray.
    bool lightPassesMedia() const { return refraction && materials.anyTransmission(); }
};

// The Unity tracer's face factor min((dot(n, L) + 1) / 2 + ambient, 1); in shadow dot(n, L) is
// clamped to at most 0 (the direct part is removed). A zero normal reads as dot 0.
float faceFactor(Int3 normal, Vec3 sunDirection, float ambient, bool inShadow);

// The sky seen along a direction: for the gradient, the horizon colour blended to the top colour by
// the direction's elevation (sine), the horizon colour below the horizon; for the Preetham sky,
// its radiance there (shared/sky_preetham.h).
Rgb skyColor(Vec3d direction, const ShadeOptions& options);

// Deterministic texel brightness in [1 - strength, 1] for a hit on a voxel face.
float textureFactor(const Hit& hit, const ShadeOptions& options);

// The camera sample a ray stands for: its pixel (y * width + x) and sample index key the random
// numbers of its sky ambient rays (ShadeOptions::skyAmbientRays), as the GPU renderer keys them.
// `primary`, when given, is the ray's first cast made already (castRay's hit but for `steps`, from
// castCameraRays, docs/algorithms/voxel-traversal.md §4.6), for the ray as the lighting model
// casts it: as given for the Unity model, with its direction normalised for the physical one.
struct RaySample {
    std::uint32_t pixel = 0;
    std::uint32_t sample = 0;
    const Hit* primary = nullptr;
};

// Radiance along a ray (primary or not), with reflections per the options. `textures` gives the
// face textures that voxel alpha 1..254 selects (texture_set.h); without it every solid voxel is
// a plain block. Sky ambient rays draw the numbers of RaySample{} (pixel 0, sample 0).
Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const ShadeOptions& options,
             const TextureSet* textures = nullptr);

// The same, for a ray carrying a cone (texture filtering and the MRMA blend of secondary rays).
Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const RayCone& cone,
             const ShadeOptions& options, const TextureSet* textures = nullptr);

// The same for camera sample `sample`, whose numbers its sky ambient rays draw.
Rgb shadeRay(const VoxelWorld& world, const Ray& ray, const RayCone& cone,
             const ShadeOptions& options, const TextureSet* textures, RaySample sample);

// Pixel and image rendering (anti-aliasing, primary ray cones): render_image.h.

}  // namespace luxel::voxel
