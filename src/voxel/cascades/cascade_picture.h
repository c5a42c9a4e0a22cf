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
// Exits into the air a refracted ray's walk through glass takes the light of before the light
// reflected back inside is dropped (SolverLight::mediumAirExits): two at the camera's surface (a
// glass sheet's reflection from inside its far face shows), one at the glass its rays follow
// (docs/algorithms/voxel-radiance-cascades.md §4.2, "Light reflected inside followed glass").
inline constexpr int kPictureCameraAirExits = 2;
inline constexpr int kPictureFollowedAirExits = 1;

}  // namespace luxel::voxel::cascades
