// libFuzzer target for the MagicaVoxel .vox reader: any bytes must give a world or an Error,
// never a crash, a sanitizer report or an allocation beyond the checked world size. The input's
// length picks the animation frame (0, 1 or 2), so keyframe selection is exercised too.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/vox_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    luxel::voxel::VoxOptions options;
    options.chunkSize = 8;
    options.frame = static_cast<int>(size % 3);
    options.maxWorldBytes = std::uint64_t{256} << 20;
    const luxel::Result<luxel::voxel::VoxImport> read =
        luxel::voxel::readVox(std::span<const std::uint8_t>(data, size), "fuzz.vox", options);
    if (read.ok()) {
        // Every material byte names one of the import's materials.
        if (read->materials.size() > static_cast<std::size_t>(luxel::voxel::kMaxTextures)) {
            std::abort();
        }
        const luxel::Int3 s = read->world.size();
        for (int z = 0; z < s.z; z += 7) {
            for (int y = 0; y < s.y; y += 7) {
                for (int x = 0; x < s.x; x += 7) {
                    const int slot = luxel::voxel::textureSlotOf(read->world.get(x, y, z));
                    if (slot >= static_cast<int>(read->materials.size())) std::abort();
                }
            }
        }
        volatile std::uint64_t solid = read->world.solidCount();
        (void)solid;
    } else {
        volatile std::size_t length = read.error().message().size();
        (void)length;
    }
    return 0;
}
