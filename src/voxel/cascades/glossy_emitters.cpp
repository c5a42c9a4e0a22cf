// The lamps in the camera surface's glossy lobe, light-sampled (glossy_emitters.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2, "Far lamps in the glossy lobe").
#include "glossy_emitters.h"

#include <algorithm>
#include <cmath>

#include "../path_trace_bsdf.h"
#include "cascade_state.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/emitter_rect.h"
#include "voxel/shadow_blockers.h"

namespace luxel::voxel::cascades {

namespace shared = gpu::shared;

namespace {

// The estimate a cell keeps its picks by: radiance x area / (d^2 + area), d from the
// rectangle's centre to the cell's box (its light at the nearest point of the cell, bounded
// where the cell touches it); 0 when the whole cell lies behind the rectangle's plane.
double cellScore(const EmitterFace& e, Vec3d lo, Vec3d hi) {
    const int axis = int(e.normal / 2u);
    const Vec3d c = rectCentre(e);
    if ((e.normal & 1u) == 0u ? !(hi[axis] > c[axis]) : !(lo[axis] < c[axis])) return 0.0;
    const double area =
        double(shared::emitterSizeA(e.extent)) * double(shared::emitterSizeB(e.extent));
    return double(std::max(e.r, std::max(e.g, e.b))) * area /
           (boxDistanceSquared(c, lo, hi) + area);
}

// The faces this thread's lamp rays last stopped at short of their lamp (shadow_blockers.h): a
// lamp ray that provably enters a solid voxel before it reaches the lamp's plane meets something
// else first, and is refused without its walk (§5). Kept over pixels, as neighbours' rays to a
// lamp mostly stop at the same wall; a face is only a plane to test, the proof reading the world
// it is given, so one kept from another picture proves nothing false.
thread_local ShadowBlockers lampBlockers;

// How far from its lamp, in cells, an empty box may grow: a room's width (§5, "Near lines proven
// clear").
constexpr int kClearReach = 16;

}  // namespace

GlossyLamps buildGlossyLamps(const VoxelWorld& world, const MaterialTable& materials) {
    const EmitterLights lights = EmitterLights::build(world, materials);
    GlossyLamps out;
    if (lights.empty()) return out;
    out.cells = lights.cells();
    for (const EmitterFace& f : lights.faces()) out.lamps.push_back(shaderFace(f));
    out.clear.resize(out.lamps.size());
    parallelForRange(int(out.lamps.size()), 16, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const shared::CascadeNearEmitter& e = out.lamps[std::size_t(i)];
            out.clear[std::size_t(i)] = growEmitterClearBox(
                world, {e.x, e.y, e.z}, int(e.normal), int(shared::emitterSizeA(e.extent)),
                int(shared::emitterSizeB(e.extent)), kClearReach);
        }
    });
    const int cellCount = out.cells.x * out.cells.y * out.cells.z;
    out.picks.assign(std::size_t(cellCount) * LUXEL_GLOSSY_PICKS, LUXEL_GLOSSY_NO_PICK);
    const std::vector<std::uint32_t>& offsets = lights.cellOffsets();
    const std::vector<std::uint32_t>& list = lights.cellFaces();
    parallelForRange(cellCount, 64, [&](int begin, int end) {
        for (int cell = begin; cell < end; ++cell) {
            const int x = cell % out.cells.x, y = cell / out.cells.x % out.cells.y,
                      z = cell / (out.cells.x * out.cells.y);
            const double side = LUXEL_EMITTER_CELL;
            const Vec3d lo{x * side, y * side, z * side}, hi = lo + Vec3d{side, side, side};
            // The strongest LUXEL_GLOSSY_PICKS, strongest first (ties: the earlier lamp).
            int kept = 0;
            double score[LUXEL_GLOSSY_PICKS];
            std::uint32_t* picks = &out.picks[std::size_t(cell) * LUXEL_GLOSSY_PICKS];
            for (std::uint32_t i = offsets[cell]; i < offsets[cell + 1]; ++i) {
                const double s = cellScore(lights.faces()[list[i]], lo, hi);
                if (!(s > 0.0) || (kept == LUXEL_GLOSSY_PICKS && !(s > score[kept - 1]))) continue;
                int j = std::min(kept, LUXEL_GLOSSY_PICKS - 1);
                for (; j > 0 && s > score[j - 1]; --j) {
                    score[j] = score[j - 1];
                    picks[j] = picks[j - 1];
                }
                score[j] = s;
                picks[j] = list[i];
                kept = std::min(kept + 1, LUXEL_GLOSSY_PICKS);
            }
        }
    });
    return out;
}

GlossyLampChoice::GlossyLampChoice(const RadianceCascades::State& state, const Hit& hit, int face)
    : state_(state),
      hit_(hit),
      face_(face),
      point_(float(hit.point.x), float(hit.point.y), float(hit.point.z)),
      normal_(float(hit.normal.x), float(hit.normal.y), float(hit.normal.z)) {}

void GlossyLampChoice::choose() {
    if (chosen_) return;
    chosen_ = true;
    const GlossyLamps& g = state_.faces.glossy;
    if (g.empty()) return;
    const int cell = shared::emitterCellIndex(point_, {g.cells.x, g.cells.y, g.cells.z});
    for (int k = 0; k < LUXEL_GLOSSY_PICKS; ++k) {
        const std::uint32_t i = g.picks[std::size_t(cell) * LUXEL_GLOSSY_PICKS + k];
        if (i == LUXEL_GLOSSY_NO_PICK) break;
        // A lamp whose plane the point is not in front of weighs 0: glossyPickWeightOf's
        // towardsX, the same float, found before the span (§5).
        const shared::CascadeNearEmitter& e = g.lamps[i];
        const int axis = int(e.normal / 2u);
        const float along = shared::emitterPlaneCoordinate(e) - point_[axis];
        if (!(((e.normal & 1u) == 0u ? -along : along) > 0.0f)) continue;
        const shared::EmitterSpan span = shared::emitterSpanInFront(point_, normal_, g.lamps[i]);
        const float w = shared::glossyPickWeightOf(point_, normal_, g.lamps[i], span);
        if (!(w > 0.0f)) continue;
        index_[count_] = i;
        span_[count_] = span;
        weight_[count_] = w;
        total_ += w;
        ++count_;
    }
}

double GlossyLampChoice::density(Int3 voxel, Int3 normal, Vec3d y) {
    choose();
    const std::uint32_t met = std::uint32_t(normalIndex(normal));
    const shared::vec3 at(float(y.x), float(y.y), float(y.z));
    for (int k = 0; k < count_; ++k) {
        const shared::CascadeNearEmitter& e = state_.faces.glossy.lamps[index_[k]];
        if (e.normal != met || !shared::emitterRectHolds({e.x, e.y, e.z}, int(met / 2u), e.extent,
                                                         {voxel.x, voxel.y, voxel.z})) {
            continue;
        }
        return double(weight_[k] / total_ * shared::emitterSpanDensity(e, span_[k], point_, at));
    }
    return 0.0;
}

Rgb GlossyLampChoice::sample(const PathBsdf& specular, int lobeRays, PathRng& rng) {
    choose();
    if (count_ == 0) return {};
    const bool blockersHold = shadowBlockersHold(state_.textures, state_.shading.stepCap);
    const bool provable = state_.faces.glossy.clear.size() == state_.faces.glossy.lamps.size();
    Rgb sum;
    for (int n = 0; n < LUXEL_GLOSSY_LIGHT_SAMPLES; ++n) {
        const float u0 = rng.next(), u1 = rng.next(), u2 = rng.next();
        // A lamp in proportion to its weight, then a uniform point of its part in front.
        const float target = u0 * total_;
        float below = 0.0f;
        int k = count_ - 1;
        for (int j = 0; j < count_; ++j) {
            below += weight_[j];
            if (target < below) {
                k = j;
                break;
            }
        }
        const shared::CascadeNearEmitter& e = state_.faces.glossy.lamps[index_[k]];
        const shared::EmitterSpan& span = span_[k];
        const shared::vec3 y = shared::emitterSpanPoint(e, span, u1, u2);
        const float lightPdf = weight_[k] / total_ * shared::emitterSpanDensity(e, span, point_, y);
        if (!(lightPdf > 0.0f)) continue;
        const shared::vec3 l = normalize(y - point_);
        const Ray towards{hit_.point, {double(l.x), double(l.y), double(l.z)}};
        const Vec3d& dir = towards.direction;
        // Seen when the shadow ray first meets this rectangle through its face (glass and
        // cutouts in between stop it, as they turn the GGX rays that count the lamp in full):
        // the face lies on the lamp's plane, which the ray crosses once, `reach` along it.
        const int axis = int(e.normal / 2u);
        const double reach =
            (double(shared::emitterPlaneCoordinate(e)) - hit_.point[axis]) / dir[axis];
        const Int3 outward = normalFromIndex(int(e.normal));
        // Inside the lamp's empty box the ray provably meets the lamp, at a voxel the crossing
        // decides (§5, "Near lines proven clear"); else blockers, then the walk.
        Int3 seenVoxel;
        if (!(blockersHold && provable &&
              rayProvenToRect(state_.faces.glossy.clear[index_[k]], hit_, dir, reach,
                              &seenVoxel))) {
            if (blockersHold && std::isfinite(reach) &&
                lampBlockers.blocks(*state_.world, towards, reach - ShadowBlockers::kEdgeMargin)) {
                continue;
            }
            // Where every solid voxel stops a ray (no cutout texel), the first voxel castRay
            // meets is castToSurface's, without the texel it would look up there.
            const Hit seen =
                blockersHold
                    ? castRay(*state_.world, towards, kInfinity, state_.shading.stepCap)
                    : castToSurface(*state_.world, state_.textures, towards, state_.shading.stepCap)
                          .hit;
            if (!seen.hit || seen.normal != outward ||
                !shared::emitterRectHolds({e.x, e.y, e.z}, axis, e.extent,
                                          {seen.voxel.x, seen.voxel.y, seen.voxel.z})) {
                if (blockersHold) lampBlockers.note(seen, true);
                continue;
            }
            seenVoxel = seen.voxel;
        }
        const float share = 1.0f - nearEmitterShare(state_, hit_, face_, seenVoxel, outward);
        if (!(share > 0.0f)) continue;
        // ggxDensity and bsdfLight(..., 0) with one half vector.
        const GgxTowards lobe(specular, dir);
        const float lobePdf = float(lobe.density());
        const float balance = shared::glossyBalance(
            lightPdf, lobePdf, float(LUXEL_GLOSSY_LIGHT_SAMPLES), float(lobeRays));
        sum += lobe.deltaLight(Rgb(e.r, e.g, e.b) * (share * balance));
    }
    return sum;
}

}  // namespace luxel::voxel::cascades
