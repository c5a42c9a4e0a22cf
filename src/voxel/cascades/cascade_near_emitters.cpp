// The light of emissive faces near a point of the picture, exactly at the point
// (docs/algorithms/voxel-radiance-cascades.md §4.1): next to a small lamp the irradiance changes
// by far more within one face (1/r^2, and up to pi L at the lamp's foot) than interpolation
// between face centres can draw. Each emitter's light is split by nearEmitterWeight of the
// distance to its centre (shared/near_emitters.h): the faces keep the far share at their centres
// (emitterFar, interpolated as before), and the pixel adds the near share at its own point,
// Lambert's contour integral times the mean transmittance of four straight lines to the emitter.
// The camera surface's glossy lobe takes the same near share by light sampling (§4.2): each
// emitter's four quarter points as delta lights, while its GGX rays keep the far share of the
// emitters they meet (nearEmitterShare). Both aim the same lines at the same points, which the
// picture casts once for both (NearEmitterRays, cascade_near_rays.h). The GPU's twin:
// src/gpu/shaders/voxel/near_emitters.glsl (same float arithmetic).
#include <cmath>

#include "../path_trace_bsdf.h"
#include "../solver_sun.h"
#include "cascade_near_rays.h"
#include "cascade_state.h"
#include "voxel/shadow_blockers.h"

namespace luxel::voxel::cascades {

namespace shared = gpu::shared;

NearEmitterRays::NearEmitterRays(const RadianceCascades::State& state, const Hit& hit, int face)
    : state_(state), hit_(hit), point_(float(hit.point.x), float(hit.point.y), float(hit.point.z)) {
    const FaceData& faces = state.faces;
    if (faces.nearOffset.empty()) return;
    face_ = face == kFindFace ? faces.table.find(hit.voxel, normalIndex(hit.normal)) : face;
    if (face_ < 0) return;
    begin_ = faces.nearOffset[face_];
    end_ = faces.nearOffset[face_ + 1];
    // The boxes prove what the walk finds when it stops at the first solid voxel: no cutout
    // texels to continue through, and no step cap short of the world (castRay's default).
    provable_ = faces.nearBox.size() == faces.nearEmitters.size() &&
                shadowBlockersHold(state.textures, state.shading.stepCap);
}

Rgb NearEmitterRays::transmittance(std::uint32_t i, int q) {
    const std::uint32_t slot = 4 * (i - begin_) + std::uint32_t(q);
    const bool kept = i - begin_ < kKept;
    if (kept && (known_ >> slot & 1u) != 0) {
        return Rgb(seen_[slot][0], seen_[slot][1], seen_[slot][2]);
    }
    const shared::CascadeNearEmitter& e = state_.faces.nearEmitters[i];
    Rgb t(1.0f);
    // A line inside the emitter's empty box is clear: the walk would cross empty cells and stop
    // at the face (§5, "Near lines proven clear").
    if (!(provable_ && lineProvenClear(state_.faces.nearBoxes[state_.faces.nearBox[i]], hit_))) {
        const FaceTarget target{{e.x, e.y, e.z}, normalFromIndex(int(e.normal))};
        const shared::vec3 d = normalize(shared::nearEmitterPoint(e, q) - point_);
        t = faceRayTransmittance(*state_.world, state_.textures,
                                 {hit_.point, {double(d.x), double(d.y), double(d.z)}},
                                 state_.shading, target);
    }
    ++cast_;
    if (kept) {
        seen_[slot][0] = t.r, seen_[slot][1] = t.g, seen_[slot][2] = t.b;
        known_ |= std::uint64_t(1) << slot;
    }
    return t;
}

Rgb nearEmitterLight(const RadianceCascades::State& state, NearEmitterRays& rays) {
    if (rays.face() < 0) return {};
    const shared::vec3& p = rays.point();
    const Int3 normal = rays.hit().normal;
    const shared::vec3 n(float(normal.x), float(normal.y), float(normal.z));
    Rgb sum;
    for (std::uint32_t i = rays.begin(); i < rays.end(); ++i) {
        const shared::CascadeNearEmitter& e = state.faces.nearEmitters[i];
        const float weight =
            shared::nearEmitterWeight(length(p - shared::nearEmitterPoint(e, -1)),
                                      LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
        if (!(weight > 0.0f)) continue;
        const float formFactor = shared::nearEmitterFormFactor(p, n, e);
        if (!(formFactor > 0.0f)) continue;
        Rgb seen;
        for (int q = 0; q < 4; ++q) seen += rays.transmittance(i, q);
        sum += Rgb(e.r, e.g, e.b) * seen * (0.25f * weight * formFactor);
    }
    return sum;
}

Rgb nearEmitterLight(const RadianceCascades::State& state, const Hit& hit) {
    NearEmitterRays rays(state, hit);
    return nearEmitterLight(state, rays);
}

Rgb nearEmitterHighlight(const RadianceCascades::State& state, NearEmitterRays& rays,
                         const PathBsdf& specular) {
    if (rays.face() < 0) return {};
    const shared::vec3& p = rays.point();
    Rgb sum;
    for (std::uint32_t i = rays.begin(); i < rays.end(); ++i) {
        const shared::CascadeNearEmitter& e = state.faces.nearEmitters[i];
        const shared::vec3 centre = shared::nearEmitterPoint(e, -1);
        const float distance = length(p - centre);
        const float weight =
            shared::nearEmitterWeight(distance, LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
        if (!(weight > 0.0f)) continue;
        // A face lights only the side it faces: from behind, a GGX ray meets another face.
        const shared::vec3 outward = shared::nearEmitterNormal(e.normal);
        if (!(dot(outward, p - centre) > 0.0f)) continue;
        const int side = shared::nearHighlightSide(distance, specular.alpha);
        Rgb seen;
        for (int q = 0; q < 4; ++q) {
            const Rgb t = rays.transmittance(i, q);
            if (!(t.maxComponent() > 0.0f)) continue;
            const Rgb radiance = Rgb(e.r, e.g, e.b) * t;
            // Each point a delta light of its cell's solid angle, (0.25 / side^2) |n_e . l| / r^2.
            for (int k = 0; k < side * side; ++k) {
                const shared::vec3 to = shared::nearEmitterQuarterPoint(e, q, k, side) - p;
                const shared::vec3 l = normalize(to);
                const float solidAngle =
                    0.25f / float(side * side) * std::abs(dot(outward, l)) / dot(to, to);
                seen += bsdfLight(specular, {double(l.x), double(l.y), double(l.z)},
                                  radiance * solidAngle, 0.0);
            }
        }
        sum += seen * weight;
    }
    return sum;
}

Rgb nearEmitterHighlight(const RadianceCascades::State& state, const Hit& hit,
                         const PathBsdf& specular) {
    NearEmitterRays rays(state, hit);
    return nearEmitterHighlight(state, rays, specular);
}

float nearEmitterShare(const RadianceCascades::State& state, const Hit& hit, int face, Int3 voxel,
                       Int3 normal) {
    const FaceData& faces = state.faces;
    if (faces.nearOffset.empty() || face < 0) return 0.0f;
    const std::uint32_t met = std::uint32_t(normalIndex(normal));
    for (std::uint32_t i = faces.nearOffset[face]; i < faces.nearOffset[face + 1]; ++i) {
        const shared::CascadeNearEmitter& e = faces.nearEmitters[i];
        if (e.x != voxel.x || e.y != voxel.y || e.z != voxel.z || e.normal != met) continue;
        const shared::vec3 p(float(hit.point.x), float(hit.point.y), float(hit.point.z));
        return shared::nearEmitterWeight(length(p - shared::nearEmitterPoint(e, -1)),
                                         LUXEL_NEAR_EMITTER_INNER, LUXEL_NEAR_EMITTER_OUTER);
    }
    return 0.0f;
}

}  // namespace luxel::voxel::cascades
