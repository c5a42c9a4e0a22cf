// libFuzzer target for voxel scene files (luxel::voxel::parseVoxelScene): any bytes must give a
// scene or an Error, never a crash or a sanitizer report. Textures and .vox worlds resolve in the
// fixed files folder (scene_files.h); worlds larger than kMaxFuzzVoxels are skipped, since a valid
// 4096 x 256 x 4096 terrain is legitimately slow and large, which is not what this target looks
// for.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "luxel/voxel/voxel_scene.h"
#include "scene_files.h"

namespace {

using namespace luxel;

constexpr double kMaxFuzzVoxels = 1 << 21;

// Whether the document asks for a world small enough to build quickly (or says nothing usable).
bool smallWorld(const json::Json& root) {
    if (!root.is_object()) return true;
    const json::Json* world = json::find(root, "world");
    if (!world || !world->is_object()) return true;
    const json::Json* size = json::find(*world, "size");
    if (!size || !size->is_array() || size->size() != 3) return true;
    double voxels = 1;
    for (const json::Json& side : *size) {
        if (!side.is_number()) return true;
        voxels *= side.get<double>();
    }
    return !(voxels > kMaxFuzzVoxels);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (const Result<json::Json> root = json::parse(text, "fuzz.json");
        root && (!fuzz::namesOnlyLocalFiles(*root) || !smallWorld(*root))) {
        return 0;
    }
    const Result<voxel::VoxelScene> scene =
        voxel::parseVoxelScene(text, fuzz::scenePath("fuzz.json"));
    if (!scene) {
        if (scene.error().message().empty()) __builtin_trap();  // an error says what is wrong
        return 0;
    }
    const Int3 s = scene->world.size();
    if (s.x < 1 || s.y < 1 || s.z < 1 || s.x > voxel::kMaxWorldSide || s.y > voxel::kMaxWorldSide ||
        s.z > voxel::kMaxWorldSide) {
        __builtin_trap();
    }
    const std::uint64_t volume = std::uint64_t(s.x) * std::uint64_t(s.y) * std::uint64_t(s.z);
    if (scene->world.solidCount() > volume) __builtin_trap();
    if (scene->textures.size() > voxel::kMaxTextures) __builtin_trap();
    return 0;
}
