// Reading a lamp room's picture pixel by pixel (the near-emitter and near-highlight tests): a
// pixel's channel sum and what its centre ray meets.
#pragma once

#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::test {

inline double pixelSum(const Image& image, int x, int y) {
    return double(image.at(x, y, 0)) + image.at(x, y, 1) + image.at(x, y, 2);
}

// Where pixel (x, y)'s centre ray meets `room.world` (a room with `world` and shading `o`).
template <typename Room>
Hit hitAt(const Room& room, const Camera& camera, int x, int y) {
    return castToSurface(room.world, nullptr, camera.rayAt(x + 0.5, y + 0.5), room.o.stepCap).hit;
}

}  // namespace luxel::voxel::test
