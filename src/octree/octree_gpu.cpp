#include "luxel/octree/octree_gpu.h"

#include <algorithm>

#include "gpu/shaders/shared/octree_layout.h"
#include "luxel/core/memory.h"
#include "luxel/octree/octree_tiles_gpu.h"
#include "octree/octree_access.h"
#include "octree/octree_device_arrays.h"
#include "octree/octree_render_params.h"
#include "voxel/cast_batch.h"

namespace luxel::octree {

namespace shared = gpu::shared;

struct OctreeGpu::State {
    gpu::Context* context = nullptr;
    gpu::Program* castProgram = nullptr;
    gpu::Program* renderProgram = nullptr;
    gpu::Program* lightProgram = nullptr;
    OctreeDeviceArrays arrays;
    std::unique_ptr<OctreeTilesGpu> tiles;  // the tiles mode's passes, made on first use
    std::shared_ptr<gpu::Buffer> params;
    // The light cache of the last scattering render, kept while its light is unchanged.
    std::shared_ptr<gpu::Buffer> lightCache;  // or one dummy float
    std::uint32_t lightStride = 0;            // 0: lightCache holds nothing
    float lightSun[3] = {0, 0, 0};
    float lightOpacityScale = 0;
    std::uint32_t lightWindow[2] = {0, 0};
    std::uint64_t lightCacheBytes = sizeof(float);

    Result<shared::OctreeRenderParams> uploadParams(const voxel::Camera& camera,
                                                    const OctreeRenderOptions& options);
    Status prepareLightCache(const shared::OctreeRenderParams& p,
                             std::vector<gpu::Dispatch>& passes);
    std::uint64_t bytes = 0;
};

OctreeGpu::OctreeGpu(std::unique_ptr<State> state) : state_(std::move(state)) {}
OctreeGpu::OctreeGpu(OctreeGpu&&) noexcept = default;
OctreeGpu& OctreeGpu::operator=(OctreeGpu&&) noexcept = default;
OctreeGpu::~OctreeGpu() = default;

std::uint64_t OctreeGpu::deviceBytes() const {
    return state_ ? state_->bytes : 0;
}

Result<OctreeGpu> OctreeGpu::create(gpu::Context& context, const Octree& tree) {
    // The parameters and the light cache's dummy word come with the arrays.
    const std::uint64_t extra = sizeof(shared::OctreeRenderParams) + sizeof(float);
    auto arrays = uploadOctreeArrays(context, tree, extra);
    if (!arrays) return arrays.error();
    auto state = std::make_unique<State>();
    state->context = &context;
    state->arrays = std::move(*arrays);
    auto program = context.program("octree_cast", 4, sizeof(shared::OctreeCastPush));
    if (!program) return program.error();
    state->castProgram = *program;
    auto renderProgram = context.program("octree_render", 6, 0);
    if (!renderProgram) return renderProgram.error();
    state->renderProgram = *renderProgram;
    auto lightProgram = context.program("octree_light_cache", 4, 0);
    if (!lightProgram) return lightProgram.error();
    state->lightProgram = *lightProgram;
    auto lightCache = context.createBuffer(sizeof(float));
    if (!lightCache) return lightCache.error();
    state->lightCache = std::move(*lightCache);
    auto params = context.createBuffer(sizeof(shared::OctreeRenderParams));
    if (!params) return params.error();
    state->params = std::move(*params);
    state->bytes = state->arrays.bytes + extra;
    return OctreeGpu(std::move(state));
}

// Makes s.lightCache hold the cache `p` reads (p.lightStride != 0), adding its fill pass to
// `passes` unless the one already there was traced under the same light. `p` is uploaded.
Status OctreeGpu::State::prepareLightCache(const shared::OctreeRenderParams& p,
                                           std::vector<gpu::Dispatch>& passes) {
    State& s = *this;
    if (p.lightStride == 0) return Ok{};
    if (s.lightStride == p.lightStride && s.lightSun[0] == p.sunX && s.lightSun[1] == p.sunY &&
        s.lightSun[2] == p.sunZ && s.lightOpacityScale == p.opacityScale &&
        s.lightWindow[0] == p.windowLow && s.lightWindow[1] == p.windowHigh) {
        return Ok{};
    }
    if (Status st = checkLightCacheSize(p); !st) return st;
    const std::uint64_t corners = shared::octreeLightCacheCorners(p);
    if (s.lightCacheBytes < corners * sizeof(float)) {
        auto buffer = s.context->createBuffer(corners * sizeof(float));
        if (!buffer) return buffer.error();
        s.bytes += corners * sizeof(float) - s.lightCacheBytes;
        s.lightCacheBytes = corners * sizeof(float);
        s.lightCache = std::move(*buffer);
    }
    gpu::Dispatch d;
    d.name = "octree light cache";
    d.program = s.lightProgram;
    d.buffers = {s.params.get(), s.arrays.nodes.get(), s.arrays.leafCounts.get(),
                 s.lightCache.get()};
    d.setLinearThreads(corners);
    passes.push_back(std::move(d));
    s.lightStride = p.lightStride;
    s.lightSun[0] = p.sunX, s.lightSun[1] = p.sunY, s.lightSun[2] = p.sunZ;
    s.lightOpacityScale = p.opacityScale;
    s.lightWindow[0] = p.windowLow, s.lightWindow[1] = p.windowHigh;
    return Ok{};
}

// Uploads the parameters of a render (camera and options) with the tree's flags.
Result<shared::OctreeRenderParams> OctreeGpu::State::uploadParams(
    const voxel::Camera& camera, const OctreeRenderOptions& options) {
    State& s = *this;
    if (Status st = validateRenderOptions(options); !st) return st.error();
    shared::OctreeRenderParams p = renderParams(s.arrays.shape, camera, options);
    if (s.arrays.hasColours) p.flags |= LUXEL_OCTREE_COLOURS;
    if (s.arrays.leafOrder) p.flags |= LUXEL_OCTREE_LEAF_ORDER;
    if (Status st = s.context->upload(*s.params, std::as_bytes(std::span(&p, 1))); !st) {
        return st.error();
    }
    return p;
}

Result<std::vector<float>> OctreeGpu::lightCache(const OctreeRenderOptions& options,
                                                 std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    auto camera = voxel::Camera::lookAt({0, 0, -1}, {0, 0, 0}, 60, 1, 1);
    if (!camera) return camera.error();
    auto p = s.uploadParams(*camera, options);
    if (!p) return p.error();
    if (p->lightStride == 0) return std::vector<float>{};
    if (Status st = checkLightCacheSize(*p); !st) return st.error();
    s.lightStride = 0;  // always run the pass: this is its single-pass entry
    std::vector<gpu::Dispatch> passes;
    if (Status st = s.prepareLightCache(*p, passes); !st) return st.error();
    auto ran = s.context->run(passes);
    if (!ran) return ran.error();
    if (timings) timings->insert(timings->end(), ran->begin(), ran->end());
    std::vector<float> values(shared::octreeLightCacheCorners(*p));
    if (Status st = s.context->download(*s.lightCache, std::as_writable_bytes(std::span(values)));
        !st) {
        return st.error();
    }
    return values;
}

Result<Image> OctreeGpu::render(const voxel::Camera& camera, const OctreeRenderOptions& options,
                                std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    if (options.mode == OctreeMode::Tiles) {
        if (!s.tiles) {
            auto tiles = OctreeTilesGpu::create(*s.context, s.arrays);
            if (!tiles) return tiles.error();
            s.tiles = std::make_unique<OctreeTilesGpu>(std::move(*tiles));
        }
        auto rendered = s.tiles->render(camera, options, {}, timings);
        if (!rendered) return rendered.error();
        return std::move(rendered->image);
    }
    const std::uint64_t pixels = static_cast<std::uint64_t>(camera.width()) * camera.height();
    if (Status st = checkMemory(pixels * sizeof(shared::VoxelPixel), "an octree image"); !st) {
        return st.error();
    }
    auto p = s.uploadParams(camera, options);
    if (!p) return p.error();
    std::vector<gpu::Dispatch> passes;
    if (Status st = s.prepareLightCache(*p, passes); !st) return st.error();
    auto output = s.context->createBuffer(pixels * sizeof(shared::VoxelPixel));
    if (!output) return output.error();
    gpu::Dispatch d;
    d.name = "octree render";
    d.program = s.renderProgram;
    d.buffers = {s.params.get(), s.arrays.nodes.get(),      s.arrays.colours.get(),
                 output->get(),  s.arrays.leafCounts.get(), s.lightCache.get()};
    d.setThreads(static_cast<std::uint64_t>(camera.width()),
                 static_cast<std::uint64_t>(camera.height()));
    passes.push_back(std::move(d));
    auto ran = s.context->run(passes);
    if (!ran) {
        s.lightStride = 0;  // the fill may not have run
        return ran.error();
    }
    if (timings) timings->insert(timings->end(), ran->begin(), ran->end());
    std::vector<shared::VoxelPixel> out(pixels);
    if (Status st = s.context->download(**output, std::as_writable_bytes(std::span(out))); !st) {
        return st.error();
    }
    Image image(camera.width(), camera.height(), 3);
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const shared::VoxelPixel& px = out[static_cast<std::size_t>(y) * camera.width() + x];
            image.setRgb(x, y, Rgb(px.r, px.g, px.b));
        }
    }
    return image;
}

Result<std::vector<OctreeHit>> OctreeGpu::castRays(std::span<const voxel::Ray> rays,
                                                   const TraceOptions& options,
                                                   std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    std::vector<OctreeHit> hits(rays.size());
    if (rays.empty()) return hits;
    const std::vector<shared::VoxelCastRay> in = voxel::castRaysForGpu(rays, options.tMax, true);
    auto rayBuffer = s.context->createBuffer(in.size() * sizeof(shared::VoxelCastRay));
    if (!rayBuffer) return rayBuffer.error();
    auto hitBuffer = s.context->createBuffer(rays.size() * sizeof(shared::VoxelCastHit));
    if (!hitBuffer) return hitBuffer.error();
    if (Status st = s.context->upload(**rayBuffer, std::as_bytes(std::span(in))); !st) {
        return st.error();
    }
    const Int3 size = s.arrays.shape.extent();
    const int cap = options.stepCap > 0 ? options.stepCap : 3 * (size.x + size.y + size.z);
    gpu::Dispatch d;
    d.name = "octree cast rays";
    d.program = s.castProgram;
    d.buffers = {s.arrays.nodes.get(), rayBuffer->get(), hitBuffer->get(),
                 s.arrays.leafCounts.get()};
    d.setPush(shared::OctreeCastPush{
        static_cast<std::uint32_t>(rays.size()), static_cast<std::uint32_t>(cap),
        static_cast<std::uint32_t>(s.arrays.shape.depth),
        std::max<std::uint32_t>(options.threshold, 1), static_cast<std::uint32_t>(size.x),
        static_cast<std::uint32_t>(size.y), static_cast<std::uint32_t>(size.z),
        s.arrays.leafOrder ? LUXEL_OCTREE_LEAF_ORDER : 0u});
    d.setLinearThreads(rays.size());
    auto out = voxel::runCastPass(*s.context, d, **hitBuffer, rays.size(), timings);
    if (!out) return out.error();
    for (std::size_t i = 0; i < out->size(); ++i) {
        const shared::VoxelCastHit& o = (*out)[i];
        hits[i] = {voxel::hitFromGpu(o), o.entry, o.pad0};  // pad0: colour index
    }
    return hits;
}

}  // namespace luxel::octree
