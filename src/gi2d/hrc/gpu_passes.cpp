#include "gi2d/hrc/gpu_passes.h"

#include <memory>

#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/near_field.h"
#include "gi2d/medium_gpu.h"
#include "gpu/shaders/shared/hrc_layout.h"

namespace luxel::gi2d::hrc {
namespace {

namespace shared = gpu::shared;

std::uint32_t u32(int v) {
    return static_cast<std::uint32_t>(v);
}

template <typename T>
std::span<const std::byte> bytesOf(std::span<T> s) {
    return std::as_bytes(s);
}

// Device buffers of one single-pass run, freed when it returns.
struct Scratch {
    gpu::Context& context;
    std::vector<std::shared_ptr<gpu::Buffer>> held;

    Result<gpu::Buffer*> upload(std::span<const std::byte> bytes) {
        auto b = context.createBuffer(std::max<std::uint64_t>(bytes.size(), 4));
        if (!b) return b.error();
        if (!bytes.empty()) {
            if (Status s = context.upload(**b, bytes); !s) return s.error();
        }
        held.push_back(*b);
        return held.back().get();
    }
    Result<gpu::Buffer*> create(std::uint64_t bytes) {
        auto b = context.createBuffer(std::max<std::uint64_t>(bytes, 4));
        if (!b) return b.error();
        held.push_back(*b);
        return held.back().get();
    }
};

Result<double> runOne(gpu::Context& context, const gpu::Dispatch& dispatch) {
    auto timings = context.run(std::span<const gpu::Dispatch>(&dispatch, 1));
    if (!timings) return timings.error();
    return timings->front().milliseconds;
}

std::span<const std::byte> coneBytes(const ConeBuffer& c) {
    return std::as_bytes(c.halves());
}

}  // namespace

bool traceReadsTransposed(const FrustumFrame& frame) {
    return frame.frustum == Frustum::PlusX || frame.frustum == Frustum::MinusX;
}

gpu::Dispatch makeTraceDispatch(gpu::Program* program, gpu::Buffer* medium, gpu::Buffer* table,
                                int n, const FrustumFrame& frame, int planes, float depthScale) {
    gpu::Dispatch d;
    d.name = "trace T" + std::to_string(n);
    d.program = program;
    d.buffers = {medium, table};
    d.setPush(shared::HrcTraceParams{u32(n), u32(frame.rows), u32(planes), u32(frame.length),
                                     u32(static_cast<int>(frame.frustum)), u32(frame.canvasWidth),
                                     u32(frame.canvasHeight), traceReadsTransposed(frame) ? 1u : 0u,
                                     depthScale});
    d.setThreads(u32(frame.rows), pow2(n) + 1, u32(planes));
    return d;
}

gpu::Dispatch makeExtendDispatch(gpu::Program* program, gpu::Buffer* below, gpu::Buffer* table,
                                 int n, int rows, int planesBelow, int planes) {
    gpu::Dispatch d;
    d.name = "extend T" + std::to_string(n);
    d.program = program;
    d.buffers = {below, table};
    d.setPush(shared::HrcExtendParams{u32(n), u32(rows), u32(planesBelow), u32(planes)});
    d.setThreads(u32(rows), pow2(n) + 1, u32(planes));
    return d;
}

gpu::Dispatch makeMergeDispatch(gpu::Program* program, gpu::Buffer* table, gpu::Buffer* upper,
                                gpu::Buffer* out, gpu::Buffer* weights, gpu::Buffer* nearLights,
                                int n, const FrustumFrame& frame, int planes, int upperPlanes,
                                Rgb sky) {
    gpu::Dispatch d;
    d.name = "merge R" + std::to_string(n);
    d.program = program;
    const int rows = frame.rows;
    // The top cascade reads no upper buffer; the output is bound twice then (never read). Without
    // a mask the weights stand in for it (never read).
    d.buffers = {table, upper ? upper : out, out, weights, nearLights ? nearLights : weights};
    d.setPush(shared::HrcMergeParams{u32(n), u32(rows), u32(planes), upper ? u32(upperPlanes) : 0u,
                                     upper ? 1u : 0u, sky.r, sky.g, sky.b,
                                     u32(static_cast<int>(frame.frustum)), u32(frame.canvasWidth),
                                     u32(frame.canvasHeight), nearLights ? 1u : 0u});
    // Two rows per invocation: a 32-bit word holds two rows of binary16 cones (hrc_layout.h).
    d.setThreads((u32(rows) + 1) / 2, pow2(n), u32(planes));
    return d;
}

gpu::Dispatch makeReadoutDispatch(gpu::Program* program, gpu::Buffer* cones, gpu::Buffer* beyond,
                                  const FrustumFrame& frame, Rgb sky) {
    gpu::Dispatch d;
    d.name = "readout";
    d.program = program;
    d.buffers = {cones, beyond};
    d.setPush(shared::HrcReadoutParams{static_cast<std::uint32_t>(frame.frustum), u32(frame.length),
                                       u32(frame.rows), u32(frame.canvasWidth),
                                       u32(frame.canvasHeight), sky.r, sky.g, sky.b});
    d.setThreads(u32(frame.length), u32(frame.rows));
    return d;
}

gpu::Dispatch makeFinishDispatch(gpu::Program* program, gpu::Buffer* canvasMedium,
                                 gpu::Buffer* beyond, gpu::Buffer* fluence, int width, int height,
                                 int frustums, bool blur) {
    gpu::Dispatch d;
    d.name = "finish";
    d.program = program;
    d.buffers = {canvasMedium, beyond, fluence};
    d.setPush(shared::HrcFinishParams{u32(width), u32(height), u32(frustums), blur ? 1u : 0u});
    d.setThreads(u32(width), u32(height));
    return d;
}

gpu::Dispatch makeNearFieldDispatch(gpu::Program* program, gpu::Buffer* canvasMedium,
                                    gpu::Buffer* pixels, gpu::Buffer* fluence, int width,
                                    int height, std::uint32_t count, Rgb sky, float reach) {
    gpu::Dispatch d;
    d.name = "near field";
    d.program = program;
    d.buffers = {canvasMedium, pixels, fluence};
    d.setPush(shared::HrcNearFieldParams{u32(width), u32(height), count, u32(kNearFieldRays),
                                         kNearFieldCutoff, sky.r, sky.g, sky.b, reach});
    d.setLinearThreads(std::uint64_t{count} * kNearFieldRays);  // a workgroup per pixel
    return d;
}

gpu::Dispatch makeTransposeDispatch(gpu::Program* program, gpu::Buffer* rows, gpu::Buffer* columns,
                                    int width, int height) {
    gpu::Dispatch d;
    d.name = "medium transpose";
    d.program = program;
    d.buffers = {rows, columns};
    d.setPush(shared::MediumTransposeParams{u32(width), u32(height), 0, 0});
    d.setThreads(u32(width), u32(height));
    return d;
}

Result<double> traceLevelOnGpu(gpu::Context& context, const Medium2D& medium,
                               const FrustumFrame& frame, RayTables& tables, int n,
                               float depthScale) {
    LUXEL_CHECK(n >= 0 && n < tables.levels());
    auto program = context.program("hrc_trace", 2, sizeof(shared::HrcTraceParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    const auto packed = packMediumForGpu(medium, traceReadsTransposed(frame));
    auto canvasMedium = scratch.upload(std::as_bytes(std::span(packed)));
    if (!canvasMedium) return canvasMedium.error();
    const std::span<std::uint16_t> table = tables.levelHalves(n);
    auto tableBuffer = scratch.create(table.size_bytes());
    if (!tableBuffer) return tableBuffer.error();
    auto ms = runOne(context, makeTraceDispatch(*program, *canvasMedium, *tableBuffer, n, frame,
                                                tables.planes(n), depthScale));
    if (!ms) return ms;
    if (Status s = context.download(**tableBuffer, std::as_writable_bytes(table)); !s) {
        return s.error();
    }
    return ms;
}

Result<double> extendLevelOnGpu(gpu::Context& context, RayTables& tables, int n) {
    LUXEL_CHECK(n >= 1 && n < tables.levels());
    auto program = context.program("hrc_extend", 2, sizeof(shared::HrcExtendParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto below = scratch.upload(bytesOf(tables.levelHalves(n - 1)));
    if (!below) return below.error();
    const std::span<std::uint16_t> table = tables.levelHalves(n);
    auto tableBuffer = scratch.create(table.size_bytes());
    if (!tableBuffer) return tableBuffer.error();
    auto ms = runOne(context, makeExtendDispatch(*program, *below, *tableBuffer, n, tables.rows(),
                                                 tables.planes(n - 1), tables.planes(n)));
    if (!ms) return ms;
    if (Status s = context.download(**tableBuffer, std::as_writable_bytes(table)); !s) {
        return s.error();
    }
    return ms;
}

Result<double> mergeCascadeOnGpu(gpu::Context& context, const RayTables& tables, int n,
                                 const ConeBuffer* upper, Rgb sky, ConeBuffer& out,
                                 const MergeNearLights& nearLights) {
    LUXEL_CHECK(n >= 0 && n + 1 < tables.levels() + 1);
    auto program = context.program("hrc_merge", 5, sizeof(shared::HrcMergeParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto table = scratch.upload(bytesOf(tables.levelHalves(n)));
    if (!table) return table.error();
    const std::vector<float> weights = coneWeights(n);
    auto weightBuffer = scratch.upload(std::as_bytes(std::span(weights)));
    if (!weightBuffer) return weightBuffer.error();
    Result<gpu::Buffer*> upperBuffer = static_cast<gpu::Buffer*>(nullptr);
    if (upper) upperBuffer = scratch.upload(coneBytes(*upper));
    if (!upperBuffer) return upperBuffer.error();
    Result<gpu::Buffer*> maskBuffer = static_cast<gpu::Buffer*>(nullptr);
    if (nearLights.mask) maskBuffer = scratch.upload(std::as_bytes(nearLights.mask->bytes()));
    if (!maskBuffer) return maskBuffer.error();
    out.reset(tables.planes(n), pow2(n), tables.rows());
    auto outBuffer = scratch.create(out.halves().size_bytes());
    if (!outBuffer) return outBuffer.error();
    // Without a mask only the frame's rows matter.
    FrustumFrame frame = nearLights.frame;
    frame.rows = tables.rows();
    auto ms =
        runOne(context, makeMergeDispatch(*program, *table, *upperBuffer, *outBuffer, *weightBuffer,
                                          *maskBuffer, n, frame, tables.planes(n),
                                          upper ? upper->planes() : 0, sky));
    if (!ms) return ms;
    if (Status s = context.download(**outBuffer, std::as_writable_bytes(out.halves())); !s) {
        return s.error();
    }
    return ms;
}

Result<double> readOutOnGpu(gpu::Context& context, const FrustumFrame& frame,
                            const ConeBuffer& cones, Rgb sky, Image& beyondSum) {
    auto program = context.program("hrc_readout", 2, sizeof(shared::HrcReadoutParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto coneBuffer = scratch.upload(coneBytes(cones));
    if (!coneBuffer) return coneBuffer.error();
    const std::span<float> beyond(beyondSum.data(), beyondSum.size());
    auto beyondBuffer = scratch.upload(std::as_bytes(beyond));
    if (!beyondBuffer) return beyondBuffer.error();
    auto ms =
        runOne(context, makeReadoutDispatch(*program, *coneBuffer, *beyondBuffer, frame, sky));
    if (!ms) return ms;
    if (Status s = context.download(**beyondBuffer, std::as_writable_bytes(beyond)); !s) {
        return s.error();
    }
    return ms;
}

Result<double> finishOnGpu(gpu::Context& context, const Medium2D& medium, const Image& beyond,
                           int frustums, bool blur, Image& fluence) {
    auto program = context.program("hrc_finish", 3, sizeof(shared::HrcFinishParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    const auto packed = packMediumForGpu(medium);
    auto mediumBuffer = scratch.upload(std::as_bytes(std::span(packed)));
    if (!mediumBuffer) return mediumBuffer.error();
    auto beyondBuffer = scratch.upload(std::as_bytes(std::span(beyond.data(), beyond.size())));
    if (!beyondBuffer) return beyondBuffer.error();
    fluence = Image(medium.width(), medium.height(), 3);
    auto out = scratch.create(fluence.size() * sizeof(float));
    if (!out) return out.error();
    auto ms = runOne(context, makeFinishDispatch(*program, *mediumBuffer, *beyondBuffer, *out,
                                                 medium.width(), medium.height(), frustums, blur));
    if (!ms) return ms;
    if (Status s = context.download(
            **out, std::as_writable_bytes(std::span(fluence.data(), fluence.size())));
        !s) {
        return s.error();
    }
    return ms;
}

}  // namespace luxel::gi2d::hrc
