// Ray cones (Akenine-Moller et al., "Texture Level of Detail Strategies for Real-Time Ray
// Tracing", Ray Tracing Gems ch. 20, 2019): each ray carries the width of the cone of directions
// one pixel covers, growing linearly with distance. It sizes texture filters at primary and
// secondary hits alike (secondary rays have no screen derivatives) and drives the MRMA blend of
// secondary rays.
#pragma once

namespace luxel::voxel {

struct RayCone {
    double width = 0.0;   // cone width at the ray's origin, world units (voxels)
    double spread = 0.0;  // growth of the width per unit of distance (radians, small-angle)

    double widthAt(double t) const { return width + spread * t; }
    // The cone continuing from a hit at distance t off a flat face: flat voxel faces add no
    // curvature, so only the origin moves.
    RayCone after(double t) const { return {widthAt(t), spread}; }
};

}  // namespace luxel::voxel
