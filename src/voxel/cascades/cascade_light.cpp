// Lighting passes of the voxel radiance cascades (docs/algorithms/voxel-radiance-cascades.md §4):
// faces send emission plus the diffuse reflection of the sun and of last pass's irradiance; the
// levels merge from the top down through the cached segment codes; each face gathers its
// irradiance from level 0 through its own segments.
#include <bit>
#include <cmath>

#include "../path_trace_bsdf.h"
#include "../path_trace_surface.h"
#include "../solver_sun.h"
#include "../sun_disk.h"
#include "cascade_demand.h"
#include "cascade_picture.h"
#include "cascade_shared.h"
#include "cascade_state.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::cascades {

namespace {

constexpr float kInvPi = float(1.0 / 3.14159265358979323846);
// Shadow rays from each quarter of a face towards a sun of non-zero radius.
constexpr int kSunRaysPerQuarter = 2;

// The mean colour of a texture's opaque texels: what a face of it reflects on average.
Texel meanOpaqueTexel(const Texture& texture) {
    double sum[3] = {0, 0, 0};
    int count = 0;
    for (const Texel& t : texture.texels) {
        if (t.cutout()) continue;
        sum[0] += t.r, sum[1] += t.g, sum[2] += t.b;
        ++count;
    }
    if (count == 0) return Texel{0, 0, 0, 1};
    return Texel{float(sum[0] / count), float(sum[1] / count), float(sum[2] / count), 1};
}

// The share of the light on a face that its material sends back into the room (as diffuse
// light: the passes know no other lobe): all of it for opaque materials, all but what the
// transmission lobe lets through for glass and water, whose segments pass it on
// (cascade_passages.h). The transmission lobe (1 - metallic)(1 - F) transmission (pathBsdf)
// is averaged over the cosine-weighted hemisphere of incoming directions.
float reflectedShare(const Material& m, const ShadeOptions& shading) {
    if (!shading.refraction || !(m.transmission > 0.0f) || !(m.metallic < 1.0f)) return 1.0f;
    constexpr int kSteps = 64;
    double passed = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;  // cos; the cosine-weighted density is 2 mu
        passed += 2.0 * mu * (1.0 - dielectricFresnel(float(mu), m.ior, shading.fresnel));
    }
    passed *= double(1.0f - m.metallic) * m.transmission / kSteps;
    return float(1.0 - passed);
}

// Mean transmittance of the face's shadow rays (sunRayTransmittance: cutouts let them through,
// glass dims them): from each of its four quarter centres one ray to a delta sun, or
// kSunRaysPerQuarter rays to a disk (the quarters take turns along the disk's spiral, sun_disk.h,
// so together they cover all of it).
Rgb sunPassing(const RadianceCascades::State& state, const Face& face, const SunDisk& sun,
               const SunRayMap& map) {
    const Int3 n = normalFromIndex(face.normal);
    const Vec3d axis = sun.axis;
    if (!(n.x * axis.x + n.y * axis.y + n.z * axis.z > 0.0)) return {};
    const int perQuarter = sun.delta() ? 1 : kSunRaysPerQuarter;
    Rgb passing;
    for (int i = 0; i < 4; ++i) {
        Hit from;
        from.hit = true;
        from.voxel = face.voxel;
        from.normal = n;
        from.point = faceQuarterCentre(face, i);
        int mapped = -1;  // startsClear, found when a proof first needs it
        for (int j = 0; j < perQuarter; ++j) {
            const Vec3d l = sun.spiral(4 * j + i, 4 * perQuarter);
            // A ray proven to reach the sky (sun_ray_map.h) passes whole, one proven blocked
            // adds nothing, as walked.
            const SunRayProof proof = map.prove(*state.world, from, l, mapped);
            if (proof == SunRayProof::Open) {
                passing += Rgb(1.0f);
            } else if (proof != SunRayProof::Blocked) {
                passing += sunRayTransmittance(*state.world, state.textures, {from.point, l},
                                               state.shading);
            }
        }
    }
    return passing * (1.0f / float(4 * perQuarter));
}

// The trilinear mean over the weighted corners (`live`, weightedCorners) whose segments do not
// start inside a solid.
template <typename Next>
Rgb mergeCorners(const std::uint32_t* codes, const Corners& corners, std::uint32_t live,
                 const std::vector<Passage>& passages, const std::vector<Rgb>& outgoing, Rgb sky,
                 Next&& next) {
    Rgb sum;
    float weight = 0.0f;
    for (; live != 0; live &= live - 1) {
        const int c = std::countr_zero(live);
        if (codes[c] == kVoid) continue;
        const float w = corners.weight[c];
        sum += chainRadiance(codes[c], passages, outgoing, sky, [&] { return next(c); }) * w;
        weight += w;
    }
    return weight > 0.0f ? sum * (1.0f / weight) : Rgb{};
}

// mergeCorners for an entry whose live corners share the code `shared` (cascade_shared.h): the
// same sums in the same order, without reading the entry's codes and with a chain through glass
// walked once for all the corners.
template <typename Next>
Rgb mergeShared(std::uint32_t shared, const std::uint32_t* codes, const Corners& corners,
                std::uint32_t live, const std::vector<Passage>& passages,
                const std::vector<Rgb>& outgoing, Rgb sky, Next&& next) {
    if (shared == kVoid) return Rgb{};
    // The passes take these from CornerRows before they call mergeEntry (the same test inside
    // mergeEntry left the terrain's pass about 5% slower); here they are merged from the codes.
    if (shared == kContinue)
        return mergeCorners(codes, corners, live, passages, outgoing, sky, next);
    Rgb radiance;  // what the shared chain brings, the same at every corner
    if (!isPassage(shared)) {
        radiance = codeRadiance(shared, outgoing, sky, Rgb{});
    } else {
        const PassageWalk walk = walkPassages(shared, passages, outgoing);
        // A chain into the level above brings each corner's own light.
        if (walk.end == kContinue) {
            return mergeCorners(codes, corners, live, passages, outgoing, sky, next);
        }
        radiance = walk.light + walk.through * codeRadiance(walk.end, outgoing, sky, Rgb{});
    }
    Rgb sum;
    float weight = 0.0f;
    for (; live != 0; live &= live - 1) {
        const float w = corners.weight[std::countr_zero(live)];
        sum += radiance * w;
        weight += w;
    }
    return weight > 0.0f ? sum * (1.0f / weight) : Rgb{};
}

// The merge of an entry: from its shared code where the stream has one, from its codes in the
// mixed stream where they differ (both cursors advanced past it), else from `codes`.
template <typename Next>
Rgb mergeEntry(SharedCursor& at, const std::uint32_t* codes, const Corners& corners,
               std::uint32_t live, const std::vector<Passage>& passages,
               const std::vector<Rgb>& outgoing, Rgb sky, Next&& next) {
    if (!at.shared) return mergeCorners(codes, corners, live, passages, outgoing, sky, next);
    const std::uint32_t shared = *at.shared++;
    if (shared == kMixed) {
        const std::uint32_t* mixed = at.mixed;
        at.mixed += 8;
        return mergeCorners(mixed, corners, live, passages, outgoing, sky, next);
    }
    return mergeShared(shared, codes, corners, live, passages, outgoing, sky, next);
}

// The weighted corners of a face or a probe as rows of what the level above sends (level 0's
// radiance for a face, the child means for a probe), in mergeCorners' order, and the normaliser
// of the bins where they all continue: such a bin's mean without reading the corners' codes,
// probes and weights again, the same sums in the same order (the same bits).
class CornerRows {
  public:
    CornerRows() = default;
    CornerRows(const Corners& corners, std::uint32_t live, const std::vector<Rgb>& radiance,
               int bins) {
        float weight = 0.0f;
        for (; live != 0; live &= live - 1) {
            const int c = std::countr_zero(live);
            row_[count_] = radiance.data() + std::size_t(corners.probe[c]) * bins;
            weight_[count_++] = corners.weight[c];
            weight += corners.weight[c];
        }
        inverse_ = weight > 0.0f ? 1.0f / weight : 0.0f;
    }
    // mergeCorners' mean for a bin `b` where every weighted corner continues.
    Rgb mean(int b) const {
        Rgb sum;
        for (int j = 0; j < count_; ++j) sum += row_[j][b] * weight_[j];
        return sum * inverse_;
    }

  private:
    const Rgb* row_[8];
    float weight_[8];
    int count_ = 0;
    float inverse_ = 0.0f;
};

// Merges level k's demanded entries (cascade_demand.h), the levels above already merged: on
// level 0 its radiance, which the faces gather; above it only the child means that the level
// below reads, each found from its four children as they are merged (kept in registers, not
// stored and read back).
void mergeLevel(RadianceCascades::State& state, std::size_t k) {
    LevelData& data = state.levels[k];
    const std::vector<Rgb>& outgoing = state.faces.outgoing;
    const std::vector<Passage>& passages = state.passages;
    const int bins = data.bins.count(), entries = demandBins(state, k), words = entries / 64;
    const std::size_t probes = std::size_t(data.level.probeCount());
    const LevelData* upper = data.level.top ? nullptr : &state.levels[k + 1];
    // Whether the level's shared codes are there (cascade_shared.h; none: read the codes).
    const bool hasShared =
        upper && !data.shared.empty() && data.sharedStart.size() == data.demandProbes.size();
    // What bin b of probe p (its weighted corners `live`) brings: the top level's own segment, or
    // the weighted mean over the corners of what each chain reaches (`at` walks the shared codes).
    const auto binRadiance = [&](int p, std::uint32_t live, SharedCursor& at, int b,
                                 const CornerRows& rows) {
        if (!upper) {
            return chainRadiance(data.codes[std::size_t(p) * bins + b], passages, outgoing,
                                 data.sky[b], [] { return Rgb{}; });
        }
        if (at.shared && *at.shared == kContinue) {
            ++at.shared;
            return rows.mean(b);
        }
        const Corners& corners = data.corners[p];
        return mergeEntry(at, &data.codes[(std::size_t(p) * bins + b) * 8], corners, live, passages,
                          outgoing, data.sky[b], [&](int c) {
                              return upper->childMean[std::size_t(corners.probe[c]) * bins + b];
                          });
    };
    std::vector<Rgb>& out = k == 0 ? data.radiance : data.childMean;
    out.resize(probes * entries);
    const DirectionBins* below = k == 0 ? nullptr : &state.levels[k - 1].bins;
    const std::vector<std::int32_t>& demanded = data.demandProbes;
    parallelForRange(int(demanded.size()), 1, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int p = demanded[i];
            const std::uint32_t live = upper ? weightedCorners(data.corners[p]) : 0;
            const CornerRows rows =
                upper ? CornerRows(data.corners[p], live, upper->childMean, bins) : CornerRows();
            SharedCursor at;
            if (hasShared) {
                const LevelData::SharedStart& start = data.sharedStart[std::size_t(i)];
                at = {data.shared.data() + start.shared, data.mixed.data() + start.mixed};
            }
            Rgb* row = &out[std::size_t(p) * entries];
            forEachDemanded(&data.demand[std::size_t(p) * words], words, [&](int e) {
                if (!below) {
                    row[e] = binRadiance(p, live, at, e, rows);
                    return;
                }
                // The solid-angle mean of bin e's children here.
                Rgb sum;
                double area = 0.0;
                for (const int child : below->children(e)) {
                    const double a = data.bins.solidAngle[child];
                    sum += binRadiance(p, live, at, child, rows) * float(a);
                    area += a;
                }
                row[e] = sum * float(1.0 / area);
            });
        }
    });
}

}  // namespace

Rgb faceDirectSun(const RadianceCascades::State& state, int f) {
    return faceDirectSun(state, f, normalFromIndex(state.faces.table[f].normal));
}

Rgb faceDirectSun(const RadianceCascades::State& state, int f, Int3 n) {
    const Vec3d sun = state.sunForVisibility;
    const double cosSun = std::max(0.0, n.x * sun.x + n.y * sun.y + n.z * sun.z);
    return state.shading.sunIrradiance * state.faces.sunPassing[f] * float(cosSun);
}

Rgb faceEmitted(const FaceData& faces, int f) {
    return faces.emittersExact ? Rgb{} : faces.emission[f];
}

double relativeChange(const std::vector<Rgb>& before, const std::vector<Rgb>& after) {
    double change = 0.0, total = 0.0;
    for (std::size_t f = 0; f < after.size(); ++f) {
        for (int c = 0; c < 3; ++c) {
            total += after[f][c];
            change += std::abs(after[f][c] - before[f][c]);
        }
    }
    return total > 0.0 ? change / total : 0.0;
}

void updateFaceLight(RadianceCascades::State& state) {
    FaceData& faces = state.faces;
    const ShadeOptions& shading = state.shading;
    const int count = faces.table.size();
    std::vector<Texel> meanTexel;
    if (state.textures) {
        for (int slot = 0; slot < state.textures->size(); ++slot) {
            meanTexel.push_back(meanOpaqueTexel((*state.textures)[slot]));
        }
    }
    const SunDisk sun = SunDisk::make(shading.sunDirection, shading.sunAngularRadius);
    const bool sunMoved = faces.sunPassing.size() != std::size_t(count) ||
                          !(sun.axis == state.sunForVisibility) ||
                          !(sun.radius == state.sunRadiusForVisibility);
    // The emitters' light depends on the emission alone (the world is fixed): a new sun or sky
    // keeps it.
    const std::vector<Rgb> emissionBefore = faces.emission;
    faces.albedo.resize(count);
    faces.emission.resize(count);
    faces.sunPassing.resize(count);
    if (faces.irradiance.size() != std::size_t(count)) faces.irradiance.assign(count, Rgb{});
    faces.outgoing.resize(count);
    // The maps of the picture's sun rays (its surface's spiral, a followed surface's single ray),
    // kept, and of the faces' (their quarters'), while they are cast (sun_ray_map.h).
    SunRayMap facesRayMap;
    if (sunMoved) {
        const bool stop = sunRaysStopAtSolids(state.textures, shading);
        state.sunRayMap =
            SunRayMap::build(*state.world, spiralDirections(sun, {kPictureSunRays, 1}), stop);
        facesRayMap =
            SunRayMap::build(*state.world, spiralDirections(sun, {4 * kSunRaysPerQuarter}), stop);
    }
    parallelForRange(count, 64, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            const Face& face = faces.table[f];
            SurfaceHit s;
            s.hit.hit = true;
            s.hit.voxel = face.voxel;
            s.hit.normal = normalFromIndex(face.normal);
            s.hit.point = faceCentre(face);
            s.hit.u = s.hit.v = 0.5f;
            const int slot =
                textureSlotOf(state.world->get(face.voxel.x, face.voxel.y, face.voxel.z));
            if (slot >= 0 && slot < int(meanTexel.size())) {
                s.slot = slot;
                s.texel = meanTexel[slot];
            }
            const PathSurface surface = pathSurfaceAt(*state.world, s, shading);
            faces.albedo[f] = surface.albedo * reflectedShare(*surface.material, shading);
            faces.emission[f] = surface.emission;
            if (sunMoved) faces.sunPassing[f] = sunPassing(state, face, sun, facesRayMap);
        }
    });
    state.sunForVisibility = sun.axis;
    state.sunRadiusForVisibility = sun.radius;
    if (faces.emitterIrradiance.size() != std::size_t(count) || faces.emission != emissionBefore) {
        faces.emittersExact = computeEmitterIrradiance(state);
    }
    faces.sky = skyMeans(faces.bins, shading);
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        const std::vector<bool> read = demandedBins(state, k);
        state.levels[k].sky = skyMeans(state.levels[k].bins, shading, &read);
    }
}

double lightingPass(RadianceCascades::State& state) {
    FaceData& faces = state.faces;
    const int count = faces.table.size();
    parallelForRange(count, 256, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            faces.outgoing[f] =
                faceEmitted(faces, f) +
                faces.albedo[f] *
                    (faceDirectSun(state, f) + faces.irradiance[f] + faces.emitterIrradiance[f]) *
                    kInvPi;
        }
    });
    for (std::size_t k = state.levels.size(); k-- > 0;) mergeLevel(state, k);

    const LevelData& level0 = state.levels.front();
    const int bins = level0.bins.count();
    // What a face that sees only sky gathers (FaceData::skyOnly), per normal.
    Rgb skyIrradiance[6];
    for (int n = 0; n < 6; ++n) {
        const auto& seen = faces.bins.cosine[n];
        for (std::size_t i = 0; i < seen.bin.size(); ++i) {
            skyIrradiance[n] += faces.sky[seen.bin[i]] * seen.weight[i];
        }
    }
    const bool skyOnlyKnown = faces.skyOnly.size() == std::size_t(count);
    std::vector<Rgb> gathered(count);
    parallelForRange(count, 64, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            if (skyOnlyKnown && faces.skyOnly[f]) {
                gathered[f] = skyIrradiance[faces.table[f].normal];
                continue;
            }
            const auto& seen = faces.bins.cosine[faces.table[f].normal];
            const std::uint32_t* codes = &faces.codes[faces.codeOffset[f]];
            const Corners& corners = faces.corners[f];
            const std::uint32_t live = weightedCorners(corners);
            SharedCursor at;
            if (!faces.shared.empty()) {
                at = {&faces.shared[faces.codeOffset[f] / 8],
                      faces.mixed.data() + faces.mixedStart[f]};
            }
            const CornerRows rows(corners, live, level0.radiance, bins);
            Rgb irradiance;
            for (std::size_t i = 0; i < seen.bin.size(); ++i) {
                const int b = seen.bin[i];
                if (at.shared && *at.shared == kContinue) {
                    ++at.shared;
                    irradiance += rows.mean(b) * seen.weight[i];
                    continue;
                }
                const Rgb incoming =
                    mergeEntry(at, codes + i * 8, corners, live, state.passages, faces.outgoing,
                               faces.sky[b], [&](int c) {
                                   return level0.radiance[std::size_t(corners.probe[c]) * bins + b];
                               });
                irradiance += incoming * seen.weight[i];
            }
            gathered[f] = irradiance;
        }
    });
    const double change = relativeChange(faces.irradiance, gathered);
    faces.irradiance = std::move(gathered);
    return change;
}

}  // namespace luxel::voxel::cascades
