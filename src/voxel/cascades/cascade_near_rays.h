// The visibility lines from one point of the radiance cascades' picture to the emitters near it
// (docs/algorithms/voxel-radiance-cascades.md §4.1, §4.2, §5): nearEmitterLight and
// nearEmitterHighlight aim the same four lines at each emitter's quarter points, so a pixel
// casts each line once, when the first of them asks, and both read it.
#pragma once

#include <cstdint>

#include "cascade_state.h"

namespace luxel::voxel::cascades {

class NearEmitterRays {
  public:
    // `face`: the hit's face id when the caller has it (-1: not a face), else looked up.
    NearEmitterRays(const RadianceCascades::State& state, const Hit& hit, int face = kFindFace);
    static constexpr int kFindFace = -2;

    const Hit& hit() const { return hit_; }
    // The hit's face (-1: not a face, no near list) and its list in faces.nearEmitters.
    int face() const { return face_; }
    std::uint32_t begin() const { return begin_; }
    std::uint32_t end() const { return end_; }
    // The hit point as the near terms take it (float, as on the GPU).
    const gpu::shared::vec3& point() const { return point_; }

    // faceRayTransmittance along the line from the hit point to quarter q (0..3) of near emitter
    // i (begin() <= i < end()), cast the first time it is asked for (the first kKept emitters of
    // the list; later ones are cast at every ask).
    Rgb transmittance(std::uint32_t i, int q);
    // Lines answered so far (cast, or proven clear by the emitter's empty box).
    int cast() const { return cast_; }

  private:
    static constexpr std::uint32_t kKept = 16;
    const RadianceCascades::State& state_;
    Hit hit_;
    int face_ = -1;
    std::uint32_t begin_ = 0, end_ = 0;
    gpu::shared::vec3 point_;
    int cast_ = 0;
    bool provable_ = false;     // lines may be proven clear (EmitterClearBox)
    std::uint64_t known_ = 0;   // bit 4 (i - begin) + q: line cast and kept in seen_
    float seen_[4 * kKept][3];  // left uninitialised: read only where known_ says it was cast
};

}  // namespace luxel::voxel::cascades
