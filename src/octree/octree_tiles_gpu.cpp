#include "luxel/octree/octree_tiles_gpu.h"

#include <algorithm>
#include <span>
#include <string>

#include "gpu/shaders/shared/octree_tiles_layout.h"
#include "luxel/core/memory.h"
#include "octree/octree_render_params.h"
#include "octree/octree_tiles_state.h"

namespace luxel::octree {

namespace shared = gpu::shared;

struct OctreeTilesGpu::State {
    gpu::Context* context = nullptr;
    gpu::Program* program = nullptr;
    std::shared_ptr<gpu::Buffer> nodes;
    std::shared_ptr<gpu::Buffer> colours;     // one uint per entry or leaf, or one dummy
    std::shared_ptr<gpu::Buffer> leafCounts;  // one uint per octant (LeafOrder), or one dummy
    std::shared_ptr<gpu::Buffer> params;
    Octree shape;  // depth and size only: what renderParams reads
    bool hasColours = false;
    bool leafOrder = false;
};

OctreeTilesGpu::OctreeTilesGpu(std::unique_ptr<State> state) : state_(std::move(state)) {}
OctreeTilesGpu::OctreeTilesGpu(OctreeTilesGpu&&) noexcept = default;
OctreeTilesGpu& OctreeTilesGpu::operator=(OctreeTilesGpu&&) noexcept = default;
OctreeTilesGpu::~OctreeTilesGpu() = default;

Result<OctreeTilesGpu> OctreeTilesGpu::create(gpu::Context& context, const Octree& tree) {
    const std::uint64_t colourWords = tree.hasColours() ? tree.colours.size() : 1;
    const std::uint64_t countWords = tree.leafOrder() ? tree.leafCounts.size() : 1;
    const std::uint64_t bytes =
        (tree.nodes.size() + colourWords + countWords) * sizeof(std::uint32_t) +
        sizeof(shared::OctreeRenderParams);
    const std::uint64_t limit = context.device().deviceLocalBytes;
    if (limit > 0 && bytes > limit) {
        return Error("octree of " + formatBytes(bytes) + " does not fit the device's " +
                     formatBytes(limit));
    }
    auto state = std::make_unique<State>();
    state->context = &context;
    state->shape.depth = tree.depth;
    state->shape.size = tree.size;
    state->hasColours = tree.hasColours();
    state->leafOrder = tree.leafOrder();
    auto program = context.program("octree_tiles", 6, sizeof(shared::OctreeTilesPush));
    if (!program) return program.error();
    state->program = *program;
    auto nodes = context.createBuffer(tree.nodes.size() * sizeof(std::uint32_t));
    if (!nodes) return nodes.error();
    state->nodes = std::move(*nodes);
    if (Status s = context.upload(*state->nodes, std::as_bytes(std::span(tree.nodes))); !s) {
        return s.error();
    }
    std::vector<std::uint32_t> packed(colourWords, 0);
    for (std::size_t i = 0; i < tree.colours.size(); ++i) {
        const Colour& c = tree.colours[i];
        packed[i] = std::uint32_t{c.r} | std::uint32_t{c.g} << 8 | std::uint32_t{c.b} << 16 |
                    std::uint32_t{c.a} << 24;
    }
    auto colours = context.createBuffer(packed.size() * sizeof(std::uint32_t));
    if (!colours) return colours.error();
    state->colours = std::move(*colours);
    if (Status s = context.upload(*state->colours, std::as_bytes(std::span(packed))); !s) {
        return s.error();
    }
    const std::uint32_t dummy[1] = {0};
    const auto counts =
        tree.leafOrder() ? std::span<const std::uint32_t>(tree.leafCounts) : std::span(dummy);
    auto leafCounts = context.createBuffer(counts.size() * sizeof(std::uint32_t));
    if (!leafCounts) return leafCounts.error();
    state->leafCounts = std::move(*leafCounts);
    if (Status s = context.upload(*state->leafCounts, std::as_bytes(counts)); !s) {
        return s.error();
    }
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
    shared::OctreeRenderParams p = renderParams(s.shape, camera, surface);
    if (s.hasColours) p.flags |= LUXEL_OCTREE_COLOURS;
    if (s.leafOrder) p.flags |= LUXEL_OCTREE_LEAF_ORDER;
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
    const int depth = s.shape.depth;
    const int count = tilePassCount(depth, tiles.tileBits);
    const int run = tiles.passes > 0 ? std::min(tiles.passes, count) : count;
    std::vector<gpu::Dispatch> dispatches(static_cast<std::size_t>(run));
    for (int pass = 0; pass < run; ++pass) {
        gpu::Dispatch& d = dispatches[static_cast<std::size_t>(pass)];
        d.name = "octree tiles pass " + std::to_string(pass);
        d.program = s.program;
        d.buffers = {s.params.get(), s.nodes.get(), s.colours.get(),
                     states->get(),  output->get(), s.leafCounts.get()};
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
