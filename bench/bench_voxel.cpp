// Voxel ray casting throughput on a 512^3 terrain at 1280x720: luxel's DDA against Embree on the
// exposed voxel faces, the same rays in the same run (the ratio is the number that matters):
// primary rays, shadow rays towards the sun and first-bounce mirror rays from the primary hits.
//   build/release/bench/luxel_bench --benchmark_filter=voxel
#include <benchmark/benchmark.h>

#include <memory>

#include "luxel/core/parallel.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "voxel/embree_faces.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

struct Setup {
    VoxelWorld world;
    std::unique_ptr<FaceScene> faces;
    std::vector<Ray> primary, shadow, reflection;
};

Setup& setup() {
    static Setup s = [] {
        Setup out{VoxelWorld::create({512, 512, 512}, 32).value(), nullptr, {}, {}, {}};
        TerrainOptions terrain;
        terrain.seed = 3;
        terrain.baseHeight = 0.3;
        terrain.amplitude = 0.2;
        terrain.frequency = 0.004;
        (void)generateTerrain(out.world, terrain);
        out.faces = std::make_unique<FaceScene>(out.world);
        const Camera camera =
            Camera::lookAt({256, 260, -40}, {256, 140, 300}, 60, 1280, 720).value();
        const Vec3d sun = normalize(Vec3d{0.4, 1.0, 0.3});
        for (int y = 0; y < 720; ++y) {
            for (int x = 0; x < 1280; ++x) {
                const Ray ray = camera.primaryRay(x, y);
                out.primary.push_back(ray);
                const Hit hit = castRay(out.world, ray);
                if (hit.hit) {
                    const Vec3d n{static_cast<double>(hit.normal.x),
                                  static_cast<double>(hit.normal.y),
                                  static_cast<double>(hit.normal.z)};
                    out.shadow.push_back({hit.point + n * 1e-4, sun});
                    // The mirror ray of the first bounce, as the shading's reflections cast it.
                    const Vec3d d = ray.direction - n * (2.0 * dot(ray.direction, n));
                    out.reflection.push_back({hit.point + n * 1e-4, d});
                }
            }
        }
        return out;
    }();
    return s;
}

template <typename Cast>
void castAll(benchmark::State& state, const std::vector<Ray>& rays, Cast&& cast) {
    for (auto _ : state) {
        parallelForRange(static_cast<int>(rays.size()), 4096, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) benchmark::DoNotOptimize(cast(rays[i]));
        });
    }
    state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

// Loop iterations (voxel visits plus block jumps) per ray: what the traversal's speed scales with.
double meanSteps(const VoxelWorld& world, const std::vector<Ray>& rays) {
    double sum = 0;
    for (const Ray& r : rays) sum += castRay(world, r).steps;
    return rays.empty() ? 0.0 : sum / static_cast<double>(rays.size());
}

void voxelPrimaryLuxel(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.primary, [&](const Ray& r) { return castRay(s.world, r).hit; });
    state.counters["steps/ray"] = meanSteps(s.world, s.primary);
}
void voxelPrimaryEmbree(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.primary, [&](const Ray& r) { return s.faces->cast(r).hit; });
}
void voxelShadowLuxel(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.shadow, [&](const Ray& r) { return castRay(s.world, r).hit; });
    state.counters["steps/ray"] = meanSteps(s.world, s.shadow);
}
void voxelShadowEmbree(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.shadow, [&](const Ray& r) { return s.faces->cast(r).hit; });
}

void voxelReflectionLuxel(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.reflection, [&](const Ray& r) { return castRay(s.world, r).hit; });
    state.counters["steps/ray"] = meanSteps(s.world, s.reflection);
}
void voxelReflectionEmbree(benchmark::State& state) {
    Setup& s = setup();
    castAll(state, s.reflection, [&](const Ray& r) { return s.faces->cast(r).hit; });
}

}  // namespace

BENCHMARK(voxelPrimaryLuxel)
    ->Name("voxel/primary/luxel")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(voxelPrimaryEmbree)
    ->Name("voxel/primary/embree")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(voxelShadowLuxel)
    ->Name("voxel/shadow/luxel")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(voxelShadowEmbree)
    ->Name("voxel/shadow/embree")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(voxelReflectionLuxel)
    ->Name("voxel/reflection/luxel")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(voxelReflectionEmbree)
    ->Name("voxel/reflection/embree")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
