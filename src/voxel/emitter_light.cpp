// Light from emissive voxels in the ray caster (emitter_light.h): the open faces, the grid of
// lists, and the light at a point. The arithmetic at a point is in float, as the GPU's twin
// (src/gpu/shaders/voxel/emitter_light.glsl) runs it, so both draw the same picture.
#include "luxel/voxel/emitter_light.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>

#include "gpu/shaders/shared/emitter_light.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/voxel/path_trace_emitters.h"
#include "luxel/voxel/shading.h"
#include "voxel/emitter_rect.h"
#include "voxel/solver_sun.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

static_assert(kMaxEmitterRays == LUXEL_EMITTER_MAX_RAYS && kEmitterFloor == LUXEL_EMITTER_FLOOR &&
              kEmitterPathRays == LUXEL_EMITTER_PATH_RAYS);
constexpr Int3 kNormals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

float largest(const EmitterFace& e) {
    return std::max(e.r, std::max(e.g, e.b));
}

int sizeA(const EmitterFace& e) {
    return int(shared::emitterSizeA(e.extent));
}
int sizeB(const EmitterFace& e) {
    return int(shared::emitterSizeB(e.extent));
}

// The reach of an emitter: past this distance from its centre its irradiance is below `floor`
// (a rectangle of area A seen from d away subtends at most A/d^2 of projected solid angle, and
// no point of it is nearer than the centre's distance less half its diagonal).
double reachOf(const EmitterFace& e, double floor) {
    const double a = sizeA(e), b = sizeB(e);
    return std::sqrt(double(largest(e)) * a * b / floor) + 0.5 * std::sqrt(a * a + b * b) + 1e-3;
}

// The open faces of emissive voxels merged into rectangles: faces of one normal, plane and
// radiance (bit for bit) grown greedily, first along a then along b, up to
// LUXEL_EMITTER_RECT_SIDE faces a side. Each rectangle's light is exact (its contour integral)
// whatever its size, so a lamp panel lights a point with all of its faces instead of its 16
// strongest; the sides are bounded so its shadow rays still resolve penumbrae.
std::vector<EmitterFace> mergedRectangles(std::vector<EmitterFace> faces) {
    // Faces of one group share normal, plane and radiance; within it a face is at (b, a) on the
    // plane's axes a = (axis + 1) % 3, b = (axis + 2) % 3.
    const auto groupOf = [](const EmitterFace& f) {
        const Int3 v{f.x, f.y, f.z};
        return std::tuple(f.normal, v[int(f.normal / 2u)], std::bit_cast<std::uint32_t>(f.r),
                          std::bit_cast<std::uint32_t>(f.g), std::bit_cast<std::uint32_t>(f.b));
    };
    const auto cellOf = [](const EmitterFace& f) {
        const int axis = int(f.normal / 2u);
        const Int3 v{f.x, f.y, f.z};
        return std::pair(v[(axis + 2) % 3], v[(axis + 1) % 3]);
    };
    std::sort(faces.begin(), faces.end(), [&](const EmitterFace& l, const EmitterFace& r) {
        return std::pair(groupOf(l), cellOf(l)) < std::pair(groupOf(r), cellOf(r));
    });
    std::vector<EmitterFace> out;
    std::vector<char> used(faces.size(), 0);
    std::size_t groupEnd = 0;
    for (std::size_t begin = 0; begin < faces.size(); begin = groupEnd) {
        groupEnd = begin + 1;
        while (groupEnd < faces.size() && groupOf(faces[groupEnd]) == groupOf(faces[begin])) {
            ++groupEnd;
        }
        const int axis = int(faces[begin].normal / 2u), a = (axis + 1) % 3, b = (axis + 2) % 3;
        // The face at (ca, cb) of this group, or -1.
        const auto find = [&](int ca, int cb) -> std::ptrdiff_t {
            const auto first = faces.begin() + std::ptrdiff_t(begin);
            const auto last = faces.begin() + std::ptrdiff_t(groupEnd);
            const auto it = std::lower_bound(
                first, last, std::pair(cb, ca),
                [&](const EmitterFace& f, std::pair<int, int> c) { return cellOf(f) < c; });
            return it != last && cellOf(*it) == std::pair(cb, ca) ? it - faces.begin() : -1;
        };
        const auto freeAt = [&](int ca, int cb) {
            const std::ptrdiff_t i = find(ca, cb);
            return i >= 0 && !used[std::size_t(i)];
        };
        for (std::size_t i = begin; i < groupEnd; ++i) {
            if (used[i]) continue;
            const Int3 v{faces[i].x, faces[i].y, faces[i].z};
            int wa = 1, wb = 1;
            while (wa < LUXEL_EMITTER_RECT_SIDE && freeAt(v[a] + wa, v[b])) ++wa;
            for (bool grow = true; grow && wb < LUXEL_EMITTER_RECT_SIDE;) {
                for (int k = 0; k < wa && grow; ++k) grow = freeAt(v[a] + k, v[b] + wb);
                if (grow) ++wb;
            }
            for (int j = 0; j < wb; ++j) {
                for (int k = 0; k < wa; ++k) used[std::size_t(find(v[a] + k, v[b] + j))] = 1;
            }
            EmitterFace rect = faces[i];
            rect.extent = std::uint32_t(wa - 1) | (std::uint32_t(wb - 1) << 16u);
            out.push_back(rect);
        }
    }
    return out;
}

// Visits the cells within `reach` of `centre` (cell side LUXEL_EMITTER_CELL).
template <typename F>
void forCellsInReach(Int3 cells, Vec3d centre, double reach, F&& visit) {
    const double side = LUXEL_EMITTER_CELL;
    Int3 lo, hi;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::clamp(int(std::floor((centre[a] - reach) / side)), 0, cells[a] - 1);
        hi[a] = std::clamp(int(std::floor((centre[a] + reach) / side)), 0, cells[a] - 1);
    }
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const Vec3d boxLo{x * side, y * side, z * side};
                if (std::sqrt(boxDistanceSquared(centre, boxLo, boxLo + Vec3d{side, side, side})) <=
                    reach) {
                    visit((z * cells.y + y) * cells.x + x);
                }
            }
}

}  // namespace

EmitterLights EmitterLights::build(const VoxelWorld& world, const MaterialTable& materials) {
    EmitterLights out;
    const PathEmitters emitters = PathEmitters::find(world, materials);
    if (emitters.empty()) return out;
    for (const Int3 v : emitters.voxels()) {
        const Rgb l = materials.forSlot(textureSlotOf(world.get(v.x, v.y, v.z))).emission;
        for (int k = 0; k < 6; ++k) {
            const Int3 n = kNormals[k];
            const Int3 next{v.x + n.x, v.y + n.y, v.z + n.z};
            if (!world.inside(next.x, next.y, next.z) || world.solid(next.x, next.y, next.z)) {
                continue;
            }
            if (out.faces_.size() == std::size_t(kMaxEmitterFaces)) return EmitterLights{};
            out.faces_.push_back({v.x, v.y, v.z, std::uint32_t(k), l.r, l.g, l.b, 0u});
        }
    }
    out.openFaces_ = int(out.faces_.size());
    out.faces_ = mergedRectangles(std::move(out.faces_));
    const Int3 size = world.size();
    const int side = LUXEL_EMITTER_CELL;
    out.cells_ = {(size.x + side - 1) / side, (size.y + side - 1) / side,
                  (size.z + side - 1) / side};
    const std::size_t cellCount = std::size_t(out.cells_.x) * out.cells_.y * out.cells_.z;
    // Count first; raise the floor until the lists fit their bound. A count stops as soon as it
    // is over the bound, so many bright faces (each reaching every cell) cost at most about
    // kMaxEmitterListEntries steps per floor tried, not faces x cells.
    std::vector<std::uint32_t> counts;
    for (;;) {
        counts.assign(cellCount, 0u);
        std::int64_t total = 0;
        for (const EmitterFace& e : out.faces_) {
            if (total > kMaxEmitterListEntries) break;
            forCellsInReach(out.cells_, rectCentre(e), reachOf(e, out.floor_), [&](int cell) {
                ++counts[std::size_t(cell)];
                ++total;
            });
        }
        if (total <= kMaxEmitterListEntries) break;
        out.floor_ *= 2.0f;
    }
    out.cellOffsets_.assign(cellCount + 1, 0u);
    for (std::size_t i = 0; i < cellCount; ++i) {
        out.cellOffsets_[i + 1] = out.cellOffsets_[i] + counts[i];
    }
    out.cellFaces_.resize(out.cellOffsets_.back());
    std::vector<std::uint32_t> filled(out.cellOffsets_.begin(), out.cellOffsets_.end() - 1);
    for (std::size_t f = 0; f < out.faces_.size(); ++f) {
        const EmitterFace& e = out.faces_[f];
        forCellsInReach(out.cells_, rectCentre(e), reachOf(e, out.floor_), [&](int cell) {
            out.cellFaces_[filled[std::size_t(cell)]++] = std::uint32_t(f);
        });
    }
    return out;
}

Rgb EmitterLights::light(const VoxelWorld& world, const TextureSet* textures, const Surface& s,
                         const ShadeOptions& shading, int rays, int& budget) const {
    const bool glossy = s.specularWeight > 0.0f && s.specularModel != LUXEL_VOXEL_SPECULAR_NONE;
    // Nothing to reflect (clear glass, a mirror): no rays.
    if (faces_.empty() || (!(s.diffuseAlbedo.maxComponent() > 0.0f) && !glossy)) return {};
    if (budget < 1) return {};
    const shared::vec3 p(float(s.point.x), float(s.point.y), float(s.point.z));
    const shared::vec3 ng(float(s.faceNormal.x), float(s.faceNormal.y), float(s.faceNormal.z));
    const int cell = shared::emitterCellIndex(p, {cells_.x, cells_.y, cells_.z});
    // The strongest emitters by unoccluded light, strongest first (ties: the earlier in the list).
    int kept = 0;
    std::uint32_t keptFace[LUXEL_EMITTER_MAX_FACES], keptRank[LUXEL_EMITTER_MAX_FACES];
    float keptLight[LUXEL_EMITTER_MAX_FACES], keptFormFactor[LUXEL_EMITTER_MAX_FACES];
    for (std::uint32_t i = cellOffsets_[cell]; i < cellOffsets_[cell + 1]; ++i) {
        const shared::CascadeNearEmitter face = shaderFace(faces_[cellFaces_[i]]);
        const shared::EmitterSpan span = shared::emitterSpanInFront(p, ng, face);
        const float formFactor = shared::emitterFormFactor(p, ng, face, span);
        const float e0 = formFactor * std::max(face.r, std::max(face.g, face.b));
        if (!(shared::emitterFade(e0, floor_) > 0.0f)) continue;
        const std::uint32_t rank = shared::emitterRank(e0);
        if (kept == LUXEL_EMITTER_MAX_FACES && !(rank > keptRank[kept - 1])) continue;
        int j = std::min(kept, LUXEL_EMITTER_MAX_FACES - 1);
        while (j > 0 && rank > keptRank[j - 1]) {
            keptFace[j] = keptFace[j - 1], keptRank[j] = keptRank[j - 1];
            keptLight[j] = keptLight[j - 1], keptFormFactor[j] = keptFormFactor[j - 1];
            --j;
        }
        keptFace[j] = cellFaces_[i], keptRank[j] = rank;
        keptLight[j] = e0, keptFormFactor[j] = formFactor;
        kept = std::min(kept + 1, LUXEL_EMITTER_MAX_FACES);
    }
    const int n = std::clamp(rays, 1, LUXEL_EMITTER_MAX_RAYS);
    const shared::vec3 sn(s.shadingNormal.x, s.shadingNormal.y, s.shadingNormal.z);
    const shared::vec3 view(s.view.x, s.view.y, s.view.z);
    const shared::vec3 f0(s.f0.x, s.f0.y, s.f0.z);
    Rgb diffuse, specular;
    for (int k = 0; k < kept; ++k) {
        const shared::CascadeNearEmitter e = shaderFace(faces_[keptFace[k]]);
        const shared::EmitterSpan span = shared::emitterSpanInFront(p, ng, e);
        // Strongest first, each emitter its rays while the path's budget lasts.
        if (n > budget) break;
        budget -= n;
        const float scale = keptFormFactor[k] * shared::emitterFade(keptLight[k], floor_);
        const Rgb share = Rgb(e.r, e.g, e.b) * (scale / float(n));  // irradiance per ray
        const FaceTarget target{{e.x, e.y, e.z}, kNormals[e.normal], e.extent};
        for (int i = 0; i < n; ++i) {
            const shared::vec3 d = normalize(shared::emitterRayTarget(e, span, i, n) - p);
            const Rgb t = faceRayTransmittance(world, textures,
                                               {s.point, {double(d.x), double(d.y), double(d.z)}},
                                               shading, target);
            if (!(t.maxComponent() > 0.0f)) continue;
            diffuse += share * t;
            if (glossy) {
                const shared::vec3 f =
                    shared::voxelSpecularBrdf(s.specularModel, sn, view, d, s.alpha, f0);
                specular += share * t * Rgb(f.x, f.y, f.z);
            }
        }
    }
    return s.diffuseAlbedo * diffuse * float(1.0 / 3.14159265358979) + specular * s.specularWeight;
}

}  // namespace luxel::voxel
