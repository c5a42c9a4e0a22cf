// The SDF soft shadow of a disk light: a march from a receiver towards the light on the voxel
// distance field with the shared estimator (soft_shadow.h: Aaltonen's closest approach, Quilez's
// negative extension, w = tan(angular radius)).
//
// Steps: the larger of the conservative distance (DistanceField::conservative) and, in an empty
// cell, the distance to leave that cell, so the march never jumps over a solid voxel and still
// moves at least a cell at a time along grazing surfaces; inside a solid the fixed minimum step.
#pragma once

#include "luxel/core/vec.h"
#include "luxel/voxel/shadows/distance_field.h"

namespace luxel::voxel {

struct SdfShadowResult {
    float visibility = 1.0f;
    // The march reached the world's bounds (the sky) or a full shadow; false: it ran out of steps.
    bool valid = false;
    int steps = 0;
};

// How far a march at p in direction d (unit) may advance without jumping over a solid voxel.
double sdfSafeStep(const DistanceField& field, Vec3d p, Vec3d d);

// V of the light seen from `origin` (already offset off its face) towards unit `l`.
// cubes: read DistanceField::surfaceDistance, else the trilinear estimate.
SdfShadowResult sdfSunVisibility(const DistanceField& field, Vec3d origin, Vec3d l,
                                 double tanRadius, int maxSteps, bool cubes = true);

}  // namespace luxel::voxel
