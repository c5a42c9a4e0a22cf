// Voxel-mode keys for surfaces, shadows and post-processing, kept free of SDL so tests can drive
// them (letters are their own SDL keycodes): docs/viewer.md lists them.
#pragma once

#include <string>

#include "luxel/voxel/material.h"
#include "renderer_voxel.h"

namespace luxel::viewer {

// Applies the key's toggle or cycle to `state`; false when the key is not one of them.
//   P lighting classic/physical    V shadow method (cycles)    G specular none/Blinn-Phong/GGX
//   Y Fresnel Schlick/exact        R refraction               N normal maps
//   X texture filter (cycles)      , / . samples per pixel    O bloom off / 0.15
//   U upscaling: native, 0.5 bilinear, 0.5 edge-aware, 0.5 temporal
bool applyVoxelSurfaceKey(int key, VoxelState& state);

// "native", "bilinear 0.50", "edge 0.50", "temporal 0.50": what U shows.
std::string upscalingLabel(const VoxelState& state);

// Saving the edited world as a MagicaVoxel file (Ctrl+S, the panel's "Save .vox"): a copy of
// the world that receives every edit the renderer receives, in the same order, so it matches
// the world on screen without reaching into the render thread.
class VoxelSaver {
  public:
    VoxelSaver(voxel::VoxelWorld world, voxel::MaterialTable materials, std::string path);
    void edit(const VoxelEdit& edit);
    // Writes the world (through a temporary file and a rename); status() then says what
    // happened: "saved 1378 voxels to m.edited.vox" or "save failed: <reason>".
    bool save();
    const std::string& status() const { return status_; }
    const std::string& path() const { return path_; }
    const voxel::VoxelWorld& world() const { return world_; }

  private:
    voxel::VoxelWorld world_;
    voxel::MaterialTable materials_;
    std::string path_, status_;
};

// Where a voxel scene's world is saved without --save: next to the scene, "<stem>.edited.vox".
std::string defaultVoxSavePath(const std::string& scenePath);

}  // namespace luxel::viewer
