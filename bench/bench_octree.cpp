// The sparse voxel octree against its peers, on the same scenes, rays and run: luxel's exact octree
// traversal (octree::castRay), the dense world's DDA (voxel::castRay) and an exact hierarchical
// DDA over a NanoVDB grid (bench/nanovdb_exact_hdda.h) built from the same voxels with OpenVDB
// (dense copy, pruned so uniform regions become active tiles). Scenes: the 512^3 voxel terrain
// of bench_voxel.cpp and the 512^3 head phantom (solid = opacity > 0). Rays: primary rays of a
// 1280x720 camera and shadow rays from the primary hits toward the sun, cast on one thread.
// Counters: Mrays/s (per core), the bytes of each structure, octree bits per solid voxel, build
// times, and how many rays of each peer hit what the dense DDA hits. Also the octree build of the
// 512^3 terrain and phantom and of the 4096^3 procedural terrain.
//   build/release/bench/luxel_bench --benchmark_filter=octree
#include <benchmark/benchmark.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/Prune.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "luxel/core/parallel.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_trace.h"
#include "luxel/octree/volume_generators.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "nanovdb_exact_hdda.h"

namespace {

using namespace luxel;
using bench::castExactHdda;
using bench::HddaHit;
using voxel::Ray;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One scene in every structure, with its rays and what was measured while building them.
struct Scene {
    voxel::VoxelWorld world;
    octree::Octree tree;   // with colours, as scenes build it
    octree::Octree shape;  // opacity only: colours no longer split otherwise equal octants
    nanovdb::GridHandle<nanovdb::HostBuffer> vdb;
    const nanovdb::NanoGrid<nanovdb::ValueMask>* grid = nullptr;
    std::vector<Ray> primary, shadow;
    std::map<std::string, double> counters;
};

// The solid voxels of the world as a NanoVDB mask grid: a dense copy into an OpenVDB grid, a
// prune that turns uniform solid nodes into active tiles, then the conversion.
void buildNanoVdb(Scene& s) {
    const auto start = std::chrono::steady_clock::now();
    const Int3 n = s.world.size();
    const openvdb::CoordBBox box(openvdb::Coord(0), openvdb::Coord(n.x - 1, n.y - 1, n.z - 1));
    openvdb::BoolGrid::Ptr solid = openvdb::BoolGrid::create(false);
    {
        // LayoutZYX: x varies fastest, as within the world's chunks.
        openvdb::tools::Dense<bool, openvdb::tools::LayoutZYX> dense(box, false);
        parallelForRange(n.z, 1, [&](int z0, int z1) {
            for (int z = z0; z < z1; ++z) {
                for (int y = 0; y < n.y; ++y) {
                    for (int x = 0; x < n.x; ++x) dense.setValue(x, y, z, s.world.solid(x, y, z));
                }
            }
        });
        openvdb::tools::copyFromDense(dense, *solid, false);
    }
    openvdb::tools::prune(solid->tree());
    openvdb::MaskGrid::Ptr mask = openvdb::MaskGrid::create();
    mask->tree().topologyUnion(solid->tree());
    openvdb::tools::prune(mask->tree());
    s.vdb = nanovdb::openToNanoVDB(*mask);
    s.grid = s.vdb.grid<nanovdb::ValueMask>();
    s.counters["nanovdb_build_s"] = secondsSince(start);
    s.counters["nanovdb_bytes"] = static_cast<double>(s.vdb.size());
    s.counters["nanovdb_active_tiles"] = static_cast<double>(mask->tree().activeTileCount());
}

// Primary rays, the dense DDA's hits, shadow rays from them, and the other structures' agreement.
void makeRays(Scene& s, const voxel::Camera& camera, Vec3d sun) {
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) s.primary.push_back(camera.primaryRay(x, y));
    }
    const std::vector<voxel::Hit> hits = voxel::castRays(s.world, s.primary);
    for (const voxel::Hit& hit : hits) {
        if (!hit.hit) continue;
        const Vec3d nrm{static_cast<double>(hit.normal.x), static_cast<double>(hit.normal.y),
                        static_cast<double>(hit.normal.z)};
        s.shadow.push_back({hit.point + nrm * 1e-4, sun});
    }
    for (const auto& [name, rays] : {std::pair{"primary", &s.primary}, {"shadow", &s.shadow}}) {
        const std::vector<voxel::Hit> dense = voxel::castRays(s.world, *rays);
        const std::vector<octree::OctreeHit> tree = octree::castRays(s.tree, *rays);
        const std::vector<octree::OctreeHit> shape = octree::castRays(s.shape, *rays);
        std::uint64_t treeAgree = 0, shapeAgree = 0, vdbAgree = 0, denseHits = 0;
        double denseSteps = 0, treeSteps = 0, vdbSteps = 0;
        for (std::size_t i = 0; i < rays->size(); ++i) {
            const HddaHit vdb = castExactHdda(*s.grid, s.world.size(), (*rays)[i]);
            const voxel::Hit& d = dense[i];
            const voxel::Hit& o = tree[i].hit;
            denseHits += d.hit ? 1 : 0;
            treeAgree += o.hit == d.hit && (!d.hit || o.voxel == d.voxel) ? 1 : 0;
            const voxel::Hit& g = shape[i].hit;
            shapeAgree += g.hit == d.hit && (!d.hit || g.voxel == d.voxel) ? 1 : 0;
            vdbAgree += vdb.hit == d.hit && (!d.hit || vdb.voxel == d.voxel) ? 1 : 0;
            denseSteps += d.steps;
            treeSteps += o.steps;
            vdbSteps += vdb.steps;
        }
        const double count = static_cast<double>(rays->size());
        const std::string key = name;
        s.counters[key + "_octree_agree%"] = 100.0 * static_cast<double>(treeAgree) / count;
        s.counters[key + "_shape_octree_agree%"] = 100.0 * static_cast<double>(shapeAgree) / count;
        s.counters[key + "_nanovdb_agree%"] = 100.0 * static_cast<double>(vdbAgree) / count;
        s.counters[key + "_dense_steps"] = denseSteps / count;
        s.counters[key + "_octree_steps"] = treeSteps / count;
        s.counters[key + "_nanovdb_steps"] = vdbSteps / count;
        std::printf(
            "%s rays: %zu, dense DDA hits %llu; octree agrees on %.4f%%, NanoVDB HDDA on "
            "%.4f%%\n",
            name, rays->size(), static_cast<unsigned long long>(denseHits),
            s.counters[key + "_octree_agree%"], s.counters[key + "_nanovdb_agree%"]);
    }
}

void finish(Scene& s, const voxel::Camera& camera, Vec3d sun) {
    const auto start = std::chrono::steady_clock::now();
    s.tree = octree::buildOctree(s.world).value();
    s.counters["octree_build_s"] = secondsSince(start);
    const octree::OctreeStats stats = octree::measure(s.tree);
    s.counters["octree_geometry_bytes"] = static_cast<double>(stats.geometryBytes);
    s.counters["octree_attribute_bytes"] = static_cast<double>(stats.attributeBytes);
    s.counters["octree_bits_per_solid"] = stats.bitsPerSolidVoxel;
    // Without colours the interior shares octants: the geometry alone.
    s.shape = octree::buildOctree(s.world, {.colours = false}).value();
    const octree::OctreeStats shape = octree::measure(s.shape);
    s.counters["shape_octree_bytes"] = static_cast<double>(shape.geometryBytes);
    s.counters["shape_octree_bits_per_solid"] = shape.bitsPerSolidVoxel;
    s.counters["dense_bytes"] =
        static_cast<double>(voxel::VoxelWorld::bytesFor(s.world.size(), s.world.chunkSize()));
    s.counters["solid_voxels"] = static_cast<double>(stats.solidVoxels);
    buildNanoVdb(s);
    makeRays(s, camera, sun);
}

const Vec3d kSun = normalize(Vec3d{0.4, 1.0, 0.3});

Scene& terrain() {
    static Scene s = [] {
        std::printf("octree benchmarks: building the 512^3 terrain scene\n");
        Scene out{voxel::VoxelWorld::create({512, 512, 512}, 32).value(),
                  {},
                  {},
                  {},
                  nullptr,
                  {},
                  {},
                  {}};
        voxel::TerrainOptions options;  // as bench_voxel.cpp
        options.seed = 3;
        options.baseHeight = 0.3;
        options.amplitude = 0.2;
        options.frequency = 0.004;
        (void)voxel::generateTerrain(out.world, options);
        finish(out, voxel::Camera::lookAt({256, 260, -40}, {256, 140, 300}, 60, 1280, 720).value(),
               kSun);
        return out;
    }();
    return s;
}

octree::Volume& phantomVolume() {
    static octree::Volume v = octree::makePhantom(512).value();
    return v;
}

Scene& phantom() {
    static Scene s = [] {
        std::printf("octree benchmarks: building the 512^3 phantom scene\n");
        const octree::Volume& v = phantomVolume();
        Scene out{voxel::VoxelWorld::create(v.size(), 32).value(), {}, {}, {}, nullptr, {}, {}, {}};
        parallelForRange(v.size().z / 32, 1, [&](int c0, int c1) {  // chunk slabs: no sharing
            for (int z = c0 * 32; z < c1 * 32; ++z) {
                for (int y = 0; y < v.size().y; ++y) {
                    for (int x = 0; x < v.size().x; ++x) {
                        if (v.opacity(x, y, z) == 0) continue;
                        voxel::Voxel c = v.colour(x, y, z);
                        c.a = 1;
                        out.world.set(x, y, z, c);
                    }
                }
            }
        });
        out.world.refreshEmptySpace();
        finish(out,
               voxel::Camera::lookAt({-260, 700, -330}, {256, 256, 256}, 40, 1280, 720).value(),
               kSun);
        return out;
    }();
    return s;
}

// On one thread, timed by its CPU time: rays per second per core, which the other programs on a
// shared machine disturb far less than they disturb wall-clock time.
template <typename Cast>
void castAll(benchmark::State& state, const std::vector<Ray>& rays, Cast&& cast) {
    for (auto _ : state) {
        for (const Ray& ray : rays) benchmark::DoNotOptimize(cast(ray));
    }
    state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

enum class Peer { Octree, ShapeOctree, Dense, NanoVdb };

void trace(benchmark::State& state, Scene& (*scene)(), bool shadow, Peer peer) {
    Scene& s = scene();
    const std::vector<Ray>& rays = shadow ? s.shadow : s.primary;
    switch (peer) {
        case Peer::Octree:
            castAll(state, rays, [&](const Ray& r) { return octree::castRay(s.tree, r).hit.hit; });
            // The scene's sizes and build times, once per scene and ray kind.
            for (const auto& [name, value] : s.counters) state.counters[name] = value;
            break;
        case Peer::ShapeOctree:
            castAll(state, rays, [&](const Ray& r) { return octree::castRay(s.shape, r).hit.hit; });
            break;
        case Peer::Dense:
            castAll(state, rays, [&](const Ray& r) { return voxel::castRay(s.world, r).hit; });
            break;
        case Peer::NanoVdb:
            castAll(state, rays,
                    [&](const Ray& r) { return castExactHdda(*s.grid, s.world.size(), r).hit; });
            break;
    }
}

void registerTraces() {
    const std::pair<const char*, Scene& (*)()> scenes[] = {{"terrain512", &terrain},
                                                           {"phantom512", &phantom}};
    const std::pair<const char*, Peer> peers[] = {{"octree", Peer::Octree},
                                                  {"octree_opacity_only", Peer::ShapeOctree},
                                                  {"dense_dda", Peer::Dense},
                                                  {"nanovdb_hdda", Peer::NanoVdb}};
    for (const auto& [sceneName, scene] : scenes) {
        for (bool shadow : {false, true}) {
            for (const auto& [peerName, peer] : peers) {
                const std::string name = std::string("octree/") + sceneName +
                                         (shadow ? "/shadow/" : "/primary/") + peerName;
                benchmark::RegisterBenchmark(name.c_str(), [scene = scene, shadow = shadow,
                                                            peer = peer](benchmark::State& st) {
                    trace(st, scene, shadow, peer);
                })->Unit(benchmark::kMillisecond);
            }
        }
    }
}

// Builds run on all threads and are timed by the wall clock; cpu_s is the CPU time of all
// threads per build.
void buildStats(benchmark::State& state, const octree::Octree& tree, std::clock_t cpuStart) {
    state.counters["cpu_s"] = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC /
                              static_cast<double>(state.iterations());
    const octree::OctreeStats stats = octree::measure(tree);
    state.counters["entries"] = static_cast<double>(tree.nodes.size());
    state.counters["bytes"] = static_cast<double>(stats.geometryBytes + stats.attributeBytes);
    state.counters["threads"] = tbb::this_task_arena::max_concurrency();
}

void buildWorld(benchmark::State& state) {
    const voxel::VoxelWorld& world = terrain().world;
    octree::Octree tree;
    const std::clock_t cpu = std::clock();
    for (auto _ : state) tree = octree::buildOctree(world).value();
    buildStats(state, tree, cpu);
}

void buildPhantom(benchmark::State& state) {
    const octree::Volume& volume = phantomVolume();
    octree::Octree tree;
    const std::clock_t cpu = std::clock();
    for (auto _ : state) tree = octree::buildOctree(volume).value();
    buildStats(state, tree, cpu);
}

void buildSparseTerrain(benchmark::State& state) {
    const auto source = octree::makeSparseTerrain(4096, 3);  // scenes/octree/terrain.json
    octree::Octree tree;
    const std::clock_t cpu = std::clock();
    for (auto _ : state) tree = octree::buildOctree(*source).value();
    buildStats(state, tree, cpu);
}

[[maybe_unused]] const bool kRegistered = (registerTraces(), true);

}  // namespace

BENCHMARK(buildWorld)
    ->Name("octree/build/terrain512_world")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK(buildPhantom)
    ->Name("octree/build/phantom512_volume")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK(buildSparseTerrain)
    ->Name("octree/build/sparse_terrain4096")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
