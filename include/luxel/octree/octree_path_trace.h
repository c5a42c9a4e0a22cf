// Brute-force Monte Carlo volume path tracing of an octree: the ground truth the volume mode's
// scattering approximation (octree_render.h) is measured against. The medium of a leaf of value v
// has extinction sigma_t = -ln(1 - a) per voxel (a = min(v / 255 * opacityScale, 1), so its
// transmittance is the renderer's (1 - a)^s), scattering albedo * colour, and a Henyey-Greenstein
// phase function; the sun is a directional light sampled at every scattering event (next-event
// estimation). Free flights are sampled exactly: the medium is piecewise constant along the
// octree walk. The sky term is not modelled: render with sky black and ambient 0 to compare.
#pragma once

#include <cstdint>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

struct PathTraceOptions {
    int samplesPerPixel = 64;
    int maxScatterings = 64;  // 1: single scattering only
    std::uint64_t seed = 1;
};

Result<Image> pathTraceOctree(const Octree& tree, const voxel::Camera& camera,
                              const OctreeRenderOptions& medium, const PathTraceOptions& options);

}  // namespace luxel::octree
