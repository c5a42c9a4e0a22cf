// The footprint of a ray cone where it meets a voxel face, in face coordinates: what texture
// filtering (TextureSet::sample) integrates over.
#pragma once

#include "luxel/core/vec.h"
#include "luxel/voxel/ray_cone.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {

// The ellipse a cone of width cone.widthAt(t) cuts from the face with axis-aligned `normal`,
// arriving along `direction`: minor half-axis = width / 2, major = minor / |cos(incidence)|,
// along the direction projected onto the face.
TexelFootprint texelFootprint(const RayCone& cone, double t, Vec3d direction, Int3 normal);

}  // namespace luxel::voxel
