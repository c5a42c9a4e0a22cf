// libFuzzer target for the octree container reader (.lxo, luxel::octree::parseOctree): any bytes
// must give a tree or an Error, never a crash, a sanitizer report or an allocation the header
// check did not allow. A tree that parses must also be safe to walk (validation is all the
// traversal relies on) and must serialise back to the same bytes (the format has no slack; a
// version 1 file is written as version 2, which must read back to itself).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_trace.h"

namespace {

using namespace luxel;

// Leaf lookups at the corners, the centre and a few cells between, so the descent follows
// different paths through the hostile tree. A leaf must lie inside the array and the cube.
void lookUp(const octree::Octree& tree) {
    const int s = tree.side() - 1;
    const Int3 cells[] = {{0, 0, 0}, {s, s, s}, {s / 2, s / 3, s / 5}, {s, 0, s / 2}, {1, s, 0}};
    volatile std::uint32_t sink = 0;
    for (const Int3& c : cells) {
        const octree::Leaf leaf = octree::findLeaf(tree, c);
        if (leaf.entry >= tree.nodes.size() || leaf.level >= tree.depth) __builtin_trap();
        sink = sink + leaf.opacity + octree::colourAt(tree, c).a;
    }
}

// Rays through the content box from outside and inside, axis-aligned and oblique, so the exact
// walk descends and pops along different paths. A hit must name an entry of the array.
void walk(const octree::Octree& tree) {
    const Int3 e = tree.extent();
    const Vec3d centre{e.x * 0.5, e.y * 0.5, e.z * 0.5};
    const Vec3d from[] = {{-1.0, centre.y, centre.z},
                          {centre.x, e.y + 1.0, centre.z},
                          {-0.5, -0.25, -0.75},
                          {e.x + 0.5, centre.y * 0.3, e.z + 0.5},
                          {centre.x * 0.9, centre.y * 1.1, centre.z * 0.7}};
    volatile std::uint32_t sink = 0;
    for (const Vec3d& o : from) {
        Vec3d d = centre - o;
        if (dot(d, d) < 1e-6) d = {0.3, -0.8, 0.5};
        const octree::OctreeHit hit = octree::castRay(tree, {o, normalize(d)});
        if (hit.hit.hit && hit.entry >= tree.nodes.size()) __builtin_trap();
        sink = sink + hit.entry;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const Result<octree::Octree> tree = octree::parseOctree(bytes, "fuzz.lxo");
    if (!tree.ok()) {
        volatile std::size_t length = tree.error().message().size();
        (void)length;
        return 0;
    }
    // A version 2 file has no slack, so it serialises back to itself. A version 1 file is written
    // as version 2, which must read back to the same tree and bytes.
    const std::string written = octree::serializeOctree(*tree);
    if (bytes.size() >= 12 && bytes[8] == octree::kOctreeFileVersion) {
        if (written != bytes) __builtin_trap();
    } else {
        const Result<octree::Octree> again = octree::parseOctree(written, "written.lxo");
        if (!again.ok() || octree::serializeOctree(*again) != written) __builtin_trap();
    }
    const octree::OctreeStats stats = octree::measure(*tree);
    volatile std::uint64_t solid = stats.solidVoxels;
    (void)solid;
    lookUp(*tree);
    walk(*tree);
    return 0;
}
