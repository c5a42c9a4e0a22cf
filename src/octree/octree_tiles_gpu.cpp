#include "luxel/octree/octree_tiles_gpu.h"

#include <algorithm>
#include <span>
#include <string>

#include "gpu/shaders/shared/octree_tiles_layout.h"
#include "luxel/core/memory.h"
#include "octree/octree_device_arrays.h"
#include "octree/octree_render_params.h"
#include "octree/octree_tiles_state.h"

namespace luxel::octree {

namespace shared = gpu::shared;

struct OctreeTilesGpu::State {
    gpu::Context* context = nullptr;
    gpu::Program* program = nullptr;
    OctreeDeviceArrays arrays;
    std::shared_ptr<gpu::Buffer> params;
};

OctreeTilesGpu::OctreeTilesGpu(std::unique_ptr<State> state) : state_(std::move(state)) {}
OctreeTilesGpu::OctreeTilesGpu(OctreeTilesGpu&&) noexcept = default;
OctreeTilesGpu& OctreeTilesGpu::operator=(OctreeTilesGpu&&) noexcept = default;
OctreeTilesGpu::~OctreeTilesGpu() = default;

Result<OctreeTilesGpu> OctreeTilesGpu::create(gpu::Context& context, const Octree& tree) {
    auto arrays = uploadOctreeArrays(context, tree, sizeof(shared::OctreeRenderParams));
    if (!arrays) return arrays.error();
    return create(context, *arrays);
}

Result<OctreeTilesGpu> OctreeTilesGpu::create(gpu::Context& context,
                                              const OctreeDeviceArrays& arrays) {
    auto state = std::make_unique<State>();
    state->context = &context;
    state->arrays = arrays;
    auto program = context.program("octree_tiles", 6, sizeof(shared::OctreeTilesPush));
    if (!program) return program.error();
    state->program = *program;
    auto params = context.createBuffer(sizeof(shared::OctreeRenderParams));
    if (!params) return params.error();
    state->params = std::move(*params);
    return OctreeTilesGpu(std::move(state));
}

Result<TileRender> OctreeTilesGpu::render(const voxel::Camera& camera,
                                          const OctreeRenderOptions& options,
                                          const TileOptions& tiles,
                                          std::vector<gpu::PassTiming>* timings) {
    if (Status s = validateRenderOptions(options); !s) return s.error();
    if (Status s = validateTileOptions(tiles); !s) return s.error();
    State& s = *state_;
    OctreeRenderOptions surface = options;
    surface.mode = OctreeMode::Surface;
    shared::OctreeRenderParams p = renderParams(s.arrays.shape, camera, surface);
    if (s.arrays.hasColours) p.flags |= LUXEL_OCTREE_COLOURS;
    if (s.arrays.leafOrder) p.flags |= LUXEL_OCTREE_LEAF_ORDER;
    const std::uint64_t pixels = static_cast<std::uint64_t>(camera.width()) * camera.height();
    const std::uint64_t bytes =
        pixels * (sizeof(shared::VoxelPixel) + 2 * sizeof(shared::OctreeTileState));
    if (Status st = checkMemory(bytes, "a tile render"); !st) return st.error();
    if (Status st = s.context->upload(*s.params, std::as_bytes(std::span(&p, 1))); !st) {
        return st.error();
    }
    auto states = s.context->createBuffer(pixels * sizeof(shared::OctreeTileState));
    if (!states) return states.error();
    auto output = s.context->createBuffer(pixels * sizeof(shared::VoxelPixel));
    if (!output) return output.error();
    const int depth = s.arrays.shape.depth;
    const int count = tilePassCount(depth, tiles.tileBits);
    const int run = tiles.passes > 0 ? std::min(tiles.passes, count) : count;
    std::vector<gpu::Dispatch> dispatches(static_cast<std::size_t>(run));
    for (int pass = 0; pass < run; ++pass) {
        gpu::Dispatch& d = dispatches[static_cast<std::size_t>(pass)];
        d.name = "octree tiles pass " + std::to_string(pass);
        d.program = s.program;
        d.buffers = {s.params.get(), s.arrays.nodes.get(), s.arrays.colours.get(),
                     states->get(),  output->get(),        s.arrays.leafCounts.get()};
        const int parent = pass == 0 ? depth : tilePassLevel(depth, tiles.tileBits, pass - 1);
        d.setPush(shared::OctreeTilesPush{
            static_cast<std::uint32_t>(pass),
            static_cast<std::uint32_t>(tilePassLevel(depth, tiles.tileBits, pass)),
            static_cast<std::uint32_t>(parent), pass == run - 1 ? 1u : 0u});
        d.setThreads(static_cast<std::uint64_t>(camera.width()),
                     static_cast<std::uint64_t>(camera.height()));
    }
    auto passes = s.context->run(dispatches);
    if (!passes) return passes.error();
    if (timings) timings->insert(timings->end(), passes->begin(), passes->end());
    std::vector<shared::VoxelPixel> colours(pixels);
    if (Status st = s.context->download(**output, std::as_writable_bytes(std::span(colours)));
        !st) {
        return st.error();
    }
    std::vector<shared::OctreeTileState> found(pixels);
    if (Status st = s.context->download(**states, std::as_writable_bytes(std::span(found))); !st) {
        return st.error();
    }
    TileRender out{Image(camera.width(), camera.height(), 3), std::vector<TilePixel>(pixels)};
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * camera.width() + x;
            out.image.setRgb(x, y, Rgb(colours[i].r, colours[i].g, colours[i].b));
            out.pixels[i] = tilePixelOf(found[i]);
        }
    }
    return out;
}

}  // namespace luxel::octree
