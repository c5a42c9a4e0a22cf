// The parallel builder (octree_build.h) gives exactly the array of the plain recursion, whatever
// the thread count, and the sparse terrain's uniform answers are right and effective. Build times
// are measured in bench/bench_octree.cpp.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <map>

#include "luxel/core/parallel.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/volume_generators.h"
#include "luxel/voxel/generators.h"

namespace luxel::octree {
namespace {

// The builder as docs/algorithms/sparse-voxel-octree.md §2 states it, with nothing clever: a
// depth-first recursion reading every voxel (no uniform answers), collapsing uniform octants and
// interning the rest in an ordered map, appended in the order they are finished.
class ReferenceBuilder {
  public:
    using Read = std::function<void(Int3, std::uint8_t&, Colour&)>;
    ReferenceBuilder(Int3 size, bool colours, bool collapse, Read read)
        : size_(size), colours_(colours), collapse_(collapse), read_(std::move(read)) {}

    Octree build() {
        Octree tree;
        tree.depth = depthFor(size_);
        tree.size = size_;
        tree.nodes.assign(8, 0);
        if (colours_) tree.colours.assign(8, Colour{});
        tree_ = &tree;
        const int half = 1 << (tree.depth - 1);
        for (int slot = 0; slot < 8; ++slot) {
            const Entry e = entry(child({0, 0, 0}, slot, half), tree.depth - 1);
            tree.nodes[slot] = e.value;
            if (colours_) tree.colours[slot] = e.colour;
        }
        return tree;
    }

  private:
    struct Entry {
        std::uint32_t value = 0;
        Colour colour;
    };
    static Int3 child(Int3 o, int slot, int half) {
        return {o.x + (slot & 1) * half, o.y + (slot >> 2) * half, o.z + ((slot >> 1) & 1) * half};
    }
    Entry entry(Int3 origin, int level) {
        const bool out = origin.x >= size_.x || origin.y >= size_.y || origin.z >= size_.z;
        if (level == 0) {
            Entry e;
            if (out) return e;
            std::uint8_t opacity = 0;
            read_(origin, opacity, e.colour);
            e.value = opacity;
            if (opacity == 0 || !colours_) e.colour = Colour{};
            return e;
        }
        if (out && collapse_) return {};
        std::array<std::uint32_t, 16> key{};
        Entry children[8];
        bool uniform = collapse_;
        for (int slot = 0; slot < 8; ++slot) {
            children[slot] = entry(child(origin, slot, 1 << (level - 1)), level - 1);
            const Entry& e = children[slot];
            key[slot] = e.value;
            const Colour c = e.colour;
            key[8 + slot] = colours_ ? (c.r | c.g << 8 | c.b << 16 | std::uint32_t{c.a} << 24) : 0;
            uniform =
                uniform && e.value < 256 && e.value == children[0].value && c == children[0].colour;
        }
        if (uniform) return children[0];
        auto [it, added] =
            octants_.try_emplace(key, static_cast<std::uint32_t>(tree_->nodes.size()));
        if (added) {
            for (int slot = 0; slot < 8; ++slot) {
                tree_->nodes.push_back(children[slot].value);
                if (colours_) tree_->colours.push_back(children[slot].colour);
            }
        }
        return {it->second + 248, Colour{}};
    }

    Int3 size_;
    bool colours_, collapse_;
    Read read_;
    Octree* tree_ = nullptr;
    std::map<std::array<std::uint32_t, 16>, std::uint32_t> octants_;
};

Octree reference(const Volume& v, const BuildOptions& options) {
    return ReferenceBuilder(v.size(), options.colours && v.hasColours(), options.collapse,
                            [&](Int3 c, std::uint8_t& o, Colour& colour) {
                                o = v.opacity(c.x, c.y, c.z);
                                colour = v.colour(c.x, c.y, c.z);
                            })
        .build();
}

Octree reference(const voxel::VoxelWorld& w, const BuildOptions& options) {
    return ReferenceBuilder(w.size(), options.colours, options.collapse,
                            [&](Int3 c, std::uint8_t& o, Colour& colour) {
                                colour = w.get(c.x, c.y, c.z);
                                o = colour.solid() ? 255 : 0;
                            })
        .build();
}

Octree reference(const OctreeSource& s, const BuildOptions& options) {
    return ReferenceBuilder(s.size(), options.colours && s.hasColours(), options.collapse,
                            [&](Int3 c, std::uint8_t& o, Colour& colour) { s.voxel(c, o, colour); })
        .build();
}

// Builds with 1, 2 and all threads; every array must equal the reference.
template <typename Input>
void expectExact(const Input& input, const BuildOptions& options, const char* what) {
    const Octree expected = reference(input, options);
    for (int threads : {1, 2, 0}) {
        ThreadLimit limit(threads);
        auto built = buildOctree(input, options);
        ASSERT_TRUE(built.ok()) << built.error().message();
        EXPECT_EQ(built->depth, expected.depth) << what;
        EXPECT_EQ(built->nodes, expected.nodes) << what << ", threads " << threads;
        EXPECT_EQ(built->colours, expected.colours) << what << ", threads " << threads;
    }
    std::printf("%s: %zu entries, identical for 1, 2 and all threads\n", what,
                expected.nodes.size());
}

TEST(OctreeBuildSpeed, PhantomIsTheReferenceArrayForAnyThreadCount) {
    auto phantom = makePhantom(48);
    ASSERT_TRUE(phantom.ok());
    expectExact(*phantom, {}, "phantom 48 with colours");
    expectExact(*phantom, {.colours = false}, "phantom 48 opacity only");
    expectExact(*phantom, {.colours = true, .collapse = false}, "phantom 48 without collapse");
}

TEST(OctreeBuildSpeed, VoxelWorldIsTheReferenceArrayForAnyThreadCount) {
    auto world = voxel::VoxelWorld::create({72, 40, 56}, 8);
    ASSERT_TRUE(world.ok());
    voxel::TerrainOptions terrain;
    terrain.seed = 5;
    terrain.caves = true;
    ASSERT_TRUE(voxel::generateTerrain(*world, terrain).ok());
    // Worlds default to leaf-order colours (a builder of its own); the parallel builder makes the
    // per-entry and the opacity-only arrays.
    expectExact(*world, {.layout = AttributeLayout::PerEntry}, "world 72x40x56 with colours");
    expectExact(*world, {.colours = false}, "world 72x40x56 opacity only");
}

TEST(OctreeBuildSpeed, SparseTerrainIsTheReferenceArrayForAnyThreadCount) {
    const auto terrain = makeSparseTerrain(128, 3);
    expectExact(*terrain, {}, "sparse terrain 128 with colours");
    expectExact(*terrain, {.colours = false}, "sparse terrain 128 opacity only");
}

// Every uniform answer of the sparse terrain is true, and it answers every block up to 128 wide
// that is all air or all stone (its exact height tiles reach that far), or the build would read
// voxels it could skip. Checked voxel by voxel over a quarter of the footprint (which has
// uniform blocks up to 64 wide).
TEST(OctreeBuildSpeed, SparseTerrainAnswersUniformBlocksFromItsHeights) {
    const int side = 256;
    const auto terrain = makeSparseTerrain(side, 3);
    for (int level = 1; level <= 7; ++level) {
        const int n = 1 << level;
        std::uint64_t airOrStone = 0, answered = 0;
        for (int z = 0; z < side / 2; z += n) {
            for (int y = 0; y < side; y += n) {
                for (int x = 0; x < side / 2; x += n) {
                    std::uint8_t o0 = 0, o = 0;
                    Colour c0, c;
                    terrain->voxel({x, y, z}, o0, c0);
                    bool uniform = true;
                    for (int k = 0; k < n && uniform; ++k) {
                        for (int j = 0; j < n && uniform; ++j) {
                            for (int i = 0; i < n && uniform; ++i) {
                                terrain->voxel({x + i, y + j, z + k}, o, c);
                                uniform = o == o0 && (o == 0 || c == c0);
                            }
                        }
                    }
                    const auto answer = terrain->uniformBlock({x, y, z}, level);
                    if (answer) {
                        ASSERT_TRUE(uniform) << "block " << x << "," << y << "," << z << " level "
                                             << level << " is not uniform";
                        ASSERT_EQ(answer->opacity, o0);
                        if (o0 != 0) {
                            ASSERT_TRUE(answer->colour == c0);
                        }
                        ++answered;
                    }
                    // Uniform dirt is possible but not promised; air and stone are.
                    const bool stone = o0 != 0 && c0 == Colour{125, 125, 130, 1};
                    if (uniform && (o0 == 0 || stone)) ++airOrStone;
                }
            }
        }
        std::printf("level %d: %llu of %llu all-air or all-stone blocks answered\n", level,
                    static_cast<unsigned long long>(answered),
                    static_cast<unsigned long long>(airOrStone));
        EXPECT_EQ(answered, airOrStone) << "level " << level;
    }
}

}  // namespace
}  // namespace luxel::octree
