// VoxelGpuRenderer: world and texture upload, per-render parameters, banded dispatches of
// voxel_render.comp.glsl (CPU reference: render() in shading.cpp).
#include "luxel/voxel/voxel_gpu.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <string>

#include "gpu/shaders/shared/texture_filter.h"
#include "gpu/shaders/shared/voxel_layout.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/cast_batch.h"
#include "voxel/material_gpu.h"
#include "voxel/shadows/shadow_upload.h"

namespace luxel::voxel {

namespace shared = gpu::shared;

namespace {

static_assert(LUXEL_VOXEL_MAX_CUTOUTS == kMaxCutoutContinuations);
static_assert(sizeof(Voxel) == 4);
static_assert(int(TextureFilter::Nearest) == LUXEL_TEXTURE_NEAREST &&
              int(TextureFilter::Trilinear) == LUXEL_TEXTURE_TRILINEAR &&
              int(TextureFilter::Anisotropic) == LUXEL_TEXTURE_ANISOTROPIC);

// Rows per dispatch: keeps every dispatch short on slow devices.
constexpr int kBandRows = 64;
// The image size create() budgets for.
constexpr int kBudgetWidth = 1920, kBudgetHeight = 1080;

Int3 chunkCounts(Int3 size, int chunk) {
    return {(size.x + chunk - 1) / chunk, (size.y + chunk - 1) / chunk,
            (size.z + chunk - 1) / chunk};
}

std::uint64_t chunkTotal(Int3 chunks) {
    return static_cast<std::uint64_t>(chunks.x) * chunks.y * chunks.z;
}

// Texels uploaded: each texture, its colour mip chain and its normal chain.
std::uint64_t texelCount(const TextureSet* textures) {
    std::uint64_t n = 0;
    for (int i = 0; textures && i < textures->size(); ++i) {
        n += (*textures)[i].texels.size() + textures->colourMips(i).size() +
             textures->normalMips(i).size();
    }
    return n;
}

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

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span(v));
}

constexpr std::uint64_t kMaterialBytes = LUXEL_VOXEL_MATERIALS * sizeof(shared::VoxelMaterial);

// Placeholders bound at 11..14 when no method needs the shadow arrays: the parameters and one
// word each.
constexpr std::uint64_t kShadowPlaceholderBytes = sizeof(shared::ShadowParams) + 3 * 4;

// What the uploaded shadow arrays were built from.
struct ShadowKey {
    const SunVisibility* given = nullptr;  // options.sunVisibility, or null when built here
    Vec3d direction;
    double angularRadius = 0.0;
    ShadowSettings settings;
    bool matches(const ShadowKey& o) const {
        return given == o.given && direction.x == o.direction.x && direction.y == o.direction.y &&
               direction.z == o.direction.z && angularRadius == o.angularRadius &&
               settings == o.settings;
    }
};

}  // namespace

std::uint64_t estimateVoxelShadowGpuMemory(Int3 size, const ShadowSettings& settings) {
    const std::uint64_t voxels =
        static_cast<std::uint64_t>(std::max(size.x, 0)) * std::max(size.y, 0) * std::max(size.z, 0);
    const ShadowMethod m = settings.method;
    std::uint64_t moments = 4, field = 4, levels = 4;
    if (m == ShadowMethod::Msm || m == ShadowMethod::Vsm || m == ShadowMethod::Blend) {
        const std::uint64_t side = static_cast<std::uint64_t>(std::max(settings.mapSize, 1));
        const bool q = settings.momentStorage == ShadowSettings::MomentStorage::Quantized16;
        moments = side * side * (q ? 8 : 16);
    }
    // Distances, then one nearest-cube feature word per cell (shadow_upload.h).
    if (m == ShadowMethod::Sdf || m == ShadowMethod::Blend) field = voxels * 8;
    if (m == ShadowMethod::FloodFill) levels = (voxels + 3) / 4 * 4;
    return sizeof(shared::ShadowParams) + moments + field + levels;
}

std::uint64_t estimateVoxelGpuMemory(Int3 size, int chunkSize, const TextureSet* textures,
                                     int width, int height) {
    const std::uint64_t chunks = chunkTotal(chunkCounts(size, chunkSize));
    const std::uint64_t perChunk = static_cast<std::uint64_t>(chunkSize) * chunkSize * chunkSize;
    const int slots = textures ? textures->size() : 0;
    const Int3 bricks{(size.x + 3) / 4, (size.y + 3) / 4, (size.z + 3) / 4};
    return chunks * perChunk * 4 + chunks * 4 + chunkTotal(bricks) * (8 + VoxelWorld::kOctants) +
           std::max(slots, 1) * sizeof(shared::VoxelTextureInfo) +
           std::max<std::uint64_t>(texelCount(textures), 1) * 16 + 256 * 4 +
           sizeof(shared::VoxelRenderParams) + kMaterialBytes +
           static_cast<std::uint64_t>(width) * height * 16 + kShadowPlaceholderBytes;
}

struct VoxelGpuRenderer::State {
    gpu::Context* context = nullptr;
    Int3 size;
    int chunkSize = 0;
    Int3 chunks;
    int textureCount = 0;
    std::uint64_t bytes = 0;
    std::shared_ptr<gpu::Buffer> params, voxels, chunkSolid, brickMasks, brickReach, textureInfo,
        texels, srgb, output, materials;
    std::uint64_t outputBytes = 0;
    gpu::Program* program = nullptr;
    VoxelGpuUploads sent;          // bytes sent to the device so far, by kind
    std::uint64_t generation = 1;  // +1 per updateRegion that re-sent chunks
    // What params and materials hold now (empty: unknown), so unchanged ones are not sent again.
    std::vector<std::byte> paramsHeld;
    std::vector<shared::VoxelMaterial> materialsHeld;
    gpu::Program* castProgram = nullptr;
    bool reachCurrent = false;
    // The world and textures given to create (sun visibility is built from them).
    const VoxelWorld* sourceWorld = nullptr;
    const TextureSet* sourceTextures = nullptr;
    std::uint64_t limit = 0;  // device memory the renderer may use (0: unknown)
    // Sun visibility arrays at bindings 11..14 (placeholders until a method needs them), and
    // what they were built from.
    std::array<std::shared_ptr<gpu::Buffer>, 4> shadow;
    std::uint64_t shadowBytes = 0;
    std::optional<ShadowKey> shadowKey;

    // Sends `data` to `buffer` at `offset`, counted in `counter`.
    Status send(gpu::Buffer& buffer, std::span<const std::byte> data, std::uint64_t& counter,
                std::uint64_t offset = 0) {
        if (Status st = context->upload(buffer, data, offset); !st) return st;
        counter += data.size();
        return Ok{};
    }

    template <typename T>
    Result<std::shared_ptr<gpu::Buffer>> uploaded(const std::vector<T>& data) {
        auto b = context->createBuffer(data.size() * sizeof(T));
        if (!b) return b.error();
        if (Status st = send(**b, bytesOf(data), sent.shadows); !st) return st.error();
        return *b;
    }

    // The parameters, unless the buffer holds these already.
    Status sendParams(const shared::VoxelRenderParams& p) {
        const auto data = std::as_bytes(std::span(&p, 1));
        if (std::equal(data.begin(), data.end(), paramsHeld.begin(), paramsHeld.end())) {
            return Ok{};
        }
        paramsHeld.clear();
        if (Status st = send(*params, data, sent.parameters); !st) return st;
        paramsHeld.assign(data.begin(), data.end());
        return Ok{};
    }

    Status setShadowArrays(const ShadowUpload& u) {
        auto p = uploaded(std::vector<shared::ShadowParams>{u.params});
        if (!p) return p.error();
        auto m = uploaded(u.moments);
        if (!m) return m.error();
        auto f = uploaded(u.field);
        if (!f) return f.error();
        auto l = uploaded(u.levels);
        if (!l) return l.error();
        shadow = {*p, *m, *f, *l};
        shadowBytes = sizeof(shared::ShadowParams) + u.moments.size() * 4 + u.field.size() * 4 +
                      u.levels.size() * 4;
        return Ok{};
    }

    // The arrays options' sun visibility needs, built on the CPU as render() does (or taken from
    // options.sunVisibility) and uploaded, unless the same ones are already there.
    Status prepareShadows(const ShadeOptions& options) {
        ShadowKey key;
        key.given = options.sunVisibility;
        if (key.given) {
            key.direction = key.given->sun().direction;
            key.angularRadius = key.given->sun().angularRadius;
            key.settings = key.given->settings();
        } else {
            key.direction = {options.sunDirection.x, options.sunDirection.y,
                             options.sunDirection.z};
            key.angularRadius = options.sunAngularRadius;
            key.settings = options.shadowSettings;
        }
        if (shadowKey && shadowKey->matches(key)) return Ok{};
        if (key.settings.method == ShadowMethod::Exact) {
            return Error(
                "sun visibility 'exact' (render.shadows, --shadows) has no GPU twin: it traces "
                "the world per light sample; render it on the CPU or use msm, vsm, sdf, blend, "
                "flood or hard");
        }
        if (usesPenumbraMsm(key.settings)) return Error(kPenumbraMsmGpuError);
        if (key.given && key.given->world().size() != size) {
            return Error("options.sunVisibility was built for another world");
        }
        const std::uint64_t needed = estimateVoxelShadowGpuMemory(size, key.settings);
        if (limit > 0 && bytes + outputBytes + needed > limit) {
            return Error(std::string("sun visibility '") + shadowMethodName(key.settings.method) +
                         "' needs " + formatBytes(needed) + " of device memory more, " +
                         formatBytes(limit) + " in all are available");
        }
        std::optional<SunVisibility> built;
        const SunVisibility* visibility = key.given;
        if (!visibility) {
            auto b = SunVisibility::build(*sourceWorld, sourceTextures,
                                          {key.direction, key.angularRadius}, key.settings);
            if (!b) return b.error();
            built.emplace(std::move(*b));
            visibility = &*built;
        }
        auto upload = shadowUploadOf(*visibility);
        if (!upload) return upload.error();
        if (Status st = setShadowArrays(*upload); !st) return st;
        shadowKey = key;
        return Ok{};
    }

    // Brick masks and reach of the whole world (a fraction of the voxel data: 16 bytes per 64
    // voxels), re-sent after every edit. The reach goes as it is stored: 8 planes of bytes
    // (VoxelWorld::brickReachData), read as words by voxel_world_access.glsl.
    Status uploadBricks(const VoxelWorld& world) {
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

    // The world part of the parameters (the rest is filled per render).
    void fillWorld(shared::VoxelRenderParams& p, int stepCap) const {
        p.sizeX = size.x, p.sizeY = size.y, p.sizeZ = size.z;
        p.chunkShift =
            static_cast<std::uint32_t>(std::countr_zero(static_cast<unsigned>(chunkSize)));
        p.chunksX = chunks.x, p.chunksY = chunks.y, p.chunksZ = chunks.z;
        p.bricksX = (size.x + 3) / 4, p.bricksY = (size.y + 3) / 4, p.bricksZ = (size.z + 3) / 4;
        p.stepCap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
        p.flags = reachCurrent ? LUXEL_VOXEL_REACH_CURRENT : 0u;
    }

    Status uploadChunkSolid(const VoxelWorld& world) {
        std::vector<std::uint32_t> counts(chunkTotal(chunks));
        std::size_t i = 0;
        for (int cz = 0; cz < chunks.z; ++cz) {
            for (int cy = 0; cy < chunks.y; ++cy) {
                for (int cx = 0; cx < chunks.x; ++cx)
                    counts[i++] = world.chunkSolidCount(cx, cy, cz);
            }
        }
        return send(*chunkSolid, bytesOf(counts), sent.world);
    }

    // Uploads chunks [cx0, cx1) of row (cy, cz): contiguous in the GPU layout.
    Status uploadChunkRow(const VoxelWorld& world, int cx0, int cx1, int cy, int cz) {
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
};

VoxelGpuRenderer::VoxelGpuRenderer(std::unique_ptr<State> state) : state_(std::move(state)) {}
VoxelGpuRenderer::VoxelGpuRenderer(VoxelGpuRenderer&&) noexcept = default;
VoxelGpuRenderer& VoxelGpuRenderer::operator=(VoxelGpuRenderer&&) noexcept = default;
VoxelGpuRenderer::~VoxelGpuRenderer() = default;

std::uint64_t VoxelGpuRenderer::deviceBytes() const {
    return state_ ? state_->bytes + state_->shadowBytes + state_->outputBytes : 0;
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

Status VoxelGpuRenderer::prepareRender(const Camera& camera, const ShadeOptions& options,
                                       bool image) {
    State& s = *state_;
    if (options.materialReflectivity) {
        return Error(
            "the GPU voxel renderer takes reflectivity per texture, not a per-voxel callback");
    }
    const int w = camera.width(), h = camera.height();
    const std::uint64_t outputBytes = static_cast<std::uint64_t>(w) * h * 16;
    if (image && (!s.output || s.outputBytes < outputBytes)) {
        s.output.reset();
        s.outputBytes = 0;
        auto b = s.context->createBuffer(outputBytes);
        if (!b) return b.error();
        s.output = *b;
        s.outputBytes = outputBytes;
    }

    shared::VoxelRenderParams p{};
    s.fillWorld(p, options.stepCap);
    p.width = w, p.height = h;
    p.textureCount = s.textureCount;
    p.flags |= (options.faceShading ? LUXEL_VOXEL_FACE_SHADING : 0u) |
               (options.shadows ? LUXEL_VOXEL_SHADOWS : 0u) |
               (options.textures ? LUXEL_VOXEL_PROCEDURAL_TEXTURE : 0u) |
               (options.reflectionMode == ShadeOptions::ReflectionMode::EnergyConserving
                    ? LUXEL_VOXEL_ENERGY_CONSERVING
                    : 0u);
    const Vec3d pos = camera.position(), f = camera.forward(), r = camera.right(), u = camera.up();
    p.positionX = float(pos.x), p.positionY = float(pos.y), p.positionZ = float(pos.z);
    // Camera::create's tanHalf_ and rayAt's aspect, rounded to float.
    p.tanHalf = float(std::tan(0.5 * camera.fovYDegrees() * (std::numbers::pi / 180.0)));
    p.aspect = float(static_cast<double>(w) / h);
    p.forwardX = float(f.x), p.forwardY = float(f.y), p.forwardZ = float(f.z);
    p.rightX = float(r.x), p.rightY = float(r.y), p.rightZ = float(r.z);
    p.upX = float(u.x), p.upY = float(u.y), p.upZ = float(u.z);
    p.maxReflections = static_cast<std::uint32_t>(std::max(options.maxReflections, 0));
    p.ambient = options.ambient;
    p.sunX = options.sunDirection.x, p.sunY = options.sunDirection.y,
    p.sunZ = options.sunDirection.z;
    p.reflectivity = options.reflectivity;
    p.skyTopR = options.skyTop.r, p.skyTopG = options.skyTop.g, p.skyTopB = options.skyTop.b;
    p.skyHorizonR = options.skyHorizon.r, p.skyHorizonG = options.skyHorizon.g,
    p.skyHorizonB = options.skyHorizon.b;
    p.textureStrength = options.textureStrength;
    p.textureTexels = static_cast<std::uint32_t>(std::max(options.textureTexels, 1));
    if (options.lighting == ShadeOptions::Lighting::Physical) {
        p.flags |=
            LUXEL_VOXEL_PHYSICAL | (options.refraction ? LUXEL_VOXEL_REFRACTION : 0u) |
            (options.fresnel == ShadeOptions::FresnelModel::Exact ? LUXEL_VOXEL_FRESNEL_EXACT : 0u);
        p.specular = options.specular == ShadeOptions::Specular::Ggx ? LUXEL_VOXEL_SPECULAR_GGX
                     : options.specular == ShadeOptions::Specular::BlinnPhong
                         ? LUXEL_VOXEL_SPECULAR_BLINN_PHONG
                         : LUXEL_VOXEL_SPECULAR_NONE;
        p.sunIrradianceR = options.sunIrradiance.r, p.sunIrradianceG = options.sunIrradiance.g,
        p.sunIrradianceB = options.sunIrradiance.b;
        p.skyAmbient = options.skyAmbient;
        // As shading_physical.cpp: the sun's image in a mirror bounds the GGX alpha.
        p.alphaMin = std::max(0.5f * static_cast<float>(options.sunAngularRadius), 1e-3f);
        p.maxReflections = static_cast<std::uint32_t>(
            std::clamp(options.maxReflections, 0, LUXEL_VOXEL_MAX_DEPTH));
    }
    if (options.lighting == ShadeOptions::Lighting::Physical) {
        p.flags |= options.normalMaps ? LUXEL_VOXEL_NORMAL_MAPS : 0u;
        // Hard is the shadow ray of the pass itself (it sees cutouts, as the CPU's); every other
        // method reads the arrays at 11..14.
        const ShadowMethod method = options.sunVisibility ? options.sunVisibility->settings().method
                                                          : options.shadowSettings.method;
        if (options.shadows && method != ShadowMethod::Hard) {
            if (Status st = s.prepareShadows(options); !st) return st.error();
            p.flags |= LUXEL_VOXEL_SUN_VISIBILITY;
        }
    }
    if (std::vector<shared::VoxelMaterial> m = gpuMaterials(options.materials);
        m.size() != s.materialsHeld.size() ||
        std::memcmp(m.data(), s.materialsHeld.data(), m.size() * sizeof(m[0])) != 0) {
        s.materialsHeld.clear();
        if (Status st = s.send(*s.materials, bytesOf(m), s.sent.materials); !st) return st.error();
        s.materialsHeld = std::move(m);
    }
    // Anti-aliasing and filtering as render_image.cpp's shadePixel and shading.cpp.
    const int samples = samplesPerPixel(options);
    p.samplesPerPixel = static_cast<std::uint32_t>(samples);
    p.textureFilter = static_cast<std::uint32_t>(options.textureFilter);
    p.maxAnisotropy = static_cast<std::uint32_t>(std::max(options.maxAnisotropy, 1));
    p.coneSpread = static_cast<float>(primaryCone(camera).spread / std::sqrt(double(samples)));
    if (Status st = s.sendParams(p); !st) return st.error();
    return Ok{};
}

Result<std::vector<gpu::Buffer*>> VoxelGpuRenderer::bindings(const Camera& camera,
                                                             const ShadeOptions& options) {
    if (Status st = prepareRender(camera, options, /*image=*/false); !st) return st.error();
    std::vector<gpu::Buffer*> buffers = renderBuffers();
    buffers[6] = state_->params.get();  // no image: the parameters stand in, as at 10
    return buffers;
}

const VoxelGpuUploads& VoxelGpuRenderer::uploads() const {
    return state_->sent;
}

std::uint64_t VoxelGpuRenderer::worldGeneration() const {
    return state_->generation;
}

std::vector<gpu::Buffer*> VoxelGpuRenderer::renderBuffers() const {
    const State& s = *state_;
    return {s.params.get(),     s.voxels.get(),    s.chunkSolid.get(), s.textureInfo.get(),
            s.texels.get(),     s.srgb.get(),      s.output.get(),     s.brickMasks.get(),
            s.brickReach.get(), s.materials.get(), s.params.get(),     s.shadow[0].get(),
            s.shadow[1].get(),  s.shadow[2].get(), s.shadow[3].get()};
}

Result<Image> VoxelGpuRenderer::render(const Camera& camera, const ShadeOptions& options,
                                       std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    Stopwatch upload;
    if (Status st = prepareRender(camera, options, /*image=*/true); !st) return st.error();
    const int w = camera.width(), h = camera.height();
    if (timings) timings->push_back({"upload parameters (CPU)", upload.milliseconds()});

    std::vector<gpu::Dispatch> dispatches;
    for (int row = 0; row < h; row += kBandRows) {
        gpu::Dispatch d;
        d.name = "voxel render rows " + std::to_string(row);
        d.program = s.program;
        d.buffers = renderBuffers();
        const int rows = std::min(kBandRows, h - row);
        d.setPush(shared::VoxelBandPush{static_cast<std::uint32_t>(row),
                                        static_cast<std::uint32_t>(rows)});
        d.setThreads(static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(rows));
        dispatches.push_back(std::move(d));
    }
    auto passes = s.context->run(dispatches);
    if (!passes) return passes.error();
    if (timings) {
        double total = 0;
        for (const gpu::PassTiming& t : *passes) total += t.milliseconds;
        timings->push_back({"voxel render (GPU)", total});
    }

    Stopwatch download;
    // The RGBA copy, its staging buffer and the RGB image exist together on the host.
    const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    if (Status st = checkMemory(pixels * (16 + 16 + 12), "downloading a " + std::to_string(w) +
                                                             "x" + std::to_string(h) + " frame");
        !st) {
        return st.error();
    }
    std::vector<float> rgba(static_cast<std::size_t>(w) * h * 4);
    if (Status st = s.context->download(*s.output, std::as_writable_bytes(std::span(rgba))); !st) {
        return st.error();
    }
    Image image(w, h, 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float* px = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            image.setRgb(x, y, {px[0], px[1], px[2]});
        }
    }
    if (timings) timings->push_back({"download image (CPU)", download.milliseconds()});
    return image;
}

Result<std::vector<Hit>> VoxelGpuRenderer::castRays(std::span<const Ray> rays, double tMax,
                                                    int stepCap, ChunkSkip skip,
                                                    std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    std::vector<Hit> hits(rays.size());
    if (rays.empty()) return hits;
    const std::vector<shared::VoxelCastRay> in =
        castRaysForGpu(rays, tMax, skip == ChunkSkip::Enabled);
    const std::uint64_t outBytes = rays.size() * sizeof(shared::VoxelCastHit);
    auto rayBuffer = s.context->createBuffer(in.size() * sizeof(shared::VoxelCastRay));
    if (!rayBuffer) return rayBuffer.error();
    auto hitBuffer = s.context->createBuffer(outBytes);
    if (!hitBuffer) return hitBuffer.error();
    shared::VoxelRenderParams p{};
    s.fillWorld(p, stepCap);
    if (Status st = s.sendParams(p); !st) return st.error();
    if (Status st = s.send(**rayBuffer, bytesOf(in), s.sent.rays); !st) return st.error();

    gpu::Dispatch d;
    d.name = "voxel cast rays";
    d.program = s.castProgram;
    d.buffers = {s.params.get(),   s.voxels.get(),     s.chunkSolid.get(), rayBuffer->get(),
                 hitBuffer->get(), s.brickMasks.get(), s.brickReach.get()};
    const std::uint32_t cap = p.stepCap;
    d.setPush(shared::VoxelCastPush{static_cast<std::uint32_t>(rays.size()), cap});
    d.setThreads(rays.size());
    auto passes = s.context->run(std::span(&d, 1));
    if (!passes) return passes.error();
    if (timings) timings->insert(timings->end(), passes->begin(), passes->end());

    std::vector<shared::VoxelCastHit> out(rays.size());
    if (Status st = s.context->download(**hitBuffer, std::as_writable_bytes(std::span(out))); !st) {
        return st.error();
    }
    for (std::size_t i = 0; i < out.size(); ++i) hits[i] = hitFromGpu(out[i]);
    return hits;
}

}  // namespace luxel::voxel
