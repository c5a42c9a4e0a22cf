// Segments of the voxel radiance cascades through glass and water
// (docs/algorithms/voxel-radiance-cascades.md §4.2): a segment that meets a transmissive voxel
// goes on through it along the straight line, as the solvers' sun rays do (solver_sun.h), and
// its chain carries what lies behind, dimmed by the glass's transmittance, plus what the glass
// face it entered sends itself.
//
// Such a segment's code is a passage: kPassage + an index into State::passages, each naming the
// face entered (kBlack: none, the segment started inside the medium), the transmittance through
// the medium (entry lobe weight, Beer-Lambert, 1 - F at the exit) and the code that follows
// (another passage, or a plain code). The GPU reads the same table at the start of its codes
// buffer (cascade_gpu.cpp, src/gpu/shaders/voxel/cascades_chain.glsl).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <vector>

#include "cascade_state.h"

namespace luxel::voxel::cascades {

// A segment as traced: the media it passes (at most kMaxPassages runs: the face each entered,
// or kBlack, and the transmittance through it) and the code it ends in. Only `runs` entries are
// set (no initialisation cost: every segment of the world is traced).
struct SegmentTrace {
    struct Run {
        std::uint32_t face;
        float transmittance[3];
    };
    int runs = 0;
    std::uint32_t end = kVoid;
    Run run[kMaxPassages];
};

// Traces the segment from `start` along `d` for at most `limit` times d (kInfinity: until it
// leaves the world). Without transmissive materials (or with shading.refraction off) it stops at
// the first face, as a plain code. Cutout texels let it through unless `cutouts` is false (then
// a textured voxel stops it whole, as `occluded` does).
SegmentTrace traceSegment(const RadianceCascades::State& state, Vec3d start, Vec3d d, double limit,
                          bool cutouts = true);

// `first` (which ends in kContinue) followed by `then`, in place.
void appendTrace(SegmentTrace& first, const SegmentTrace& then);

// The product of a trace's transmittances.
Rgb traceTransmittance(const SegmentTrace& trace);

// What decides which voxels segments pass and how much gets through: the refraction switch, the
// Fresnel model and each material's transmission, metallic, ior and absorption (empty when
// nothing transmits). The faces and segments are built again when it changes
// (RadianceCascades::setLight, cascade_build.cpp).
std::vector<float> mediaSignature(const ShadeOptions& shading);

// Appends passages from several threads and hands out their codes, within `budget` bytes of
// passages: the vector's capacity grows by doubling as push_back would, clamped so the old and
// the new storage together (the peak while it moves) stay within the budget. A trace that would
// pass it is refused: its code is kBlack, refused() turns true (the cast stops early) and
// reached() is the bytes that would have been needed.
class PassageWriter {
  public:
    PassageWriter(std::vector<Passage>& passages, std::uint64_t budget)
        : passages_(passages), budget_(budget) {}
    // The code of a trace: its end when it passed no medium, else its first passage.
    std::uint32_t codeOf(const SegmentTrace& trace);
    bool refused() const { return refused_.load(std::memory_order_relaxed); }
    std::uint64_t reached() const { return reached_; }

  private:
    // Room for `more` passages within the budget; false (and refused) when there is none.
    bool reserveFor(std::size_t more);

    std::vector<Passage>& passages_;
    std::uint64_t budget_ = 0, reached_ = 0;
    std::atomic<bool> refused_{false};
    std::mutex lock_;
};

}  // namespace luxel::voxel::cascades
