// libFuzzer target for the MagicaVoxel .vox reader: any bytes must give a world or an Error,
// never a crash, a sanitizer report or an allocation beyond the checked world size.
#include <cstddef>
#include <cstdint>
#include <span>

#include "luxel/voxel/vox_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const luxel::Result<luxel::voxel::VoxelWorld> world =
        luxel::voxel::parseVox(std::span<const std::uint8_t>(data, size), "fuzz.vox", 8);
    if (world.ok()) {
        // Touch the result so the reads are not optimised away.
        volatile std::uint64_t solid = world->solidCount();
        (void)solid;
    } else {
        volatile std::size_t length = world.error().message().size();
        (void)length;
    }
    return 0;
}
