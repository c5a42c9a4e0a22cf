// The scene graph of a MagicaVoxel file (MagicaVoxel-file-format-vox-extension.txt): transform
// (nTRN), group (nGRP) and shape (nSHP) nodes and layers (LAYR), flattened into model placements
// for one animation frame. Format details and the conventions luxel follows:
// docs/scene-format-voxel.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "voxel/vox_chunks.h"

namespace luxel::voxel::vox {

using Int3L = std::array<std::int64_t, 3>;

// A rotation that maps axes onto axes: row i holds `sign[i]` in column `column[i]`, so
// out[i] = sign[i] * in[column[i]].
struct Rotation {
    std::array<int, 3> column{0, 1, 2};
    std::array<int, 3> sign{1, 1, 1};

    // The packed byte of nTRN's `_r`: bits 0-1 the column of row 0's entry, bits 2-3 that of row
    // 1 (row 2 takes the remaining column), bits 4, 5, 6 the signs of rows 0, 1, 2 (set:
    // negative). Empty for a byte that names a column twice or column 3.
    static std::optional<Rotation> fromByte(int packed);
    Int3L apply(const Int3L& v) const;
    Rotation operator*(const Rotation& inner) const;  // apply inner, then this
    bool operator==(const Rotation&) const = default;
};

// x -> rotation * x + translation, in vox axes (z up).
struct Transform {
    Rotation rotation;
    Int3L translation{0, 0, 0};
    Transform operator*(const Transform& inner) const;
};

// One model placed in the scene: voxel v of the model lands on cell
// transform(v - floor(size / 2)), MagicaVoxel's pivot convention.
struct Placement {
    int model = 0;
    Transform transform;
};

// Deepest accepted chain of nodes from the root, and most placements one file may produce
// (shared groups multiply: a group used twice by a group used twice ...).
inline constexpr int kMaxGraphDepth = 256;
inline constexpr std::size_t kMaxPlacements = std::size_t{1} << 16;
// Most node visits one walk may make (shared groups that place nothing still cost visits).
inline constexpr std::size_t kMaxNodeVisits = std::size_t{1} << 20;

class SceneGraph {
  public:
    // Each reads one chunk's content; a malformed field throws VoxFailure.
    void addTransform(Bytes bytes, const Chunk& chunk);
    void addGroup(Bytes bytes, const Chunk& chunk);
    void addShape(Bytes bytes, const Chunk& chunk);
    void addLayer(Bytes bytes, const Chunk& chunk);

    bool empty() const { return nodes_.empty(); }
    // 1 + the largest keyframe index of any transform or shape (1 without animation).
    int frameCount() const { return frameCount_; }
    // Every visible model placement at `frame`, from root node 0. Throws VoxFailure for a missing
    // root or child, a model id outside 0..modelCount-1, a cycle, nesting deeper than
    // kMaxGraphDepth, more than kMaxPlacements placements or kMaxNodeVisits visits.
    std::vector<Placement> place(int frame, int modelCount) const;

  private:
    template <typename T>
    struct Keyed {
        int frame;
        T value;
    };
    struct Node {
        enum class Kind { Transform, Group, Shape } kind = Kind::Group;
        std::size_t at = 0;  // chunk offset, for messages
        bool hidden = false;
        int layer = -1;
        std::vector<int> children;                // transform: one; group: any
        std::vector<Keyed<Transform>> keyframes;  // transform
        std::vector<Keyed<int>> models;           // shape
    };
    void addNode(int id, Node node, std::size_t at);
    struct Walk {
        int frame = 0, modelCount = 0;
        std::vector<char> onPath;  // by nodes_ index: on the path from the root
        std::size_t visits = 0;
        std::vector<Placement> out;
    };
    void visit(int id, const Transform& parent, int depth, std::size_t from, Walk& walk) const;

    std::vector<Node> nodes_;
    std::unordered_map<int, std::size_t> index_;  // node id -> nodes_ index
    std::unordered_map<int, bool> layerHidden_;
    int frameCount_ = 1;
};

}  // namespace luxel::voxel::vox
