// A sparse voxel octree in the uint32 format of the WebGL octree design
// (docs/algorithms/sparse-voxel-octree.md):
// - the tree is an array of uint32; each run of 8 entries is an octant, entries 0-7 the root;
// - an entry below 256 is a leaf holding an opacity 0 (empty) .. 255 (opaque) for its whole cube;
// - an entry of 256 or more is a branch whose 8 children start at index value - 248.
// Identical octants are stored once (the builder hash-conses them), so the array is a DAG.
//
// Child order within an octant: slot = x | z << 1 | y << 2, with y up (luxel's voxel axes). The
// vertical axis is the highest bit so that the design's worked example (root entries 0-3 = 256,
// 4-7 = 0; entries 8-11 = 255, 12-15 = 0) is "only the bottom-most slice is fully opaque".
//
// Colour is not part of the format; it lives in a side array laid out one of two ways
// (AttributeLayout, docs/algorithms/sparse-voxel-octree.md §1 "Colour"). Voxel worlds keep their
// texture slot in the alpha byte, as in VoxelWorld.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::octree {

inline constexpr std::uint32_t kLeafLimit = 256;   // entries below are leaves
inline constexpr std::uint32_t kBranchBias = 248;  // child index = entry - kBranchBias
// Deepest tree accepted: 2^16 = 65536 voxels a side, the most a float traversal resolves exactly.
inline constexpr int kMaxDepth = 16;

constexpr bool isLeaf(std::uint32_t entry) {
    return entry < kLeafLimit;
}
constexpr std::uint32_t childBase(std::uint32_t branch) {
    return branch - kBranchBias;
}
constexpr std::uint32_t branchTo(std::uint32_t base) {
    return base + kBranchBias;
}
// The slot of the child holding cell (x, y, z) in an octant whose entries are 2^level wide.
constexpr int childSlot(int x, int y, int z, int level) {
    return ((x >> level) & 1) | (((z >> level) & 1) << 1) | (((y >> level) & 1) << 2);
}

using Colour = voxel::Voxel;  // RGBA8; for voxel worlds alpha is the texture slot

// How the colours of a tree are stored.
enum class AttributeLayout {
    None,      // opacity only
    PerEntry,  // one colour per entry (the leaf stored there); colours are part of the sharing key
    // Geometry shared on opacity alone; one colour per leaf of the expanded (unshared) tree in
    // depth-first order, found through a per-octant subtree leaf count (Dolonius et al. 2017).
    LeafOrder,
};

struct Octree {
    int depth = 1;  // the tree is 2^depth voxels a side
    // The box [0, size) the content occupies within the cube (a 300x120x300 world in a 512^3
    // cube): rays are clipped to it. Zero means the whole cube.
    Int3 size;
    std::vector<std::uint32_t> nodes;  // the design's array; entries 0-7 are the root octant
    // How `colours` is indexed when it is not empty (PerEntry or LeafOrder).
    AttributeLayout layout = AttributeLayout::PerEntry;
    // PerEntry: one per entry. LeafOrder: one per leaf of the expanded tree, depth first.
    std::vector<Colour> colours;
    // LeafOrder only: per octant (base / 8), the leaves of its expanded subtree (the attribute
    // index); leafCounts[0] == colours.size().
    std::vector<std::uint32_t> leafCounts;

    int side() const { return 1 << depth; }
    Int3 extent() const { return size.x > 0 ? size : Int3(side(), side(), side()); }
    bool hasColours() const { return !colours.empty(); }
    AttributeLayout attributes() const { return colours.empty() ? AttributeLayout::None : layout; }
    bool leafOrder() const { return attributes() == AttributeLayout::LeafOrder; }
};

const char* attributeLayoutName(AttributeLayout layout);  // "none", "per-entry", "leaf-order"

// The leaf holding a cell: its entry index, its opacity, and the cube it covers.
struct Leaf {
    std::uint32_t entry = 0;
    std::uint32_t colourIndex = 0;  // its index in `colours`: the entry, or its leaf order
    std::uint8_t opacity = 0;
    int level = 0;  // the cube is 2^level voxels a side
    Int3 origin;    // its lowest corner
};

// The leaf holding `cell` (inside [0, side)^3) of a validated octree.
Leaf findLeaf(const Octree& tree, Int3 cell);
std::uint8_t opacityAt(const Octree& tree, Int3 cell);
Colour colourAt(const Octree& tree, Int3 cell);  // transparent black without colours

// Size and sparsity: octants and bytes of the array (geometry) and of the colours (attributes),
// and bits per voxel over the solid voxels (opacity > 0) and over the whole cube.
struct OctreeStats {
    int depth = 0;
    std::uint64_t octants = 0;        // runs of 8 entries in the array
    std::uint64_t reachable = 0;      // octants reachable from the root
    std::uint64_t geometryBytes = 0;  // 4 per entry
    AttributeLayout layout = AttributeLayout::None;
    std::uint64_t attributeBytes = 0;       // the colours: 4 per entry or per leaf
    std::uint64_t attributeIndexBytes = 0;  // LeafOrder: the leaf counts, 4 per octant
    std::uint64_t solidVoxels = 0;          // voxels with opacity > 0 (the expanded tree)
    std::uint64_t totalVoxels = 0;          // side^3
    std::uint64_t expandedOctants = 0;      // octants the tree would have without sharing
    double bitsPerSolidVoxel = 0;           // geometry bits / solid voxels
    double bitsPerVoxel = 0;                // geometry bits / total voxels
};
OctreeStats measure(const Octree& tree);

}  // namespace luxel::octree
