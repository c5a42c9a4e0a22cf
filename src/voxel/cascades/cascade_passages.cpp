// Segments of the voxel radiance cascades through glass and water (cascade_passages.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2). Along the straight line, as the solvers' sun
// rays (solver_sun.h): the entry's transmission lobe weight, Beer-Lambert inside, 1 - F where
// the line leaves into the air; a touching medium of another material is entered with its own
// lobe weight and no exit between them; an opaque voxel inside stops the segment.
#include "cascade_passages.h"

#include <algorithm>
#include <cmath>

#include "../shading_physical.h"
#include "../solver_sun.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::cascades {

namespace {

// Below this the light that is left counts as none, as for the sun's rays.
constexpr float kDarkTransmittance = 1e-4f;

bool insideWorld(const VoxelWorld& world, Vec3d p) {
    const Int3 s = world.size();
    return p.x >= 0.0 && p.y >= 0.0 && p.z >= 0.0 && p.x <= s.x && p.y <= s.y && p.z <= s.z;
}

// The material of the voxel at `cell` when light passes into it (solid, transmissive, and
// shading.refraction on), else null.
const Material* mediumAt(const RadianceCascades::State& state, Int3 cell) {
    const VoxelWorld& world = *state.world;
    if (!world.inside(cell.x, cell.y, cell.z)) return nullptr;
    const Voxel v = world.get(cell.x, cell.y, cell.z);
    if (!v.solid()) return nullptr;
    const Material& m = state.shading.materials.forSlot(textureSlotOf(v));
    return m.transmission > 0.0f && m.metallic < 1.0f ? &m : nullptr;
}

enum class Inside { Left, EndsInside, Blocked };

// Walks the line from `point` in medium voxel `cell` for at most `room` voxels of length,
// multiplying `t` by what passes; on Left, `point` is where it leaves into the air and `walked`
// the length inside; on Blocked, `blocker` is the face of the opaque voxel it met (kBlack: none).
Inside walkThrough(const RadianceCascades::State& state, Int3 cell, Vec3d& point, Vec3d dir,
                   double room, Rgb& t, double& walked, std::uint32_t& blocker) {
    blocker = kBlack;
    walked = 0.0;
    for (int media = 0; media < kMaxSunRayMedia; ++media) {
        const Material& m = *mediumAt(state, cell);
        const MediumExit exit = walkMedium(*state.world, cell, point, dir);
        if (walked + exit.distance >= room) {
            t *= mediumAbsorption(m, room - walked);
            return Inside::EndsInside;
        }
        t *= mediumAbsorption(m, exit.distance);
        walked += exit.distance;
        point = exit.point;
        if (!exit.intoSolid) {
            t *= Rgb(mediumExitTransmission(m, dir, exit.outward, state.shading));
            return Inside::Left;
        }
        const Int3 next{exit.cell.x + exit.outward.x, exit.cell.y + exit.outward.y,
                        exit.cell.z + exit.outward.z};
        const Material* other = mediumAt(state, next);
        const Int3 inward{-exit.outward.x, -exit.outward.y, -exit.outward.z};
        if (!other) {
            // An opaque voxel under the medium: its face is a probe (surface_faces.h).
            const int face = state.faces.table.find(next, normalIndex(inward));
            if (face >= 0 && std::uint32_t(face) < kPassage) blocker = std::uint32_t(face);
            return Inside::Blocked;
        }
        t *= Rgb(mediumEntryTransmission(*other, inward, dir, state.shading));
        cell = next;
    }
    return Inside::Blocked;
}

}  // namespace

SegmentTrace traceSegment(const RadianceCascades::State& state, Vec3d start, Vec3d d, double limit,
                          bool cutouts) {
    const VoxelWorld& world = *state.world;
    const ShadeOptions& shading = state.shading;
    const double length = std::sqrt(dot(d, d));
    // A segment of no length (a connector to where it already is) has no direction to walk.
    const bool media = shading.lightPassesMedia() && length > 0.0;
    const Vec3d dir = media ? d * (1.0 / length) : d;
    SegmentTrace out;
    Vec3d origin = start;
    double t0 = 0.0;  // where origin lies along d
    // Ends a run through a medium entered by `face`; false when the segment goes no further.
    auto pass = [&](std::uint32_t face, Int3 cell, Vec3d point, Rgb t) {
        if (out.runs == kMaxPassages) {
            out.end = kBlack;
            return false;
        }
        double walked = 0.0;
        std::uint32_t blocker = kBlack;
        const double room = (limit - t0) * length;
        const Inside inside = walkThrough(state, cell, point, dir, room, t, walked, blocker);
        out.run[out.runs++] = {face, {t.r, t.g, t.b}};
        if (inside == Inside::EndsInside) {
            out.end = kContinue;
            return false;
        }
        if (inside == Inside::Blocked) {
            out.end = blocker;
            return false;
        }
        if (!(traceTransmittance(out).maxComponent() > kDarkTransmittance)) {
            out.end = kBlack;
            return false;
        }
        origin = point;
        t0 += walked / length;
        return true;
    };
    if (media) {
        // A chain whose last segment ended inside glass goes on from inside it.
        const Vec3d ahead = start + dir * 1e-7;
        const Int3 cell{int(std::floor(ahead.x)), int(std::floor(ahead.y)),
                        int(std::floor(ahead.z))};
        if (mediumAt(state, cell) && !pass(kBlack, cell, start, Rgb(1.0f))) return out;
    }
    for (;;) {
        const SurfaceHit s = castToSurface(world, cutouts ? state.textures : nullptr, {origin, d},
                                           shading.stepCap, limit - t0);
        if (!s.hit.hit) {
            const bool open = limit == kInfinity || !insideWorld(world, start + d * limit);
            out.end = (s.hit.capped || s.cutoutCapped) ? kBlack : open ? kSky : kContinue;
            return out;
        }
        if (s.hit.normal == Int3{} || !(s.hit.t > 1e-9)) {
            out.end = out.runs > 0 ? kBlack : kVoid;
            return out;
        }
        const int found = state.faces.table.find(s.hit.voxel, normalIndex(s.hit.normal));
        const std::uint32_t face =
            found < 0 || std::uint32_t(found) >= kPassage ? kBlack : std::uint32_t(found);
        const Material* m = media ? mediumAt(state, s.hit.voxel) : nullptr;
        if (!m) {
            out.end = face;
            return out;
        }
        t0 += s.hit.t;
        const Rgb entry(mediumEntryTransmission(*m, s.hit.normal, dir, shading));
        if (!pass(face, s.hit.voxel, s.hit.point, entry)) return out;
    }
}

void appendTrace(SegmentTrace& first, const SegmentTrace& then) {
    for (int i = 0; i < then.runs; ++i) {
        if (first.runs == kMaxPassages) {
            first.end = kBlack;
            return;
        }
        first.run[first.runs++] = then.run[i];
    }
    // A connector that starts inside a solid ends a chain that has passed glass in the dark.
    first.end = then.end == kVoid && first.runs > 0 ? kBlack : then.end;
}

Rgb traceTransmittance(const SegmentTrace& trace) {
    Rgb t(1.0f);
    for (int i = 0; i < trace.runs; ++i) {
        const float* r = trace.run[i].transmittance;
        t *= Rgb(r[0], r[1], r[2]);
    }
    return t;
}

std::vector<float> mediaSignature(const ShadeOptions& shading) {
    const MaterialTable& materials = shading.materials;
    if (!shading.lightPassesMedia()) return {};
    std::vector<float> key{float(shading.fresnel)};
    for (int slot = -1; slot < materials.slotCount(); ++slot) {
        const Material& m = materials.forSlot(slot);
        key.insert(key.end(), {m.transmission, m.metallic, m.ior, m.absorption.r, m.absorption.g,
                               m.absorption.b});
    }
    return key;
}

std::uint32_t passageEnd(std::uint32_t code, const std::vector<Passage>& passages) {
    for (int i = 0; i < kMaxPassages && isPassage(code); ++i) code = passages[code - kPassage].next;
    return code;
}

PassageWalk walkPassages(std::uint32_t code, const std::vector<Passage>& passages,
                         const std::vector<Rgb>& outgoing) {
    PassageWalk walk;
    walk.through = Rgb(1.0f);
    for (int i = 0; i < kMaxPassages && isPassage(code); ++i) {
        const Passage& p = passages[code - kPassage];
        if (p.face < kPassage) walk.light += walk.through * outgoing[p.face];
        walk.through *= p.transmittance;
        code = p.next;
    }
    walk.end = code;
    return walk;
}

bool PassageWriter::reserveFor(std::size_t more) {
    const std::size_t size = passages_.size(), capacity = passages_.capacity();
    if (size + more <= capacity) return true;
    const std::uint64_t each = sizeof(Passage);
    // While the vector moves, the old storage and the new are both held.
    const std::uint64_t room = budget_ / each > capacity ? budget_ / each - capacity : 0;
    const std::size_t grown = std::min<std::uint64_t>(std::max(2 * capacity, size + more), room);
    if (grown < size + more) {
        reached_ = (std::uint64_t(capacity) + std::max(2 * capacity, size + more)) * each;
        refused_.store(true, std::memory_order_relaxed);
        return false;
    }
    passages_.reserve(grown);
    return true;
}

std::uint32_t PassageWriter::codeOf(const SegmentTrace& trace) {
    if (trace.runs == 0) return trace.end;
    const std::lock_guard<std::mutex> hold(lock_);
    // The codes stay below kVoid - 1, which names a mixed entry (kMixed, cascade_shared.h).
    if (passages_.size() + std::size_t(trace.runs) >= std::size_t(kVoid - kPassage)) return kBlack;
    if (refused() || !reserveFor(std::size_t(trace.runs))) return kBlack;
    std::uint32_t next = trace.end;
    for (int i = trace.runs; i-- > 0;) {
        const SegmentTrace::Run& run = trace.run[i];
        const float* t = run.transmittance;
        passages_.push_back(Passage{run.face, next, Rgb(t[0], t[1], t[2])});
        next = kPassage + std::uint32_t(passages_.size() - 1);
    }
    return next;
}

}  // namespace luxel::voxel::cascades
