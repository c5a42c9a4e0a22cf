// Procedural volumes for the octree: a CT-like phantom (dense, 8-bit) and a heightfield terrain
// source far larger than a dense grid could hold (built straight into an octree).
#pragma once

#include <cstdint>
#include <memory>

#include "luxel/core/error.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/volume.h"

namespace luxel::octree {

// A head-like phantom in a side^3 volume, after the Shepp-Logan idea in 3D: a thin dense skull
// shell (about side/170 voxels, at least 1), soft tissue with faint noise inside, two low-density
// ventricles, one-voxel-thin concentric shells (a test of thin features), and a few small dense
// calcifications. Colours: a bone-to-tissue ramp by opacity. side in 8..kMaxVolumeSide.
Result<Volume> makePhantom(int side, std::uint64_t seed = 1);

// Rolling terrain of `side`^3 voxels (a power of two up to 65536) whose ground is a sum of sine
// waves: solid below the surface (grass on top, dirt, then stone), empty above. Answers uniform
// blocks from the height bounds of each column block, so a 4096^3 or larger tree builds in time
// proportional to its surface, not its volume.
std::unique_ptr<OctreeSource> makeSparseTerrain(int side, std::uint64_t seed = 1);

}  // namespace luxel::octree
