// What the voxel radiance cascades' picture draws with, on the CPU (cascade_picture.cpp) and the
// GPU (cascade_picture_gpu.cpp) alike (docs/algorithms/voxel-radiance-cascades.md §4.2).
#pragma once

#include <cstdint>

namespace luxel::voxel::cascades {

inline constexpr std::uint64_t kReflectionSeed = 0x7265666c;  // the picture's GGX directions
// Shadow rays per pixel over the sun's disk: a quarter of sky visibility's, for the frame rate;
// the penumbra is drawn in 5 steps.
inline constexpr int kPictureSunRays = 4;
inline constexpr int kPictureSpecularRays = 2;  // and half its reflection rays

}  // namespace luxel::voxel::cascades
