// Toggles and cycles of the voxel surface, shadow and post options; saving the edited world.
#include "voxel_controls.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "luxel/voxel/vox_import.h"

namespace luxel::viewer {
namespace {

template <typename E>
E next(E value, int count) {
    return static_cast<E>((static_cast<int>(value) + 1) % count);
}

}  // namespace

bool applyVoxelSurfaceKey(int key, VoxelState& state) {
    voxel::ShadeOptions& s = state.shading;
    post::PostOptions& p = state.post;
    switch (key) {
        case 'p':
            s.lighting = s.lighting == voxel::ShadeOptions::Lighting::Classic
                             ? voxel::ShadeOptions::Lighting::Physical
                             : voxel::ShadeOptions::Lighting::Classic;
            return true;
        case 'v':
            s.shadowSettings.method = next(s.shadowSettings.method, 7);
            return true;
        case 'g':
            s.specular = next(s.specular, 3);
            return true;
        case 'y':
            s.fresnel = next(s.fresnel, 2);
            return true;
        case 'r':
            s.refraction = !s.refraction;
            return true;
        case 'n':
            s.normalMaps = !s.normalMaps;
            return true;
        case 'x':
            s.textureFilter = next(s.textureFilter, 3);
            return true;
        case ',':
            s.samplesPerPixel = std::max(1, s.samplesPerPixel / 2);
            return true;
        case '.':
            s.samplesPerPixel = std::min(64, s.samplesPerPixel * 2);
            return true;
        case 'o':
            p.bloom.strength = p.bloom.strength > 0.0f ? 0.0f : 0.15f;
            return true;
        case 'u':
            // native -> bilinear -> edge -> temporal -> native, at half resolution.
            if (state.temporal) {
                state.temporal = false;
                p.internalScale = 1.0f;
            } else if (p.internalScale >= 1.0f) {
                p.internalScale = 0.5f;
                p.upscaler = post::Upscaler::Bilinear;
            } else if (p.upscaler == post::Upscaler::Bilinear) {
                p.upscaler = post::Upscaler::Edge;
            } else {
                state.temporal = true;
            }
            return true;
        default:
            return false;
    }
}

std::string upscalingLabel(const VoxelState& state) {
    const post::PostOptions& p = state.post;
    if (!state.temporal && p.internalScale >= 1.0f) return "native";
    char text[64];
    std::snprintf(text, sizeof text, "%s %.2f",
                  state.temporal ? "temporal" : post::upscalerName(p.upscaler), p.internalScale);
    return text;
}

VoxelSaver::VoxelSaver(voxel::VoxelWorld world, voxel::MaterialTable materials, std::string path)
    : world_(std::move(world)), materials_(std::move(materials)), path_(std::move(path)) {}

void VoxelSaver::edit(const VoxelEdit& e) {
    applyVoxelEdit(world_, e);
}

bool VoxelSaver::save() {
    auto written = voxel::writeVox(world_, path_, &materials_);
    if (!written) {
        status_ = "save failed: " + written.error().message();
        return false;
    }
    status_ = "saved " + std::to_string(world_.solidCount()) + " voxels to " + path_;
    if (!written->empty()) status_ += " (" + written->front() + ")";
    return true;
}

std::string defaultVoxSavePath(const std::string& scenePath) {
    const std::filesystem::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + ".edited.vox")).string();
}

}  // namespace luxel::viewer
