// Device memory estimates of VoxelGpuRenderer (its buffers, as create allocates them), so that
// callers and create can refuse a world too large before uploading anything.
#include <algorithm>

#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

namespace voxel_gpu {

Int3 chunkCounts(Int3 size, int chunk) {
    return {(size.x + chunk - 1) / chunk, (size.y + chunk - 1) / chunk,
            (size.z + chunk - 1) / chunk};
}

std::uint64_t chunkTotal(Int3 chunks) {
    return static_cast<std::uint64_t>(chunks.x) * chunks.y * chunks.z;
}

}  // namespace voxel_gpu

using voxel_gpu::chunkCounts;
using voxel_gpu::chunkTotal;

namespace {

// Texels uploaded: each texture, its colour mip chain and its normal chain.
std::uint64_t texelCount(const TextureSet* textures) {
    std::uint64_t n = 0;
    for (int i = 0; textures && i < textures->size(); ++i) {
        n += (*textures)[i].texels.size() + textures->colourMips(i).size() +
             textures->normalMips(i).size();
    }
    return n;
}

// Placeholders bound at 11..14 when no method needs the shadow arrays: the parameters and one
// word each.
constexpr std::uint64_t kShadowPlaceholderBytes = sizeof(shared::ShadowParams) + 3 * 4;

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
           sizeof(shared::VoxelRenderParams) + voxel_gpu::kMaterialBytes +
           static_cast<std::uint64_t>(width) * height * 16 + kShadowPlaceholderBytes;
}

}  // namespace luxel::voxel
