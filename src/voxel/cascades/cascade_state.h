// What the voxel radiance cascades keep between lighting passes (radiance_cascades.h): the
// faces, the levels, every segment's first hit as a code, and the radiance of the last pass.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "../../gpu/shaders/shared/near_emitters.h"
#include "../sun_ray_map.h"
#include "cascade_layout.h"
#include "emitter_clear_box.h"
#include "glossy_emitters.h"
#include "luxel/voxel/radiance_cascades.h"
#include "octahedral_bins.h"
#include "surface_faces.h"

namespace luxel::voxel {
struct PathBsdf;
}  // namespace luxel::voxel

namespace luxel::voxel::cascades {

// A segment's code: the id of the face it meets first, or one of these.
inline constexpr std::uint32_t kContinue = 0xFFFFFFFFu;  // meets nothing: the next level goes on
inline constexpr std::uint32_t kSky = 0xFFFFFFFEu;       // leaves the world: the sky
inline constexpr std::uint32_t kBlack = 0xFFFFFFFDu;     // meets a face that is not a probe
inline constexpr std::uint32_t kVoid = 0xFFFFFFFCu;      // starts inside a solid: left out
// Codes from kPassage up to kVoid pass glass or water: kPassage + an index into State::passages
// (cascade_passages.h). Face ids stay below kPassage.
inline constexpr std::uint32_t kPassage = 0x80000000u;
// Most media one chain of passages crosses; past it the segment counts as blocked.
inline constexpr int kMaxPassages = 16;

inline bool isPassage(std::uint32_t code) {
    return code >= kPassage && code < kVoid;
}

// A segment's run through one medium: what the face it entered sends (face kBlack: none, it
// started inside), times the transmittance so far, then `transmittance` times what `next` brings.
struct Passage {
    std::uint32_t face = kBlack;
    std::uint32_t next = kBlack;
    Rgb transmittance;
};

struct LevelData {
    Level level;
    DirectionBins bins;
    // The sky's mean per bin: over the bins a pass reads only (demandedBins), the others black.
    std::vector<Rgb> sky;
    std::vector<Corners> corners;      // per probe: the level above's probes around it
    std::vector<std::uint32_t> codes;  // [probe][bin][corner] ([probe][bin] on the top level)
    // What a pass merges (cascade_light.cpp): level 0's radiance, which the faces gather, and
    // above it only the child means the level below reads. Only the demanded entries are
    // written; the others are never read.
    std::vector<Rgb> radiance;   // [probe][bin], level 0
    std::vector<Rgb> childMean;  // [probe][bin of the level below]: mean of its children
    // The entries a pass merges (cascade_demand.h), one bit each in rows of 64-bit words:
    // [probe][bin] on level 0, [probe][bin of the level below] above; and the probes with any.
    std::vector<std::uint64_t> demand;
    std::vector<std::int32_t> demandProbes;
    // The code each merged entry's weighted corners share, or kMixed (cascade_shared.h), in the
    // order a pass merges them (per demanded probe its demanded entries, above level 0 each
    // entry's four children); `mixed`, the eight codes of each kMixed entry, in the same order;
    // sharedStart[i] is where demandProbes[i]'s begin in both. Empty on the top level and where
    // cleared: the pass then reads the codes.
    std::vector<std::uint32_t> shared, mixed;
    struct SharedStart {
        std::size_t shared = 0, mixed = 0;
    };
    std::vector<SharedStart> sharedStart;
};

struct FaceData {
    FaceTable table;
    DirectionBins bins;  // side kFaceBinSide, like level 0
    std::vector<Rgb> sky;
    std::vector<Corners> corners;           // per face: level 0's probes around it
    std::vector<std::uint32_t> codes;       // per face, its normal's cosine bins x 8 corners
    std::vector<std::uint32_t> codeOffset;  // per face
    // Per face and bin (at codeOffset / 8 + bin): the code its weighted corners share, or kMixed
    // (cascade_shared.h); `mixed`, the eight codes of each kMixed bin, face by face (face f's from
    // mixedStart[f]). Empty where cleared.
    std::vector<std::uint32_t> shared, mixed, mixedStart;
    // Per face: 1 where every chain it gathers leaves the world at once (all its weighted corners'
    // codes kSky in every bin: the faces on the world's floor and outer walls, over half of the
    // terrain's), so its irradiance is its normal's sky irradiance, the same each pass.
    std::vector<std::uint8_t> skyOnly;
    std::vector<Rgb> albedo, emission;
    // Mean transmittance of the face's rays over the sun's disk (0 blocked, 1 open, a colour
    // through glass: sunRayTransmittance, solver_sun.h).
    std::vector<Rgb> sunPassing;
    std::vector<Rgb> outgoing;    // radiance the face sends, this pass
    std::vector<Rgb> irradiance;  // indirect irradiance gathered, last pass
    // Irradiance from the emissive faces, exact (cascade_emitters.cpp); when it is computed the
    // chains carry reflected light only.
    std::vector<Rgb> emitterIrradiance;
    bool emittersExact = true;
    // What the picture needs to take the emitters near a pixel exactly (cascade_near_emitters.cpp):
    // per face its emitterIrradiance less the share nearEmitterWeight gives the near term at its
    // centre, and the emitters that weight reaches anywhere on it (CSR: nearOffset[f] up to
    // nearOffset[f + 1] in nearEmitters). Empty lists and emitterFar = emitterIrradiance when the
    // exact term is off. `emitterVersion` counts the computations (the GPU picture uploads anew).
    std::vector<Rgb> emitterFar;
    std::vector<std::uint32_t> nearOffset;
    std::vector<gpu::shared::CascadeNearEmitter> nearEmitters;
    // The empty box in front of each emitting face that proves its lines from the pixels inside
    // clear without a walk (emitter_clear_box.h; CPU only), and beside each near emitter the
    // index of its box: a box is made once per emitter, not once per face that lists it.
    std::vector<EmitterClearBox> nearBoxes;
    std::vector<std::uint32_t> nearBox;
    std::uint64_t emitterVersion = 0;
    // The lamps the picture's glossy surfaces light-sample (glossy_emitters.h), found with the
    // emitters' light.
    GlossyLamps glossy;
    // Drops the emitters' light, so updateFaceLight computes it again.
    void clearEmitterLight() {
        emitterIrradiance.clear();
        emitterFar.clear();
        nearOffset.clear();
        nearEmitters.clear();
        nearBoxes.clear();
        nearBox.clear();
        glossy = GlossyLamps{};
    }
};

// Most (emitting face, receiving face) pairs computed exactly; past it the chains carry emission.
inline constexpr double kMaxEmitterPairs = 2e7;

}  // namespace luxel::voxel::cascades

namespace luxel::voxel {

struct RadianceCascades::State {
    const VoxelWorld* world = nullptr;
    const TextureSet* textures = nullptr;
    ShadeOptions shading;
    CascadeOptions options;
    cascades::FaceData faces;
    std::vector<cascades::LevelData> levels;
    std::vector<cascades::Passage> passages;  // of the segments through glass and water
    std::vector<float> castMedia;             // the mediaSignature the segments were cast for
    int casts = 0;              // how often they were cast (a GPU copy made before is stale)
    bool castComplete = false;  // false when the last cast was refused (castSegments)
    // Bytes estimated before building (estimateCascades) and the limit the passages must fit
    // in beside them; the bytes a refused cast's passages would have needed.
    std::uint64_t plannedBytes = 0, memoryLimit = 0, passagesRefusedAt = 0;
    Vec3d sunForVisibility{};           // the sun direction sunPassing was found for
    double sunRadiusForVisibility = 0;  // and the sun's angular radius
    // The points whose shadow rays all reach the sky, for that sun (found with sunPassing).
    SunRayMap sunRayMap;
    CascadeStats stats;
};

}  // namespace luxel::voxel

namespace luxel::voxel::cascades {

// What face f receives from the sun (Lambert's cosine times its visible fraction) and sends as
// emission into the chains (nothing when emitterIrradiance carries it exactly): the CPU pass and
// the GPU upload read the same values (cascade_light.cpp).
Rgb faceDirectSun(const RadianceCascades::State& state, int f);
// The same for a face whose normal the caller has (the face record left unread).
Rgb faceDirectSun(const RadianceCascades::State& state, int f, Int3 normal);
Rgb faceEmitted(const FaceData& faces, int f);
// A pass's change of the faces' irradiance: sum of |after - before| over the sum of `after`
// (0 when that is 0); solve() stops below the tolerance.
double relativeChange(const std::vector<Rgb>& before, const std::vector<Rgb>& after);

// create(), `solve` (the lighting passes, on the CPU or the GPU) and render(), timed:
// renderRadianceCascades and renderRadianceCascadesGpu (radiance_cascades.cpp).
Result<CascadeImage> renderCascadesWith(const VoxelWorld& world, const Camera& camera,
                                        const ShadeOptions& shading, const CascadeOptions& options,
                                        const TextureSet* textures,
                                        const std::function<Status(RadianceCascades&)>& solve);

// Radiance a plain segment code brings: a face's, the sky's, or (kContinue) `next`.
inline Rgb codeRadiance(std::uint32_t code, const std::vector<Rgb>& outgoing, Rgb sky, Rgb next) {
    if (code < kPassage) return outgoing[code];
    if (code == kContinue) return next;
    if (code == kSky) return sky;
    return Rgb{};
}

// The plain code the chain of passages from `code` ends in.
std::uint32_t passageEnd(std::uint32_t code, const std::vector<Passage>& passages);
// A chain of passages from `code` followed to its plain code `end`: the glass faces' own light
// on the way (`light`) and the transmittance through all of them (`through`), so that the chain
// brings light + through times what `end` brings. One walk gives what decides whether the level
// above is read and what the chain brings (out of line, so the plain codes' path stays small;
// cascade_passages.cpp).
struct PassageWalk {
    Rgb light, through;
    std::uint32_t end = kBlack;
};
PassageWalk walkPassages(std::uint32_t code, const std::vector<Passage>& passages,
                         const std::vector<Rgb>& outgoing);

// Radiance a segment code brings, following its passages (the GPU's twin:
// src/gpu/shaders/voxel/cascades_chain.glsl); next() is what kContinue brings.
template <typename Next>
inline Rgb chainRadiance(std::uint32_t code, const std::vector<Passage>& passages,
                         const std::vector<Rgb>& outgoing, Rgb sky, Next&& next) {
    if (!isPassage(code)) [[likely]] {
        return codeRadiance(code, outgoing, sky, code == kContinue ? next() : Rgb{});
    }
    const PassageWalk walk = walkPassages(code, passages, outgoing);
    const Rgb behind = walk.end == kContinue ? next() : Rgb{};
    return walk.light + walk.through * codeRadiance(walk.end, outgoing, sky, behind);
}

// Casts every segment of the faces and the levels once (cascade_segments.cpp). Refuses, with
// the bytes (also in State::passagesRefusedAt) and `hint` in brackets, when the passages would
// take the cascades past State::memoryLimit beside State::plannedBytes (checked as they are
// made; the cast stops early, leaving the codes not cast kVoid and castComplete false).
Status castSegments(RadianceCascades::State& state, const std::string& hint);
// Refuses an estimate over its limit, naming its spacing and bytes.
Status checkEstimate(const CascadeEstimate& estimate);
// Finds the faces for the state's shading (the irradiance gathered so far stays with its face),
// plans the levels and casts the segments (cascade_build.cpp): what create() builds, and what
// setLight() builds again when what passes glass changes (mediaSignature). From the spacing
// estimateCascades picks under State::memoryLimit; with an automatic spacing a cast refused for
// its runs through glass is tried again at twice the spacing, up to kMaxCascadeSpacing, and
// stats.spacingNote says why. Refuses as castSegments does when no spacing it may take fits.
Status buildSegments(RadianceCascades::State& state);
// The state's faces, levels, segments, passages and bytes into its stats.
void updateStats(RadianceCascades::State& state);
// Face colours and sun visibility for the state's shading (cascade_light.cpp).
void updateFaceLight(RadianceCascades::State& state);
// The faces' emitterIrradiance, emitterFar and near lists; false (and zeros, no lists) when
// there are too many pairs.
bool computeEmitterIrradiance(RadianceCascades::State& state);
// The faces' irradiance plus `emitter` (emitterIrradiance, or emitterFar for the picture's own
// surface) at a point on a face, bilinear between the centres of the face and its open
// neighbours in the plane (RadianceCascades::indirectIrradiance).
// `face`, when given, receives the id of the face at `point` (-1: none), which callers would
// otherwise look up again.
Rgb interpolatedIrradiance(const FaceData& faces, const std::vector<Rgb>& emitter, Int3 voxel,
                           Int3 normal, Vec3d point, int* face = nullptr);
// The light of the emitters near `hit` taken exactly there, each by its nearEmitterWeight
// (cascade_near_emitters.cpp). With `rays`, the visibility lines are read from (and cast into)
// them, so that nearEmitterHighlight at the same hit casts none twice; without, each call
// casts its own.
class NearEmitterRays;
Rgb nearEmitterLight(const RadianceCascades::State& state, const Hit& hit);
Rgb nearEmitterLight(const RadianceCascades::State& state, NearEmitterRays& rays);
// The glossy highlight of the emitters near `hit` (the camera's surface), light-sampled: each
// emitter's four quarter points as delta lights of a quarter of its solid angle through the
// specular-only lobe `specular` (bsdfLight), times its nearEmitterWeight s; the GGX rays count
// the same emitter's emission times 1 - s (nearEmitterShare).
Rgb nearEmitterHighlight(const RadianceCascades::State& state, const Hit& hit,
                         const PathBsdf& specular);
Rgb nearEmitterHighlight(const RadianceCascades::State& state, NearEmitterRays& rays,
                         const PathBsdf& specular);
// The nearEmitterWeight at `hit` of the emitting face (voxel, normal) when it is in the near list
// of hit's face `hitFace` (its id in the face table, -1: none); 0 when it is not.
float nearEmitterShare(const RadianceCascades::State& state, const Hit& hit, int hitFace,
                       Int3 voxel, Int3 normal);
// One lighting pass (cascade_light.cpp); returns the relative change of total irradiance.
double lightingPass(RadianceCascades::State& state);

}  // namespace luxel::voxel::cascades
