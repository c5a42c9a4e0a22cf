// The memory a render needs, estimated once for `luxel render` (which refuses before allocating)
// and `luxel info` (which reports the same refusal), so both say the same thing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "luxel/core/error.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/post/post_options.h"

namespace luxel::cli {

// A 2D render at width x height: the medium, the solver's buffers (its fluence included), what
// writing the images needs once the solver's buffers are gone (the fluence, auto exposure's list,
// the writers' strips: render_outputs.h), and with bounce light the albedo images, the medium
// re-lit by the bounced source and the source images. The solve and the writing do not overlap.
struct Memory2D {
    std::uint64_t medium = 0, solver = 0, outputs = 0, bounce = 0;
    std::uint64_t total() const { return medium + bounce + std::max(solver, outputs); }
};
Memory2D estimate2D(int width, int height, gi2d::Solver2D solver, const gi2d::RcOptions& rc,
                    bool bounces = false);

// The host memory of a voxel or octree frame at the camera's width x height with `post` (its
// internal scale included); `gpu` adds the download of a GPU frame. The scene itself is already
// loaded when this is asked, so it is not counted.
std::uint64_t frameBytes(int width, int height, const post::PostOptions& post, bool gpu);

// "rendering WxH<detail> needs X, only Y is available" when `needed` does not fit.
Status checkRenderMemory(int width, int height, std::uint64_t needed,
                         const std::string& detail = "");

}  // namespace luxel::cli
