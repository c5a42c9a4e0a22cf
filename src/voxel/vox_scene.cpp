#include "luxel/voxel/vox_scene.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <vector>

#include "luxel/core/file_io.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

constexpr int kDefaultWidth = 960, kDefaultHeight = 540;
constexpr double kFovY = 40.0;
constexpr double kElevation = 30.0, kAzimuth = 45.0;  // degrees

// What a camera must see of a world: for every column of bricks holding solid voxels, the
// corners of the box round its solid voxels (read from the occupancy masks, so it costs one
// pass over the bricks). The whole world's corners when nothing is solid.
std::vector<Vec3d> solidOutline(const VoxelWorld& world) {
    const Int3 bricks = world.brickCount(), size = world.size();
    constexpr int kSide = VoxelWorld::kBrickSide;
    std::vector<Vec3d> points;
    for (int bz = 0; bz < bricks.z; ++bz) {
        for (int bx = 0; bx < bricks.x; ++bx) {
            Int3 lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{-1, -1, -1};
            for (int by = 0; by < bricks.y; ++by) {
                for (std::uint64_t m = world.brickMask(bx, by, bz); m != 0; m &= m - 1) {
                    const int bit = std::countr_zero(m);  // bit (z * 16 + y * 4 + x)
                    const Int3 v{bx * kSide + (bit & 3), by * kSide + (bit >> 2 & 3),
                                 bz * kSide + (bit >> 4 & 3)};
                    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
                    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
                }
            }
            if (hi.x < 0) continue;
            for (int corner = 0; corner < 8; ++corner) {
                points.push_back({double(corner & 1 ? hi.x + 1 : lo.x),
                                  double(corner & 2 ? hi.y + 1 : lo.y),
                                  double(corner & 4 ? hi.z + 1 : lo.z)});
            }
        }
    }
    if (points.empty()) {
        for (int corner = 0; corner < 8; ++corner) {
            points.push_back({corner & 1 ? double(size.x) : 0.0, corner & 2 ? double(size.y) : 0.0,
                              corner & 4 ? double(size.z) : 0.0});
        }
    }
    return points;
}

VoxelScene sceneFrom(VoxImport import, const std::string& path, const VoxSceneOptions& options) {
    VoxelScene scene{};
    scene.sourcePath = path;
    if (Status s = addVoxMaterials(import, scene.textures, scene.shading.materials); !s) {
        // Cannot happen: an import holds at most kMaxTextures materials and the set is empty.
        import.warnings.push_back(path + ": " + s.error().message());
    }
    const int w = options.width > 0 ? options.width : kDefaultWidth;
    const int h = options.height > 0 ? options.height : kDefaultHeight;
    scene.camera = framingCamera(solidOutline(import.world), w, h).value();
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
    std::vector<Vec3d> corners;
    for (int corner = 0; corner < 8; ++corner) {
        corners.push_back({corner & 1 ? double(size.x) : 0.0, corner & 2 ? double(size.y) : 0.0,
                           corner & 4 ? double(size.z) : 0.0});
    }
    return framingCamera(corners, width, height);
}

Result<Camera> framingCamera(const std::vector<Vec3d>& points, int width, int height) {
    if (points.empty()) return Error("framing an empty set of points");
    Vec3d lo = points.front(), hi = points.front();
    for (const Vec3d& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const Vec3d centre = (lo + hi) * 0.5;
    const double toRad = std::numbers::pi / 180.0;
    const double tanY = std::tan(kFovY * toRad / 2);
    const double tanX = tanY * width / std::max(height, 1);
    const double el = kElevation * toRad, az = kAzimuth * toRad;
    const Vec3d toCamera{std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
    // The view's axes do not depend on the distance: take them from a camera one voxel away.
    Result<Camera> probe = Camera::lookAt(centre + toCamera, centre, kFovY, width, height);
    if (!probe) return probe.error();
    const Vec3d right = probe->right(), up = probe->up();
    const auto dot = [](Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    // The nearest distance D at which every point is inside the image: a point at offset p from
    // the target is at depth D - p.toCamera and must satisfy |p.right| <= tanX * depth and
    // |p.up| <= tanY * depth. Then the target moves across the view to centre the points'
    // image, and the distance is found again (a dozen rounds settle it).
    Vec3d target = centre;
    double distance = 1.0;
    for (int round = 0;; ++round) {
        distance = 1.0;
        for (const Vec3d& point : points) {
            const Vec3d p = point - target;
            const double along = dot(p, toCamera);
            distance = std::max({distance, std::abs(dot(p, right)) / tanX + along,
                                 std::abs(dot(p, up)) / tanY + along});
        }
        distance *= 1.08;  // a margin round the model
        if (round == 12) break;
        double uLo = 1e300, uHi = -1e300, vLo = 1e300, vHi = -1e300;
        for (const Vec3d& point : points) {
            const Vec3d p = point - target;
            const double depth = distance - dot(p, toCamera);
            uLo = std::min(uLo, dot(p, right) / depth), uHi = std::max(uHi, dot(p, right) / depth);
            vLo = std::min(vLo, dot(p, up) / depth), vHi = std::max(vHi, dot(p, up) / depth);
        }
        target =
            target + right * (0.5 * (uLo + uHi) * distance) + up * (0.5 * (vLo + vHi) * distance);
    }
    return Camera::lookAt(target + toCamera * distance, target, kFovY, width, height);
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
