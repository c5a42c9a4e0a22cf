// Radiance cascades in voxel worlds: real-time global illumination from world-space probe
// cascades, measured against the path tracer (docs/algorithms/voxel-radiance-cascades.md).
//
// The open voxel faces are the finest probes (one irradiance value each, interpolated across
// neighbouring faces at a pixel); above them, world-space levels of probes double their spacing
// and their direction bins per side from level to level. Every probe direction is a chain of
// segments that ends exactly where the next level's segment starts (one segment towards each of
// the eight upper probes around it, weighted trilinearly), so light reaches a probe only along
// an unbroken path: no light crosses a 1-voxel wall. The world is static between create() calls,
// so each segment's first hit is found once; a lighting pass then only reads the faces'
// outgoing radiance through those hits. Faces reflect diffusely (the path tracer's surface
// model); each pass feeds the faces' irradiance back as one more reflection.
//
// Direct sun light is computed per pixel with a shadow ray (as the path tracer's first
// reflection); the cascades carry everything else: sky light, emissive voxels and the light
// surfaces reflect.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

namespace cascades {
struct GlossyRay;
}

inline constexpr int kMaxCascadeBounces = 1024;
inline constexpr int kMaxCascadeSpacing = 64;

struct CascadeOptions {
    // Probe spacing of the first world level, voxels: a power of two in 1..kMaxCascadeSpacing;
    // 0 picks 2, or the smallest larger spacing whose cascades fit `memoryLimit`.
    int spacing = 0;
    // Reflections solved by solve(): 0 iterates until converged (at most kMaxCascadeBounces).
    int bounces = 0;
    // solve() stops when a pass changes the faces' total irradiance by less than this fraction.
    double tolerance = 1e-4;
    // Bytes the cascades may take; 0: 2 GiB or the memory the machine has, if less.
    std::uint64_t memoryLimit = 0;
    // The picture takes the light of emissive faces within a few voxels of each pixel exactly
    // at the pixel (docs/algorithms/voxel-radiance-cascades.md §4.1); false: between face centres
    // as for the rest of the light.
    bool nearEmitters = true;
    // The picture's glossy surfaces light-sample the lamps in their specular lobe and weigh
    // those samples against their GGX rays by multiple importance sampling (§4.2, "Far lamps in
    // the glossy lobe"); false: the GGX rays alone draw what the near term leaves.
    bool glossyEmitters = true;
};

// Options checked: spacing, bounces, tolerance finite and in range; the error names the field.
Status validateCascades(const CascadeOptions& options);

// What create() plans for a world, without building: the spacing it picks (or the one given),
// the levels, the probes, the open faces (counted as faces towards empty neighbours) and the
// bytes. `fits` is false when those bytes exceed the memory limit.
struct CascadeEstimate {
    int spacing = 0, levels = 0;
    std::int64_t probes = 0, faces = 0;
    std::uint64_t bytes = 0, limit = 0;
    bool fits = true;
};
CascadeEstimate estimateCascades(const VoxelWorld& world, const CascadeOptions& options = {});

struct CascadeStats {
    int faces = 0, levels = 0, spacing = 0;
    std::int64_t probes = 0, segments = 0;
    std::int64_t passages = 0;  // runs of segments through glass and water
    std::uint64_t bytes = 0;
    double buildSeconds = 0.0;
    int bounces = 0;  // lighting passes run so far
    // Why `spacing` is larger than estimateCascades picked (empty when it is not): an automatic
    // spacing doubled because the segments' runs through glass did not fit the memory limit.
    std::string spacingNote;
};

class RadianceCascades {
  public:
    // Finds the faces, plans the levels and casts every segment once (world, textures: kept, must
    // outlive it unchanged). Fails on an invalid light (validatePathTrace), an estimate over the
    // memory limit, or segments' runs through glass that pass it as they are cast (not estimated)
    // at a spacing given in `options`; an automatic spacing is doubled until they fit
    // (stats().spacingNote says so), and fails only past kMaxCascadeSpacing.
    static Result<RadianceCascades> create(const VoxelWorld& world, const TextureSet* textures,
                                           const ShadeOptions& shading,
                                           const CascadeOptions& options = {});
    RadianceCascades(RadianceCascades&&) noexcept;
    RadianceCascades& operator=(RadianceCascades&&) noexcept;
    ~RadianceCascades();

    // New light (sun, sky, materials), irradiance so far kept (a bounce a frame in the viewer).
    // Where it changes what passes glass (refraction, the glass's materials) the faces under
    // glass, the levels' spacing and the segments are built again as create() would build them
    // for this light. Fails on an invalid light, or as create() on runs through glass (the next
    // call builds again).
    Status setLight(const ShadeOptions& shading);
    // The picture's rays per pixel (render.samples, clamped to 1..kMaxSamplesPerPixel): a
    // picture setting, so the light is kept (the viewer's samples per pixel).
    void setPictureSamples(int samplesPerPixel);
    // The picture's adaptive samples and contrast (render.adaptive_samples, adaptive_contrast).
    void setPictureAdaptiveSamples(int adaptiveSamples, double adaptiveContrast);
    // One lighting pass: faces' outgoing radiance from the current irradiance, the levels merged
    // top down, each face's irradiance gathered. Returns the relative change of the summed face
    // irradiance (1 after the first pass from black).
    double iterate();
    // Passes until options.bounces are done or a pass changes less than options.tolerance.
    // Returns the passes run.
    int solve();

    // Irradiance from everything but the direct sun at a point on a face (voxel, axis normal),
    // interpolated between the face and its coplanar neighbours.
    Rgb indirectIrradiance(Int3 voxel, Int3 normal, Vec3d point) const;
    // The picture: render.samples primary rays per pixel (shading.samplesPerPixel at
    // shared/pixel_samples.h's positions; one: the pixel centre; cutouts honoured), shaded with the
    // material model (docs/algorithms/voxel-radiance-cascades.md §4.2): emission, the diffuse
    // lobe x (direct sun + indirectIrradiance / pi), the specular lobe's sun highlight and its
    // split-sum reflection of what a few GGX rays meet; rows in parallel. Then the pixels of
    // strong contrast drawn again with shading.adaptiveSamples rays (src/voxel/cascades/
    // adaptive_samples.h); `refinedPixels` receives how many.
    Result<Image> render(const Camera& camera, int* refinedPixels = nullptr) const;

    CascadeStats stats() const;

    struct State;  // defined by the implementation (src/voxel/cascades/cascade_state.h)

  private:
    friend class RadianceCascadesGpu;
    explicit RadianceCascades(std::unique_ptr<State> state);
    // The radiance arriving along a ray leaving a face: the sky (and the sun's disk when every
    // lobe since the camera's surface was a delta lobe), glass or polished metal shaded with its
    // material and followed while `depth` < kSolverFollowDepth (src/voxel/solver_surface.h), or the
    // face met shaded Lambertian with its sun and indirectIrradiance. `rng` draws the followed
    // faces' GGX directions. `glossy`: the ray is a GGX direction of the camera's surface, so an
    // emitter of its near list counts 1 - its near weight of its emission (the rest is the
    // surface's light-sampled highlight), and a lamp its light samples could pick is handed
    // back in glossy->lamp instead, for multiple importance sampling (cascade_picture.cpp).
    Rgb reflectedLight(const Ray& r, bool delta, int depth, PathRng& rng,
                       cascades::GlossyRay* glossy = nullptr) const;
    // The picture's radiance along one camera ray; `primary`, when given, is castRay's hit of
    // it made already (castCameraRays, cascade_picture.cpp).
    Rgb pixelRadiance(const Ray& ray, PathRng& rng, const Hit* primary = nullptr) const;
    std::unique_ptr<State> state_;
};

struct CascadeImage {
    Image radiance;
    CascadeStats stats;
    double lightSeconds = 0.0, renderSeconds = 0.0;
    int refinedPixels = 0;  // the picture's pixels drawn again with the adaptive samples
};

// create(), solve() and render() in one call.
Result<CascadeImage> renderRadianceCascades(const VoxelWorld& world, const Camera& camera,
                                            const ShadeOptions& shading,
                                            const CascadeOptions& options = {},
                                            const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
