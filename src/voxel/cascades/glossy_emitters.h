// The lamps in the radiance cascades' camera surface's glossy lobe
// (docs/algorithms/voxel-radiance-cascades.md §4.2, "Far lamps in the glossy lobe"): a GGX ray
// that meets a small bright lamp far away shows its full radiance as a sparkle, so the surface
// also light-samples the lamps and weighs both strategies by the balance heuristic
// (shared/glossy_emitters.h). The lamps are the ray caster's rectangles (EmitterLights); each cell
// of its grid keeps LUXEL_GLOSSY_PICKS of them, and a point picks among its cell's. The GPU's twin:
// src/gpu/shaders/voxel/glossy_emitters.glsl (same float arithmetic).
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/shaders/shared/glossy_emitters.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/voxel_world.h"
#include "voxel/cascades/emitter_clear_box.h"

namespace luxel::voxel {
struct PathBsdf;
}

namespace luxel::voxel::cascades {

// The lamps and each grid cell's picks (the GPU's buffers 23 and 24). Empty: no lamp, or
// CascadeOptions::glossyEmitters off; the picture is then what the GGX rays alone draw.
struct GlossyLamps {
    Int3 cells;                                          // the grid's cells per axis
    std::vector<std::uint32_t> picks;                    // LUXEL_GLOSSY_PICKS per cell
    std::vector<gpu::shared::CascadeNearEmitter> lamps;  // the rectangles
    // Beside each lamp, the empty box in front of it that proves its light samples' rays from
    // the points inside it seen without a walk (emitter_clear_box.h; CPU only).
    std::vector<EmitterClearBox> clear;
    bool empty() const { return lamps.empty(); }
};

// The open emissive faces merged into rectangles (EmitterLights::build) and, for each cell of
// its grid, the LUXEL_GLOSSY_PICKS that light it most by an estimate taken at the cell (radiance
// x area / (distance^2 + area) from the rectangle's centre to the cell), strongest first, the
// ones that face away from the whole cell left out.
GlossyLamps buildGlossyLamps(const VoxelWorld& world, const MaterialTable& materials);

// What a GGX ray of the camera surface met that the light samples could also have found: the
// lamp's emission (times 1 - its near weight) and the density with which the light samples find
// that point; `lightDensity` 0 leaves it to the split sum as before.
struct GlossyLampHit {
    Rgb emission;
    double lightDensity = 0.0;
};

// One camera surface's choice among its cell's lamps: each by glossyPickWeight at the hit point,
// found when first asked for (only glossy surfaces ask).
class GlossyLampChoice {
  public:
    // `face`: the hit's face id in the face table (-1: none), for nearEmitterShare.
    GlossyLampChoice(const RadianceCascades::State& state, const Hit& hit, int face);

    // The density, in solid angle at the hit, with which the light samples find the point y on
    // face (voxel, normal); 0 when no pick holds it.
    double density(Int3 voxel, Int3 normal, Vec3d y);
    // LUXEL_GLOSSY_LIGHT_SAMPLES light samples through the specular-only lobe `specular` (with
    // its S), each weighted by the balance heuristic against `lobeRays` GGX rays; draws three
    // numbers per sample, none when the cell picks nothing here.
    Rgb sample(const PathBsdf& specular, int lobeRays, PathRng& rng);

  private:
    void choose();
    const RadianceCascades::State& state_;
    const Hit& hit_;
    int face_;
    gpu::shared::vec3 point_, normal_;
    bool chosen_ = false;
    int count_ = 0;
    std::uint32_t index_[LUXEL_GLOSSY_PICKS];
    float weight_[LUXEL_GLOSSY_PICKS];
    // Each pick's part in front of the point, as its weight was found with.
    gpu::shared::EmitterSpan span_[LUXEL_GLOSSY_PICKS];
    float total_ = 0.0f;
};

// A GGX direction of the camera's surface as RadianceCascades::reflectedLight follows it: the
// surface's hit (its near list), its choice of lamps (null: none) and what the ray met of them.
struct GlossyRay {
    const Hit* at = nullptr;
    int atFace = -1;  // the hit's face id (-1: none)
    GlossyLampChoice* lamps = nullptr;
    GlossyLampHit met;
};

}  // namespace luxel::voxel::cascades
