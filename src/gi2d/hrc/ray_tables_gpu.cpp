// GPU ray extension (shader src/gpu/shaders/gi2d/hrc_extend.comp.glsl) for one cascade level.
#include <cstring>

#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/ray_tables.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "luxel/gpu/context.h"

namespace luxel::gi2d::hrc {

Result<double> extendLevelOnGpu(gpu::Context& context, RayTables& tables, int n) {
    LUXEL_CHECK(n >= 1 && n < tables.levels());
    const std::span<std::uint16_t> below = tables.levelHalves(n - 1);
    const std::span<std::uint16_t> above = tables.levelHalves(n);
    auto belowBuffer = context.createBuffer(below.size_bytes());
    if (!belowBuffer) return belowBuffer.error();
    auto aboveBuffer = context.createBuffer(above.size_bytes());
    if (!aboveBuffer) return aboveBuffer.error();
    if (Status s = context.upload(**belowBuffer, std::as_bytes(below)); !s) return s.error();

    auto program = context.program("hrc_extend", 2, sizeof(gpu::shared::HrcExtendParams));
    if (!program) return program.error();
    const gpu::shared::HrcExtendParams params{static_cast<std::uint32_t>(n),
                                              static_cast<std::uint32_t>(tables.rows()),
                                              static_cast<std::uint32_t>(tables.planes(n - 1)),
                                              static_cast<std::uint32_t>(tables.planes(n))};
    gpu::Dispatch dispatch;
    dispatch.name = "hrc_extend T" + std::to_string(n);
    dispatch.program = *program;
    dispatch.buffers = {belowBuffer->get(), aboveBuffer->get()};
    dispatch.setPush(params);
    dispatch.setThreads(static_cast<std::uint64_t>(tables.rows()), pow2(n) + 1,
                        static_cast<std::uint64_t>(tables.planes(n)));
    auto timings = context.run(std::span<const gpu::Dispatch>(&dispatch, 1));
    if (!timings) return timings.error();
    if (Status s = context.download(**aboveBuffer, std::as_writable_bytes(above)); !s) {
        return s.error();
    }
    return timings->front().milliseconds;
}

}  // namespace luxel::gi2d::hrc
