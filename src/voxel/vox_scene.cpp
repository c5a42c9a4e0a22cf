#include "luxel/voxel/vox_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "luxel/core/file_io.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

constexpr int kDefaultWidth = 960, kDefaultHeight = 540;
constexpr double kFovY = 40.0;
constexpr double kElevation = 30.0, kAzimuth = 45.0;  // degrees

VoxelScene sceneFrom(VoxImport import, const std::string& path, const VoxSceneOptions& options) {
    VoxelScene scene{};
    scene.sourcePath = path;
    if (Status s = addVoxMaterials(import, scene.textures, scene.shading.materials); !s) {
        // Cannot happen: an import holds at most kMaxTextures materials and the set is empty.
        import.warnings.push_back(path + ": " + s.error().message());
    }
    const int w = options.width > 0 ? options.width : kDefaultWidth;
    const int h = options.height > 0 ? options.height : kDefaultHeight;
    scene.camera = framingCamera(import.world.size(), w, h).value();
    scene.world = std::move(import.world);
    scene.warnings = std::move(import.warnings);
    ShadeOptions& o = scene.shading;
    // Materials (glass, metal, emission) show under physical lighting only; the procedural face
    // texture is off so colours read as MagicaVoxel shows them.
    o.lighting = ShadeOptions::Lighting::Physical;
    o.textures = false;
    // The sun stands high over the camera's left shoulder, so the two visible sides differ.
    o.sunDirection = {0.3f, 1.0f, -0.6f};
    return scene;
}

}  // namespace

bool hasVoxExtension(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".vox";
}

bool hasVoxMagic(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "VOX ", 4) == 0;
}

Result<Camera> framingCamera(Int3 size, int width, int height) {
    const Vec3d centre{size.x / 2.0, size.y / 2.0, size.z / 2.0};
    const double radius = 0.5 * std::sqrt(double(size.x) * size.x + double(size.y) * size.y +
                                          double(size.z) * size.z);
    const double toRad = std::numbers::pi / 180.0;
    const double halfY = kFovY * toRad / 2;
    const double halfX = std::atan(std::tan(halfY) * width / std::max(height, 1));
    const double distance = 1.05 * radius / std::sin(std::min(halfX, halfY));
    const double el = kElevation * toRad, az = kAzimuth * toRad;
    const Vec3d toCamera{std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
    const Vec3d position{centre.x + distance * toCamera.x, centre.y + distance * toCamera.y,
                         centre.z + distance * toCamera.z};
    return Camera::lookAt(position, centre, kFovY, width, height);
}

Status addVoxMaterials(VoxImport& import, TextureSet& textures, MaterialTable& table) {
    if (import.materials.empty()) return Ok{};
    const int offset = textures.size();
    if (offset + static_cast<int>(import.materials.size()) > kMaxTextures) {
        return Error("the scene's " + std::to_string(offset) + " textures and the file's " +
                     std::to_string(import.materials.size()) + " materials exceed the " +
                     std::to_string(kMaxTextures) + " texture slots");
    }
    for (const Material& m : import.materials) {
        Texture white;
        white.name = materialSlotName(m.name);
        white.width = white.height = 1;
        white.texels = {Texel{}};
        Result<int> slot = textures.add(std::move(white));
        if (!slot) return slot.error();
        Material withTexture = m;
        withTexture.proceduralTexture = true;
        if (Status s = table.setSlot(*slot, std::move(withTexture)); !s) return s;
    }
    if (offset == 0) return Ok{};
    VoxelWorld& w = import.world;
    const Int3 s = w.size();
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                Voxel v = w.get(x, y, z);
                const int slot = textureSlotOf(v);
                if (slot < 0) continue;
                v.a = alphaForSlot(slot + offset);
                w.set(x, y, z, v);
            }
        }
    }
    return Ok{};
}

Result<VoxelScene> voxSceneFromBytes(std::span<const std::uint8_t> bytes, const std::string& path,
                                     const VoxSceneOptions& options) {
    Result<VoxImport> import = readVox(bytes, path, {options.chunkSize, options.frame});
    if (!import) return import.error();
    return sceneFrom(std::move(*import), path, options);
}

Result<VoxelScene> loadVoxScene(const std::string& path, const VoxSceneOptions& options) {
    Result<VoxImport> import = readVoxFile(path, {options.chunkSize, options.frame});
    if (!import) return import.error();
    return sceneFrom(std::move(*import), path, options);
}

}  // namespace luxel::voxel
