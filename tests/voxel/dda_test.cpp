// Tests for the Amanatides & Woo voxel traversal: edge cases and a brute-force oracle, run on both
// backends: castRays on the CPU (double) and VoxelGpuRenderer::castRays on the Vulkan device
// (float; lavapipe on CPU-only machines, skipped with the reason when there is no device). Both
// run the same kernel (src/gpu/shaders/shared/voxel_dda.h), so the edge-case rules hold on both.
// The same suite runs on the sparse voxel octree built from each test world
// (src/gpu/shaders/shared/octree_walk.h): its hits must be the dense walk's, edge cases included.
#include "luxel/voxel/dda.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_trace.h"
#include "luxel/voxel/voxel_gpu.h"

namespace luxel::voxel {
namespace {

enum class Backend { Cpu, Gpu, OctreeCpu, OctreeGpu };

// One Vulkan context for the whole suite (validation on: any message fails the test).
gpu::Context* sharedContext() {
    static std::unique_ptr<gpu::Context> context = [] {
        auto c = gpu::Context::create({.device = "", .validation = true});
        return c ? std::move(*c) : nullptr;
    }();
    return context.get();
}

class VoxelDdaTest : public ::testing::TestWithParam<Backend> {
  protected:
    void SetUp() override {
        if (gpu() && !sharedContext()) {
            GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
        }
    }
    void TearDown() override {
        if (gpu() && sharedContext()) {
            EXPECT_EQ(sharedContext()->validationMessages(), 0)
                << sharedContext()->lastValidationMessage();
        }
    }
    bool gpu() const { return GetParam() == Backend::Gpu || GetParam() == Backend::OctreeGpu; }
    bool octree() const {
        return GetParam() == Backend::OctreeCpu || GetParam() == Backend::OctreeGpu;
    }

    std::vector<Hit> castAll(const VoxelWorld& world, const std::vector<Ray>& rays,
                             double tMax = kInfinity, int stepCap = 0,
                             ChunkSkip skip = ChunkSkip::Enabled) const {
        if (octree()) {
            // Without collapse every leaf is a voxel, so the octree visits every cell as the
            // plain walk does (ChunkSkip::Disabled); with it, uniform octants are jumped.
            auto tree = octree::buildOctree(
                world, {.colours = false, .collapse = skip == ChunkSkip::Enabled});
            EXPECT_TRUE(tree.ok());
            const octree::TraceOptions options{.tMax = tMax, .stepCap = stepCap};
            std::vector<octree::OctreeHit> found;
            if (gpu()) {
                auto uploaded = octree::OctreeGpu::create(*sharedContext(), *tree);
                EXPECT_TRUE(uploaded.ok()) << uploaded.error().message();
                auto cast = uploaded->castRays(rays, options);
                EXPECT_TRUE(cast.ok()) << cast.error().message();
                if (cast.ok()) found = std::move(*cast);
                found.resize(rays.size());
            } else {
                found = octree::castRays(*tree, rays, options);
            }
            std::vector<Hit> hits;
            for (const octree::OctreeHit& h : found) hits.push_back(h.hit);
            return hits;
        }
        if (!gpu()) return castRays(world, rays, tMax, stepCap, skip);
        auto renderer = VoxelGpuRenderer::create(*sharedContext(), world);
        EXPECT_TRUE(renderer.ok()) << renderer.error().message();
        auto hits = renderer->castRays(rays, tMax, stepCap, skip);
        EXPECT_TRUE(hits.ok()) << hits.error().message();
        return hits.ok() ? *hits : std::vector<Hit>(rays.size());
    }

    Hit cast(const VoxelWorld& world, const Ray& ray, double tMax = kInfinity, int stepCap = 0,
             ChunkSkip skip = ChunkSkip::Enabled) const {
        return castAll(world, {ray}, tMax, stepCap, skip)[0];
    }
};

std::string backendName(const ::testing::TestParamInfo<Backend>& info) {
    static const char* const kNames[] = {"Cpu", "Gpu", "OctreeCpu", "OctreeGpu"};
    return kNames[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Backends, VoxelDdaTest,
                         ::testing::Values(Backend::Cpu, Backend::Gpu, Backend::OctreeCpu,
                                           Backend::OctreeGpu),
                         backendName);

// The ray the GPU sees: rounded to float.
Ray roundedToFloat(const Ray& r) {
    const auto f = [](const Vec3d& v) {
        return Vec3d{double(float(v.x)), double(float(v.y)), double(float(v.z))};
    };
    return {f(r.origin), f(r.direction)};
}

constexpr Voxel kStone{128, 128, 128, 255};

VoxelWorld makeWorld(Int3 size, int chunkSize = 8) {
    Result<VoxelWorld> world = VoxelWorld::create(size, chunkSize);
    EXPECT_TRUE(world.ok());
    return std::move(world).value();
}

// Every field but `steps` (which chunk jumps change).
void expectSameHit(const Hit& a, const Hit& b) {
    EXPECT_EQ(a.hit, b.hit);
    EXPECT_EQ(a.capped, b.capped);
    EXPECT_EQ(a.voxel, b.voxel);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.u, b.u);
    EXPECT_EQ(a.v, b.v);
}

TEST_P(VoxelDdaTest, AxisAlignedRaysHitWithExactT) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 8, kStone);
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {1, -1}) {
            Vec3d origin{8.5, 8.5, 8.5}, direction;
            origin[axis] = sign > 0 ? 2.25 : 14.75;
            direction[axis] = sign;
            const Hit hit = cast(world, {origin, direction});
            ASSERT_TRUE(hit.hit) << axis << " " << sign;
            EXPECT_EQ(hit.voxel, (Int3{8, 8, 8}));
            EXPECT_EQ(hit.t, 5.75);
            Int3 normal;
            normal[axis] = -sign;
            EXPECT_EQ(hit.normal, normal);
            EXPECT_EQ(hit.point[axis], sign > 0 ? 8.0 : 9.0);
            EXPECT_EQ(hit.u, 0.5f);
            EXPECT_EQ(hit.v, 0.5f);
            EXPECT_FALSE(hit.capped);
        }
    }
}

TEST_P(VoxelDdaTest, SignedZeroComponentsGiveIdenticalResults) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 8, kStone);
    world.set(3, 8, 3, kStone);
    // Origins inside cells and exactly on planes of the zero axes.
    for (Vec3d origin : {Vec3d{1.5, 8.5, 8.5}, Vec3d{1.5, 8.0, 8.0}, Vec3d{1.5, 9.0, 9.0},
                         Vec3d{1.5, 8.0, 9.0}, Vec3d{-3.0, 8.25, 8.0}}) {
        const Hit reference = cast(world, {origin, {1.0, 0.0, 0.0}});
        for (double y : {0.0, -0.0}) {
            for (double z : {0.0, -0.0}) {
                const Hit hit = cast(world, {origin, {1.0, y, z}});
                expectSameHit(hit, reference);
                EXPECT_EQ(hit.steps, reference.steps);
                EXPECT_FALSE(std::isnan(hit.t));
            }
        }
    }
    // On the planes y = 8 and z = 8 the ray belongs to the cells above (floor): it hits (8, 8, 8).
    const Hit onPlanes = cast(world, {{1.5, 8.0, 8.0}, {1.0, -0.0, -0.0}});
    ASSERT_TRUE(onPlanes.hit);
    EXPECT_EQ(onPlanes.voxel, (Int3{8, 8, 8}));
    EXPECT_EQ(onPlanes.t, 6.5);
    // On the planes y = 9 and z = 9 it belongs to cells (9, 9): it passes the voxel.
    EXPECT_FALSE(cast(world, {{1.5, 9.0, 9.0}, {1.0, -0.0, 0.0}}).hit);
}

TEST_P(VoxelDdaTest, TinyComponentsBehaveLikeZero) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 8, kStone);
    for (double e : {1e-9, -1e-9, 1e-300, -1e-300}) {
        const Hit hit = cast(world, {{2.5, 8.5, 8.5}, {1.0, e, -e}});
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.voxel, (Int3{8, 8, 8}));
        EXPECT_EQ(hit.normal, (Int3{-1, 0, 0}));
        EXPECT_NEAR(hit.t, 5.5, 1e-12);
    }
}

TEST_P(VoxelDdaTest, OriginOnBoundariesAndCorners) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 8, kStone);
    // On the entry face of the solid voxel, moving in: hit at t = 0 with that face's normal.
    Hit hit = cast(world, {{8.0, 8.5, 8.5}, {1.0, 0.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.t, 0.0);
    EXPECT_EQ(hit.normal, (Int3{-1, 0, 0}));
    // On a face of the solid voxel, moving away: no self-hit on either side.
    EXPECT_FALSE(cast(world, {{8.0, 8.5, 8.5}, {-1.0, 0.3, 0.2}}).hit);
    EXPECT_FALSE(cast(world, {{9.0, 8.5, 8.5}, {1.0, 0.3, 0.2}}).hit);
    EXPECT_FALSE(cast(world, {{8.5, 9.0, 8.5}, {0.1, 1.0, 0.2}}).hit);
    // At the voxel's corner moving into it: t = 0; the three entry planes tie, highest axis wins.
    hit = cast(world, {{8.0, 8.0, 8.0}, {1.0, 1.0, 1.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{8, 8, 8}));
    EXPECT_EQ(hit.t, 0.0);
    EXPECT_EQ(hit.normal, (Int3{0, 0, -1}));
    // From a far corner of another cell along the diagonal into the voxel's corner.
    hit = cast(world, {{6.0, 6.0, 6.0}, {1.0, 1.0, 1.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{8, 8, 8}));
    EXPECT_EQ(hit.t, 2.0);
    EXPECT_EQ(hit.normal, (Int3{0, 0, -1}));
    // Origin on the world boundary moving out misses; moving in enters.
    EXPECT_FALSE(cast(world, {{16.0, 8.5, 8.5}, {1.0, 0.0, 0.0}}).hit);
    hit = cast(world, {{16.0, 8.5, 8.5}, {-1.0, 0.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.t, 7.0);
    EXPECT_EQ(hit.normal, (Int3{1, 0, 0}));
}

TEST_P(VoxelDdaTest, OriginInsideSolidHitsAtZeroWithNoNormal) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 8, kStone);
    const Hit hit = cast(world, {{8.25, 8.5, 8.75}, {0.3, -1.0, 0.2}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{8, 8, 8}));
    EXPECT_EQ(hit.t, 0.0);
    EXPECT_EQ(hit.normal, (Int3{0, 0, 0}));
    EXPECT_EQ(hit.point, (Vec3d{8.25, 8.5, 8.75}));
    EXPECT_EQ(hit.steps, 1);
}

TEST_P(VoxelDdaTest, RaysFromOutsideTheWorld) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(0, 0, 0, kStone);
    world.set(15, 15, 15, kStone);
    // Entering through a world face: normal of that face.
    Hit hit = cast(world, {{-3.5, 0.5, 0.5}, {1.0, 0.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{0, 0, 0}));
    EXPECT_EQ(hit.t, 3.5);
    EXPECT_EQ(hit.normal, (Int3{-1, 0, 0}));
    hit = cast(world, {{15.5, 20.0, 15.5}, {0.0, -2.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.t, 2.0);  // t in units of the direction's length
    EXPECT_EQ(hit.normal, (Int3{0, 1, 0}));
    // Missing the box: pointing away, passing beside it, parallel outside it, zero and NaN.
    EXPECT_FALSE(cast(world, {{-3.5, 0.5, 0.5}, {-1.0, 0.0, 0.0}}).hit);
    EXPECT_FALSE(cast(world, {{-3.5, 0.5, 0.5}, {1.0, 2.0, 0.0}}).hit);
    EXPECT_FALSE(cast(world, {{-3.5, 17.0, 0.5}, {1.0, 0.0, 0.0}}).hit);
    EXPECT_FALSE(cast(world, {{-3.5, 16.0, 0.5}, {1.0, -0.0, 0.0}}).hit);
    EXPECT_FALSE(cast(world, {{0.5, 0.5, 0.5}, {0.0, 0.0, 0.0}}).hit);
    EXPECT_FALSE(cast(world, {{-3.5, 0.5, 0.5}, {std::nan(""), 0.0, 0.0}}).hit);
    // Grazing the world's edge (t_enter == t_exit): touches voxel (0, 0, 0) along its edge.
    hit = cast(world, {{-1.0, 1.0, 0.5}, {1.0, -1.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{0, 0, 0}));
    EXPECT_EQ(hit.t, 1.0);
    // tMax: the hit at t = 3.5 is outside [0, 3].
    EXPECT_FALSE(cast(world, {{-3.5, 0.5, 0.5}, {1.0, 0.0, 0.0}}, 3.0).hit);
    EXPECT_TRUE(cast(world, {{-3.5, 0.5, 0.5}, {1.0, 0.0, 0.0}}, 3.5).hit);
}

TEST_P(VoxelDdaTest, DiagonalThroughCornerTieStepsXFirst) {
    VoxelWorld world = makeWorld({8, 8, 8});
    world.set(1, 1, 0, kStone);
    Hit hit = cast(world, {{0.5, 0.5, 0.5}, {1.0, 1.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{1, 1, 0}));
    EXPECT_EQ(hit.t, 0.5);
    EXPECT_EQ(hit.normal, (Int3{0, -1, 0}));
    // x steps first at the tie, so the x neighbour touched along the edge is visited first.
    world.set(1, 0, 0, kStone);
    hit = cast(world, {{0.5, 0.5, 0.5}, {1.0, 1.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.voxel, (Int3{1, 0, 0}));
    EXPECT_EQ(hit.normal, (Int3{-1, 0, 0}));
    EXPECT_EQ(hit.t, 0.5);
}

TEST_P(VoxelDdaTest, ThinDiagonalWallDoesNotLeak) {
    VoxelWorld world = makeWorld({8, 8, 8});
    for (int i = 0; i < 8; ++i) {
        for (int k = 0; k < 8; ++k) world.set(i, 7 - i, k, kStone);
    }
    // Along the diagonal through cell corners: exact ties at every corner.
    for (int k = 0; k < 8; ++k) {
        const Hit hit =
            cast(world, {{0.0, 0.0, k + 0.5}, {1.0, 1.0, 0.0}}, kInfinity, 0, ChunkSkip::Disabled);
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.voxel.x + hit.voxel.y, 7);
    }
}

TEST_P(VoxelDdaTest, LongestDiagonalAndStepCap) {
    VoxelWorld world = makeWorld({16, 16, 16}, 4);
    world.set(15, 15, 15, kStone);
    const Ray diagonal{{0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}};
    Hit hit = cast(world, diagonal, kInfinity, 0, ChunkSkip::Disabled);
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.steps, 3 * 16 - 2);  // every cell of the 6-connected path
    EXPECT_EQ(hit.t, 14.5);
    EXPECT_TRUE(cast(world, diagonal, kInfinity, 46, ChunkSkip::Disabled).hit);
    hit = cast(world, diagonal, kInfinity, 45, ChunkSkip::Disabled);
    EXPECT_FALSE(hit.hit);
    EXPECT_TRUE(hit.capped);
    EXPECT_EQ(hit.steps, 45);
    // Chunk jumps need far fewer iterations for the same hit.
    const Hit skipped = cast(world, diagonal);
    expectSameHit(skipped, cast(world, diagonal, kInfinity, 0, ChunkSkip::Disabled));
    EXPECT_LT(skipped.steps, 46);
}

TEST_P(VoxelDdaTest, LongRaysDoNotDrift) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(15, 3, 9, kStone);
    // Exact entry t from far away: boundaries are recomputed from integer cells. (Float holds
    // quarter units only up to about 2^21, hence a nearer origin on the GPU.)
    const double x = gpu() ? -1e6 + 0.25 : -1e7 + 0.25;
    const Hit hit = cast(world, {{x, 3.5, 9.5}, {1.0, 0.0, 0.0}});
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.t, 15.0 - x);
    EXPECT_EQ(hit.voxel, (Int3{15, 3, 9}));
}

// Nearest closed voxel box along the ray (zero components: origin in [i, i+1)).
struct Reference {
    bool hit = false;
    Int3 voxel, normal;
    double t = kInfinity;
    double secondT = kInfinity;  // the next-nearest voxel entry, for near-tie detection
    bool normalTie = false;
};

Reference bruteForce(const std::vector<Int3>& solids, const Ray& ray) {
    Reference ref;
    for (const Int3& c : solids) {
        double enter = -kInfinity, exit = kInfinity;
        int axis = -1;
        double enters[3] = {-kInfinity, -kInfinity, -kInfinity};
        bool inside = true;
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.direction[a];
            if (d == 0.0) {
                if (!(o >= c[a] && o < c[a] + 1.0)) inside = false;
                continue;
            }
            double t0 = (c[a] - o) / d, t1 = (c[a] + 1.0 - o) / d;
            if (t0 > t1) std::swap(t0, t1);
            enters[a] = t0;
            if (t0 >= enter) enter = t0, axis = a;
            exit = std::min(exit, t1);
        }
        if (!inside) continue;
        const double t = std::max(enter, 0.0);
        if (t > exit) continue;
        if (t < ref.t) {
            ref.secondT = ref.t;
            ref.hit = true;
            ref.t = t;
            ref.voxel = c;
            ref.normal = Int3{};
            ref.normalTie = false;
            if (enter >= 0.0) {
                ref.normal[axis] = ray.direction[axis] > 0 ? -1 : 1;
                for (int a = 0; a < 3; ++a) {
                    if (a != axis && std::abs(enters[a] - enter) <= 1e-12 * (1.0 + enter)) {
                        ref.normalTie = true;
                    }
                }
            }
        } else {
            ref.secondT = std::min(ref.secondT, t);
        }
    }
    return ref;
}

TEST_P(VoxelDdaTest, RandomRaysAgreeWithBruteForce) {
    const Int3 size{24, 20, 28};
    VoxelWorld world = makeWorld(size, 8);
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Int3> solids;
    for (int z = 0; z < size.z; ++z) {
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                // Sparse, and nothing in the chunks with x < 8 and z < 8 (exercise skipping).
                if ((x < 8 && z < 8) || unit(rng) > 0.04) continue;
                world.set(x, y, z, kStone);
                solids.push_back({x, y, z});
            }
        }
    }
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
        Vec3d origin, direction;
        const double spread = i % 10 == 0 ? 1e4 : 6.0;
        for (int a = 0; a < 3; ++a) {
            origin[a] = -spread + unit(rng) * (size[a] + 2.0 * spread);
            direction[a] = unit(rng) * 2.0 - 1.0;
            if (i % 7 == 0 && a == i % 3) direction[a] = (i % 2) ? 0.0 : -0.0;
        }
        // Far origins aim at the world so they hit something.
        if (spread > 10.0) {
            for (int a = 0; a < 3; ++a) direction[a] = size[a] * unit(rng) - origin[a];
        }
        // The reference sees the ray the backend sees.
        rays.push_back(gpu() ? roundedToFloat({origin, direction}) : Ray{origin, direction});
    }
    // Relative precision of the backend's arithmetic: ties closer than this may go either way.
    const double eps = gpu() ? 2e-5 : 1e-12;
    const std::vector<Hit> jumped = castAll(world, rays, kInfinity, 0, ChunkSkip::Enabled);
    const std::vector<Hit> plain = castAll(world, rays, kInfinity, 0, ChunkSkip::Disabled);
    int hits = 0, ties = 0;
    for (int i = 0; i < static_cast<int>(rays.size()); ++i) {
        const Reference ref = bruteForce(solids, rays[i]);
        for (const Hit* result : {&jumped[i], &plain[i]}) {
            const Hit& hit = *result;
            ASSERT_EQ(hit.hit, ref.hit) << "ray " << i;
            EXPECT_FALSE(hit.capped);
            if (!hit.hit) continue;
            EXPECT_NEAR(hit.t, ref.t, 1e3 * eps * std::max(1.0, ref.t)) << "ray " << i;
            const bool tie = ref.secondT - ref.t <= eps * std::max(1.0, ref.t);
            if (tie) {
                ++ties;
                EXPECT_TRUE(world.solid(hit.voxel.x, hit.voxel.y, hit.voxel.z));
                continue;
            }
            EXPECT_EQ(hit.voxel, ref.voxel) << "ray " << i;
            if (!ref.normalTie) {
                EXPECT_EQ(hit.normal, ref.normal) << "ray " << i;
            }
            if (result == &jumped[i]) ++hits;
        }
    }
    EXPECT_GT(hits, 800);
    EXPECT_LT(ties, 10);
}

TEST_P(VoxelDdaTest, ChunkSkippingMatchesPlainTraversal) {
    // Sparse voxels in 4^3 chunks; rays from cell centres and corners along small integer
    // directions hit chunk edges and corners exactly (ties inside jumps).
    VoxelWorld world = makeWorld({32, 30, 32}, 4);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(0, 29);
    for (int i = 0; i < 40; ++i) world.set(coord(rng), coord(rng), coord(rng), kStone);
    std::uniform_int_distribution<int> cell(-2, 33), dir(-2, 2);
    std::vector<Ray> rays;
    for (int i = 0; i < 6000; ++i) {
        const double offset = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 0.5 : 0.25);
        const Vec3d origin{coord(rng) + offset, cell(rng) + offset, cell(rng) + offset};
        const Vec3d direction{double(dir(rng)), double(dir(rng)), double(dir(rng))};
        rays.push_back({origin, direction});
    }
    const std::vector<Hit> plain = castAll(world, rays, kInfinity, 0, ChunkSkip::Disabled);
    const std::vector<Hit> skipped = castAll(world, rays, kInfinity, 0, ChunkSkip::Enabled);
    int compared = 0, hits = 0;
    long stepsPlain = 0, stepsSkipped = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        expectSameHit(skipped[i], plain[i]);
        stepsPlain += plain[i].steps;
        stepsSkipped += skipped[i].steps;
        ++compared;
        hits += plain[i].hit;
    }
    EXPECT_EQ(compared, 6000);
    EXPECT_GT(hits, 100);
    EXPECT_LT(stepsSkipped * 2, stepsPlain);
}

// The GPU pass against its CPU twin ray by ray, on a terrain-like world with refreshed brick
// distances (the jumps the renderer uses). Origins on a quarter grid and power-of-two direction
// components make every product exact in float and double alike, so ties (edges and corners,
// frequent here) resolve identically and hit, voxel, normal, t and loop iterations must agree.
TEST(VoxelCastParity, GpuPassMatchesTheCpuTwinRayByRay) {
    if (!sharedContext()) {
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    }
    VoxelWorld world = VoxelWorld::create({64, 40, 72}, 8).value();
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> height(4, 30), coord(0, 63), pick(0, 10);
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0};
    for (int z = 0; z < 72; ++z) {
        for (int x = 0; x < 64; ++x) {
            const int h = (x * 7 + z * 3) % 23 + 4;
            for (int y = 0; y < h; ++y) world.set(x, y, z, kStone);
        }
    }
    for (int i = 0; i < 300; ++i) world.set(coord(rng), height(rng), coord(rng) % 72, kStone);
    world.refreshEmptySpace();
    std::vector<Ray> rays;
    for (int i = 0; i < 5000; ++i) {
        const Vec3d origin{coord(rng) + 0.25 * (i % 4), 36.0 + (i % 5), coord(rng) * 1.125 - 2.0};
        const Vec3d direction{dyadic[pick(rng)], -dyadic[3 + 2 * (i % 3)], dyadic[pick(rng)]};
        rays.push_back({origin, direction});
    }
    auto renderer = VoxelGpuRenderer::create(*sharedContext(), world);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    for (ChunkSkip skip : {ChunkSkip::Enabled, ChunkSkip::Disabled}) {
        const std::vector<Hit> cpu = castRays(world, rays, kInfinity, 0, skip);
        auto gpuHits = renderer->castRays(rays, kInfinity, 0, skip);
        ASSERT_TRUE(gpuHits.ok()) << gpuHits.error().message();
        int hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Hit& c = cpu[i];
            const Hit& g = (*gpuHits)[i];
            ASSERT_EQ(g.hit, c.hit) << "ray " << i;
            EXPECT_EQ(g.steps, c.steps) << "ray " << i;
            if (!c.hit) continue;
            ++hits;
            EXPECT_EQ(g.voxel, c.voxel) << "ray " << i;
            EXPECT_EQ(g.normal, c.normal) << "ray " << i;
            EXPECT_EQ(g.t, c.t) << "ray " << i;
        }
        EXPECT_GT(hits, 2000);  // half the rays: the rest leave through the sides
    }
    EXPECT_EQ(sharedContext()->validationMessages(), 0) << sharedContext()->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::voxel
