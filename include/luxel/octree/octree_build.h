// Building an octree (octree.h) bottom-up from a voxel source: uniform octants collapse into one
// leaf, identical octants are stored once (a DAG). Sources: a dense Volume, a VoxelWorld (opacity
// 255 for solid voxels, the voxel's RGBA as its colour), or any OctreeSource, such as a
// procedural scene far larger than a dense grid could hold.
#pragma once

#include <cstdint>
#include <optional>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/volume.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::octree {

struct BuildOptions {
    bool colours = true;  // keep the source's colours (octree.h); false: opacity only
    // Merge a uniform octant into one leaf. false keeps every leaf a voxel (octants are still
    // shared): traversal then visits every cell, as the plain per-voxel walk does.
    bool collapse = true;
    // PerEntry or LeafOrder for a coloured source; unset: the source's preferredLayout().
    std::optional<AttributeLayout> layout = std::nullopt;
};

// What the builder reads. Cells outside size() are empty. The builder calls a source from several
// threads at once, so its const methods must be safe to call concurrently (per-thread caches, such
// as OpenVDB accessors, belong in thread-local storage).
class OctreeSource {
  public:
    virtual ~OctreeSource() = default;
    virtual Int3 size() const = 0;
    virtual bool hasColours() const = 0;
    // The layout a build uses unless told: LeafOrder where colours vary voxel by voxel (voxel
    // worlds), PerEntry where they come in large uniform regions (the trade-off is measured in
    // docs/algorithms/sparse-voxel-octree.md §2).
    virtual AttributeLayout preferredLayout() const { return AttributeLayout::PerEntry; }
    // The opacity and colour of one voxel inside size().
    virtual void voxel(Int3 cell, std::uint8_t& opacity, Colour& colour) const = 0;
    // Whether the aligned cube [origin, origin + 2^level) holds one opacity and colour throughout
    // (for example none at all): the builder then stores one leaf without visiting its voxels.
    // Sources answer what they know cheaply; nullopt means "look inside".
    struct Uniform {
        std::uint8_t opacity = 0;
        Colour colour;
    };
    virtual std::optional<Uniform> uniformBlock(Int3 origin, int level) const {
        (void)origin;
        (void)level;
        return std::nullopt;
    }
};

// The smallest depth (>= 1) whose cube holds `size`.
int depthFor(Int3 size);

Result<Octree> buildOctree(const OctreeSource& source, const BuildOptions& options = {});
Result<Octree> buildOctree(const Volume& volume, const BuildOptions& options = {});
Result<Octree> buildOctree(const voxel::VoxelWorld& world, const BuildOptions& options = {});

}  // namespace luxel::octree
