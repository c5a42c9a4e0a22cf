// Voxel-mode keys for surfaces, shadows and post-processing, kept free of SDL so tests can drive
// them (letters are their own SDL keycodes): docs/viewer.md lists them.
#pragma once

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

}  // namespace luxel::viewer
