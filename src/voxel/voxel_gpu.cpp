// VoxelGpuRenderer's world: create (buffers, world, textures and the sRGB table uploaded once)
// and updateRegion (edited chunks re-sent); the passes are in voxel_gpu_render.cpp.
#include "luxel/voxel/voxel_gpu.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/tonemap.h"
#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

using voxel_gpu::bytesOf;
using voxel_gpu::chunkCounts;
using voxel_gpu::chunkTotal;
using voxel_gpu::kMaterialBytes;

namespace {

static_assert(sizeof(Voxel) == 4);

// The image size create() budgets for.
constexpr int kBudgetWidth = 1920, kBudgetHeight = 1080;

// One chunk in the GPU layout (VoxelWorld::index): z, then y, then x inside the chunk.
void packChunk(const VoxelWorld& world, int cx, int cy, int cz, std::uint32_t* out) {
    const int n = world.chunkSize();
    for (int lz = 0; lz < n; ++lz) {
        for (int ly = 0; ly < n; ++ly) {
            for (int lx = 0; lx < n; ++lx) {
                const Voxel v = world.get(cx * n + lx, cy * n + ly, cz * n + lz);
                std::uint32_t word;
                std::memcpy(&word, &v, 4);  // r | g << 8 | b << 16 | a << 24 (little endian)
                *out++ = word;
            }
        }
    }
}

}  // namespace

Status VoxelGpuRenderer::State::uploadBricks(const VoxelWorld& world) {
    const Int3 n = world.brickCount();
    const std::uint64_t bricks = chunkTotal(n);
    std::vector<std::uint32_t> masks;
    masks.reserve(bricks * 2);
    for (int bz = 0; bz < n.z; ++bz) {
        for (int by = 0; by < n.y; ++by) {
            for (int bx = 0; bx < n.x; ++bx) {
                const std::uint64_t m = world.brickMask(bx, by, bz);
                masks.push_back(static_cast<std::uint32_t>(m));
                masks.push_back(static_cast<std::uint32_t>(m >> 32));
            }
        }
    }
    reachCurrent = world.emptySpaceCurrent();
    if (Status st = send(*brickMasks, bytesOf(masks), sent.world); !st) return st;
    return send(*brickReach,
                std::as_bytes(std::span(world.brickReachData(), bricks * VoxelWorld::kOctants)),
                sent.world);
}

Status VoxelGpuRenderer::State::uploadChunkSolid(const VoxelWorld& world) {
    std::vector<std::uint32_t> counts(chunkTotal(chunks));
    std::size_t i = 0;
    for (int cz = 0; cz < chunks.z; ++cz) {
        for (int cy = 0; cy < chunks.y; ++cy) {
            for (int cx = 0; cx < chunks.x; ++cx) counts[i++] = world.chunkSolidCount(cx, cy, cz);
        }
    }
    return send(*chunkSolid, bytesOf(counts), sent.world);
}

Status VoxelGpuRenderer::State::uploadChunkRow(const VoxelWorld& world, int cx0, int cx1, int cy,
                                               int cz) {
    const std::size_t perChunk = static_cast<std::size_t>(chunkSize) * chunkSize * chunkSize;
    std::vector<std::uint32_t> words(perChunk * (cx1 - cx0));
    parallelForRange(cx1 - cx0, 1, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            packChunk(world, cx0 + i, cy, cz, words.data() + perChunk * i);
        }
    });
    const std::uint64_t firstChunk =
        (static_cast<std::uint64_t>(cz) * chunks.y + cy) * chunks.x + cx0;
    return send(*voxels, bytesOf(words), sent.world, firstChunk * perChunk * 4);
}

VoxelGpuRenderer::VoxelGpuRenderer(std::unique_ptr<State> state) : state_(std::move(state)) {}
VoxelGpuRenderer::VoxelGpuRenderer(VoxelGpuRenderer&&) noexcept = default;
VoxelGpuRenderer& VoxelGpuRenderer::operator=(VoxelGpuRenderer&&) noexcept = default;
VoxelGpuRenderer::~VoxelGpuRenderer() = default;

std::uint64_t VoxelGpuRenderer::deviceBytes() const {
    return state_ ? state_->bytes + state_->shadowBytes + state_->emitterBytes + state_->outputBytes
                  : 0;
}

const VoxelGpuUploads& VoxelGpuRenderer::uploads() const {
    return state_->sent;
}

std::uint64_t VoxelGpuRenderer::worldGeneration() const {
    return state_->generation;
}

Result<VoxelGpuRenderer> VoxelGpuRenderer::create(gpu::Context& context, const VoxelWorld& world,
                                                  const TextureSet* textures,
                                                  std::uint64_t memoryBudget) {
    const Int3 size = world.size();
    const std::uint64_t needed =
        estimateVoxelGpuMemory(size, world.chunkSize(), textures, kBudgetWidth, kBudgetHeight);
    const std::uint64_t limit = memoryBudget > 0 ? memoryBudget : context.device().deviceLocalBytes;
    if (limit > 0 && needed > limit) {
        return Error("voxel world " + std::to_string(size.x) + "x" + std::to_string(size.y) + "x" +
                     std::to_string(size.z) + " needs " + formatBytes(needed) +
                     " of device memory (with a 1920x1080 image), " +
                     (memoryBudget > 0 ? "the budget is " : "the device has ") +
                     formatBytes(limit));
    }
    auto state = std::make_unique<State>();
    State& s = *state;
    s.context = &context;
    s.size = size;
    s.chunkSize = world.chunkSize();
    s.chunks = chunkCounts(size, s.chunkSize);
    s.textureCount = textures ? textures->size() : 0;
    s.sourceWorld = &world;
    s.sourceTextures = textures;
    s.limit = limit;
    auto program =
        context.program("voxel_render", LUXEL_VOXEL_BUFFERS, sizeof(shared::VoxelBandPush));
    if (!program) return program.error();
    s.program = *program;
    auto castProgram = context.program("voxel_cast", 7, sizeof(shared::VoxelCastPush));
    if (!castProgram) return castProgram.error();
    s.castProgram = *castProgram;
    const std::uint64_t bricks = chunkTotal(world.brickCount());

    const std::uint64_t perChunk =
        static_cast<std::uint64_t>(s.chunkSize) * s.chunkSize * s.chunkSize;
    const std::uint64_t chunks = chunkTotal(s.chunks);
    // Texture table and texels (one dummy entry each when there are none: no empty buffers).
    std::vector<shared::VoxelTextureInfo> infos(std::max(s.textureCount, 1));
    std::vector<Texel> texels;
    for (int i = 0; i < s.textureCount; ++i) {
        const Texture& t = (*textures)[i];
        shared::VoxelTextureInfo& info = infos[i];
        info.texelOffset = static_cast<std::uint32_t>(texels.size());
        info.width = static_cast<std::uint32_t>(t.width);
        info.height = static_cast<std::uint32_t>(t.height);
        info.reflectivity = t.reflectivity.value_or(-1.0f);
        texels.insert(texels.end(), t.texels.begin(), t.texels.end());
        // Mip chains for filtering (texture_sample.glsl).
        info.mipOffset = static_cast<std::uint32_t>(texels.size());
        info.levels = static_cast<std::uint32_t>(textures->mipLevels(i));
        texels.insert(texels.end(), textures->colourMips(i).begin(), textures->colourMips(i).end());
        info.normalOffset = static_cast<std::uint32_t>(texels.size());
        info.hasNormalMap = textures->hasNormalMap(i) ? 1u : 0u;
        texels.insert(texels.end(), textures->normalMips(i).begin(), textures->normalMips(i).end());
    }
    if (texels.empty()) texels.push_back(Texel{});
    std::vector<float> srgb(256);
    for (int i = 0; i < 256; ++i) srgb[i] = srgbToLinear(i / 255.0f);  // albedo() in shading.cpp

    struct Allocation {
        std::shared_ptr<gpu::Buffer>* buffer;
        std::uint64_t bytes;
    };
    for (const Allocation& a :
         {Allocation{&s.params, sizeof(shared::VoxelRenderParams)},
          Allocation{&s.voxels, chunks * perChunk * 4}, Allocation{&s.chunkSolid, chunks * 4},
          Allocation{&s.brickMasks, bricks * 8},
          Allocation{&s.brickReach, bricks * VoxelWorld::kOctants},
          Allocation{&s.textureInfo, infos.size() * sizeof(shared::VoxelTextureInfo)},
          Allocation{&s.texels, texels.size() * 16}, Allocation{&s.srgb, srgb.size() * 4},
          Allocation{&s.materials, kMaterialBytes}}) {
        auto b = context.createBuffer(a.bytes);
        if (!b) return b.error();
        *a.buffer = *b;
        s.bytes += a.bytes;
    }
    // No sun visibility arrays yet: one-word placeholders (ShadowParams for the first).
    ShadowUpload placeholder;
    placeholder.moments = {0}, placeholder.field = {0.0f}, placeholder.levels = {0};
    if (Status st = s.setShadowArrays(placeholder); !st) return st.error();
    if (Status st = s.setEmitterPlaceholders(); !st) return st.error();
    for (int cz = 0; cz < s.chunks.z; ++cz) {
        for (int cy = 0; cy < s.chunks.y; ++cy) {
            if (Status st = s.uploadChunkRow(world, 0, s.chunks.x, cy, cz); !st) return st.error();
        }
    }
    if (Status st = s.uploadChunkSolid(world); !st) return st.error();
    if (Status st = s.uploadBricks(world); !st) return st.error();
    if (Status st = s.send(*s.textureInfo, bytesOf(infos), s.sent.textures); !st) return st.error();
    if (Status st = s.send(*s.texels, bytesOf(texels), s.sent.textures); !st) return st.error();
    if (Status st = s.send(*s.srgb, bytesOf(srgb), s.sent.textures); !st) return st.error();
    return VoxelGpuRenderer(std::move(state));
}

Status VoxelGpuRenderer::updateRegion(const VoxelWorld& world, Int3 min, Int3 maxExclusive) {
    State& s = *state_;
    if (world.size() != s.size || world.chunkSize() != s.chunkSize) {
        return Error("updateRegion: the world is not the one the renderer was created with");
    }
    Int3 lo, hi;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::clamp(min[a], 0, s.size[a]);
        hi[a] = std::clamp(maxExclusive[a], 0, s.size[a]);
        if (lo[a] >= hi[a]) return Ok{};  // nothing inside the world
        lo[a] /= s.chunkSize;
        hi[a] = (hi[a] - 1) / s.chunkSize + 1;
    }
    ++s.generation;  // the device's copy changes from here
    for (int cz = lo.z; cz < hi.z; ++cz) {
        for (int cy = lo.y; cy < hi.y; ++cy) {
            if (Status st = s.uploadChunkRow(world, lo.x, hi.x, cy, cz); !st) return st;
        }
    }
    if (Status st = s.uploadChunkSolid(world); !st) return st;
    s.shadowKey.reset();  // the maps saw the old world
    return s.uploadBricks(world);
}

}  // namespace luxel::voxel
