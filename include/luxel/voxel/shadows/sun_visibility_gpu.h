// Sun visibility on the GPU: the arrays a SunVisibility built (moment map, distance field, light
// levels) and its parameters, uploaded once, and a batch pass (shadow_visibility.comp.glsl) that
// evaluates visibility for many surface points with the same lookups the render pass includes
// (src/gpu/shaders/voxel/sun_visibility.glsl). Every method but Exact; Hard traces the distance
// field's solid cells, so it ignores cutout texels (the CPU's hard ray does not).
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gpu/fwd.h"
#include "luxel/voxel/shadows/sun_visibility.h"

namespace luxel::gpu {
class Buffer;
}

namespace luxel::voxel {

class SunVisibilityGpu {
  public:
    // Uploads what `visibility` uses (Hard builds the distance field here). Exact is refused.
    static Result<SunVisibilityGpu> create(gpu::Context& context, const SunVisibility& visibility);
    SunVisibilityGpu(SunVisibilityGpu&&) noexcept;
    SunVisibilityGpu& operator=(SunVisibilityGpu&&) noexcept;
    ~SunVisibilityGpu();

    // V for every query, as SunVisibility::visibility computes it (in float).
    Result<std::vector<float>> evaluate(std::span<const ShadowQuery> queries,
                                        std::vector<gpu::PassTiming>* timings = nullptr);

    // The buffers the render pass binds at 11 (params), 12 (moments), 13 (field), 14 (levels).
    std::array<gpu::Buffer*, 4> buffers() const;

  private:
    struct State;
    explicit SunVisibilityGpu(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace luxel::voxel
