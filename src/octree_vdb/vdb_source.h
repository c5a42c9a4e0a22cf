// An OpenVDB float grid as an OctreeSource (luxel/octree/octree_build.h): the builder reads the
// grid's voxels through a value accessor and asks it which cubes are uniform, which it answers
// from the tree's tiles and leaf nodes, so sparse grids and large constant tiles build without
// visiting their voxels.
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>
#include <tbb/enumerable_thread_specific.h>

#include "luxel/octree/octree_build.h"

namespace luxel::octree {

// Grid value -> 8-bit opacity (luxel/octree/octree_vdb.h): fog volumes round(255 * clamp(v, 0,
// max) / max); level sets 255 inside (v < 0), 0 outside.
struct VdbQuantiser {
    bool levelSet = false;
    float max = 1;

    std::uint8_t operator()(float v) const;
};

class VdbSource final : public OctreeSource {
  public:
    // Cell (0, 0, 0) of the octree is voxel `origin` of `grid`, which must outlive the source.
    VdbSource(const openvdb::FloatGrid& grid, openvdb::Coord origin, Int3 size,
              VdbQuantiser quantise);

    Int3 size() const override { return size_; }
    bool hasColours() const override { return false; }
    void voxel(Int3 cell, std::uint8_t& opacity, Colour& colour) const override;
    std::optional<Uniform> uniformBlock(Int3 origin, int level) const override;

  private:
    // The one opacity of every voxel of `box` (grid coordinates), or nullopt when they differ.
    std::optional<std::uint8_t> uniformOpacity(const openvdb::CoordBBox& box) const;

    openvdb::Coord origin_;
    Int3 size_;
    VdbQuantiser quantise_;
    // The builder reads a source from several threads at once, and an accessor (which caches the
    // path to the last node read) is not thread safe: one per thread, copied from an exemplar.
    using Accessor = openvdb::FloatGrid::ConstAccessor;
    Accessor& accessor() const { return accessors_.local(); }
    mutable tbb::enumerable_thread_specific<Accessor> accessors_;
};

}  // namespace luxel::octree
