#include "voxel/vox_scene_graph.h"

#include <algorithm>
#include <limits>

namespace luxel::voxel::vox {
namespace {

// Translations are int32 in the format; composed ones are kept far below int64 overflow.
constexpr std::int64_t kMaxTranslation = std::int64_t{1} << 31;

bool hiddenIn(const Dict& dict) {
    const std::string* v = lookup(dict, "_hidden");
    return v && *v == "1";
}

// A keyframe's `_f` (absent: `fallback`); must be 0 or more.
int frameOf(const Dict& dict, int fallback, const FieldReader& reader) {
    const std::string* f = lookup(dict, "_f");
    if (!f) return fallback;
    std::int64_t v = 0;
    if (!parseInt(*f, v) || v < 0 || v > std::numeric_limits<int>::max()) {
        reader.fail("_f '" + *f + "' is not a frame index (a whole number from 0)");
    }
    return static_cast<int>(v);
}

Transform transformOf(const Dict& dict, const FieldReader& reader) {
    Transform t;
    if (const std::string* r = lookup(dict, "_r")) {
        std::int64_t packed = 0;
        std::optional<Rotation> rotation;
        if (parseInt(*r, packed) && packed >= 0 && packed < 128) {
            rotation = Rotation::fromByte(static_cast<int>(packed));
        }
        if (!rotation) reader.fail("_r '" + *r + "' is not a valid packed rotation");
        t.rotation = *rotation;
    }
    if (const std::string* text = lookup(dict, "_t")) {
        std::string_view rest = *text;
        for (int a = 0; a < 3; ++a) {
            while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
            const std::size_t end = std::min(rest.find(' '), rest.size());
            std::int64_t v = 0;
            if (!parseInt(rest.substr(0, end), v) || v < -kMaxTranslation || v > kMaxTranslation) {
                reader.fail("_t '" + *text + "' is not three whole numbers (each within +-2^31)");
            }
            t.translation[a] = v;
            rest.remove_prefix(end);
        }
        while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
        if (!rest.empty()) reader.fail("_t '" + *text + "' has more than three numbers");
    }
    return t;
}

// The count field of a list whose items take at least `itemBytes` each.
int countOf(FieldReader& reader, const char* what, std::size_t itemBytes) {
    const std::int32_t n = reader.i32(what);
    if (n < 0 || static_cast<std::size_t>(n) > reader.left() / itemBytes) {
        reader.fail(std::string(what) + " is " + std::to_string(n) + ", but " +
                    std::to_string(reader.left()) + " bytes remain in the chunk");
    }
    return n;
}

template <typename T>
const T& keyframeAt(const std::vector<T>& keys, int frame) {
    // The last keyframe at or before `frame` holds (steps, no interpolation); before the first,
    // the first.
    const T* chosen = &keys.front();
    for (const T& k : keys) {
        if (k.frame <= frame) chosen = &k;
    }
    return *chosen;
}

}  // namespace

std::optional<Rotation> Rotation::fromByte(int packed) {
    const int row0 = packed & 3, row1 = (packed >> 2) & 3;
    if (row0 == 3 || row1 == 3 || row0 == row1) return std::nullopt;
    Rotation r;
    r.column = {row0, row1, 3 - row0 - row1};
    for (int i = 0; i < 3; ++i) r.sign[i] = (packed >> (4 + i)) & 1 ? -1 : 1;
    return r;
}

Int3L Rotation::apply(const Int3L& v) const {
    return {sign[0] * v[column[0]], sign[1] * v[column[1]], sign[2] * v[column[2]]};
}

Rotation Rotation::operator*(const Rotation& inner) const {
    Rotation r;
    for (int i = 0; i < 3; ++i) {
        r.column[i] = inner.column[column[i]];
        r.sign[i] = sign[i] * inner.sign[column[i]];
    }
    return r;
}

Transform Transform::operator*(const Transform& inner) const {
    Transform t;
    t.rotation = rotation * inner.rotation;
    const Int3L moved = rotation.apply(inner.translation);
    for (int a = 0; a < 3; ++a) t.translation[a] = moved[a] + translation[a];
    return t;
}

void SceneGraph::addNode(int id, Node node, std::size_t at) {
    if (id < 0) throw VoxFailure{at + 12, "node id " + std::to_string(id) + " is negative"};
    if (index_.count(id)) {
        throw VoxFailure{at + 12, "node id " + std::to_string(id) +
                                      " is defined twice (first at byte " +
                                      std::to_string(nodes_[index_[id]].at) + ")"};
    }
    node.at = at;
    index_[id] = nodes_.size();
    nodes_.push_back(std::move(node));
}

void SceneGraph::addTransform(Bytes bytes, const Chunk& chunk) {
    FieldReader r(bytes, chunk);
    Node node;
    node.kind = Node::Kind::Transform;
    const int id = r.i32("node id");
    node.hidden = hiddenIn(r.dict("node attributes"));
    node.children = {r.i32("child node id")};
    r.i32("reserved id");
    node.layer = r.i32("layer id");
    const int frames = countOf(r, "frame count", 4);
    for (int f = 0; f < frames; ++f) {
        const Dict d = r.dict("frame attributes");
        node.keyframes.push_back({frameOf(d, f, r), transformOf(d, r)});
    }
    if (node.keyframes.empty()) node.keyframes.push_back({0, Transform{}});
    std::stable_sort(node.keyframes.begin(), node.keyframes.end(),
                     [](const auto& a, const auto& b) { return a.frame < b.frame; });
    frameCount_ = std::max(frameCount_, node.keyframes.back().frame + 1);
    addNode(id, std::move(node), chunk.at);
}

void SceneGraph::addGroup(Bytes bytes, const Chunk& chunk) {
    FieldReader r(bytes, chunk);
    Node node;
    node.kind = Node::Kind::Group;
    const int id = r.i32("node id");
    node.hidden = hiddenIn(r.dict("node attributes"));
    const int children = countOf(r, "child count", 4);
    for (int i = 0; i < children; ++i) node.children.push_back(r.i32("child node id"));
    addNode(id, std::move(node), chunk.at);
}

void SceneGraph::addShape(Bytes bytes, const Chunk& chunk) {
    FieldReader r(bytes, chunk);
    Node node;
    node.kind = Node::Kind::Shape;
    const int id = r.i32("node id");
    node.hidden = hiddenIn(r.dict("node attributes"));
    const int models = countOf(r, "model count", 8);
    for (int i = 0; i < models; ++i) {
        const int model = r.i32("model id");
        const Dict d = r.dict("model attributes");
        node.models.push_back({frameOf(d, i, r), model});
    }
    std::stable_sort(node.models.begin(), node.models.end(),
                     [](const auto& a, const auto& b) { return a.frame < b.frame; });
    if (!node.models.empty()) {
        frameCount_ = std::max(frameCount_, node.models.back().frame + 1);
    }
    addNode(id, std::move(node), chunk.at);
}

void SceneGraph::addLayer(Bytes bytes, const Chunk& chunk) {
    FieldReader r(bytes, chunk);
    const int id = r.i32("layer id");
    layerHidden_[id] = hiddenIn(r.dict("layer attributes"));
}

std::vector<Placement> SceneGraph::place(int frame, int modelCount) const {
    if (nodes_.empty()) return {};
    if (!index_.count(0)) {
        throw VoxFailure{nodes_.front().at, "the scene graph has no root node 0"};
    }
    Walk walk;
    walk.frame = frame;
    walk.modelCount = modelCount;
    walk.onPath.assign(nodes_.size(), 0);
    visit(0, Transform{}, 0, nodes_[index_.at(0)].at, walk);
    return std::move(walk.out);
}

void SceneGraph::visit(int id, const Transform& parent, int depth, std::size_t from,
                       Walk& walk) const {
    const auto found = index_.find(id);
    if (found == index_.end()) {
        throw VoxFailure{from, "node " + std::to_string(id) + " does not exist"};
    }
    const Node& node = nodes_[found->second];
    if (walk.onPath[found->second]) {
        throw VoxFailure{node.at, "node " + std::to_string(id) +
                                      " is its own ancestor (a cycle in the scene graph)"};
    }
    if (depth >= kMaxGraphDepth) {
        throw VoxFailure{node.at, "the scene graph nests deeper than " +
                                      std::to_string(kMaxGraphDepth) + " nodes"};
    }
    if (++walk.visits > kMaxNodeVisits) {
        throw VoxFailure{node.at, "the scene graph visits more than " +
                                      std::to_string(kMaxNodeVisits) +
                                      " nodes (groups shared many times over)"};
    }
    if (node.hidden) return;
    if (node.kind == Node::Kind::Transform) {
        const auto layer = layerHidden_.find(node.layer);
        if (layer != layerHidden_.end() && layer->second) return;
    }
    walk.onPath[found->second] = 1;
    switch (node.kind) {
        case Node::Kind::Transform: {
            const Transform t = parent * keyframeAt(node.keyframes, walk.frame).value;
            visit(node.children.front(), t, depth + 1, node.at, walk);
            break;
        }
        case Node::Kind::Group:
            for (int child : node.children) visit(child, parent, depth + 1, node.at, walk);
            break;
        case Node::Kind::Shape: {
            if (node.models.empty()) break;
            const int model = keyframeAt(node.models, walk.frame).value;
            if (model < 0 || model >= walk.modelCount) {
                throw VoxFailure{node.at, "shape node " + std::to_string(id) + " names model " +
                                              std::to_string(model) + ", the file has " +
                                              std::to_string(walk.modelCount) + " (0.." +
                                              std::to_string(walk.modelCount - 1) + ")"};
            }
            if (walk.out.size() >= kMaxPlacements) {
                throw VoxFailure{node.at, "the scene graph places more than " +
                                              std::to_string(kMaxPlacements) + " models"};
            }
            walk.out.push_back({model, parent});
            break;
        }
    }
    walk.onPath[found->second] = 0;
}

}  // namespace luxel::voxel::vox
