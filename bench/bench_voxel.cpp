// Voxel ray casting throughput on a 512^3 terrain at 1280x720: luxel against Embree on the same
// scene and the same rays, in the same benchmark iteration, on one thread. Two cameras: a flyover
// (high above, looking down over the terrain) and a first-person view (2.5 voxels above the
// ground, looking along it). Per camera: primary rays (nearest hit), shadow rays towards the sun
// from the primary hits (occlusion only: luxel's occluded(), Embree's rtcOccluded1) and
// first-bounce mirror rays (nearest hit).
//
// Embree's scene: every solid voxel face that borders empty space, as one quad
// (RTC_GEOMETRY_TYPE_QUAD; tests/voxel/embree_faces.h), BVH built at RTC_BUILD_QUALITY_HIGH.
// Each side's time is the thread's CPU time, so the counters are Mrays per CPU-second and
// `luxel/embree` is their ratio within the run (load from other processes cancels out).
//   build/release/bench/luxel_bench --benchmark_filter=voxel
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "voxel/embree_faces.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

struct View {
    std::vector<Ray> primary, shadow, reflection;
};

struct Setup {
    VoxelWorld world;
    std::unique_ptr<FaceScene> faces;
    View flyover, firstPerson;
};

View makeView(const VoxelWorld& world, const Camera& camera) {
    View view;
    const Vec3d sun = normalize(Vec3d{0.4, 1.0, 0.3});
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.primaryRay(x, y);
            view.primary.push_back(ray);
            const Hit hit = castRay(world, ray);
            if (!hit.hit) continue;
            const Vec3d n{static_cast<double>(hit.normal.x), static_cast<double>(hit.normal.y),
                          static_cast<double>(hit.normal.z)};
            view.shadow.push_back({hit.point + n * 1e-4, sun});
            // The mirror ray of the first bounce, as the shading's reflections cast it.
            const Vec3d d = ray.direction - n * (2.0 * dot(ray.direction, n));
            view.reflection.push_back({hit.point + n * 1e-4, d});
        }
    }
    return view;
}

Setup& setup() {
    static Setup s = [] {
        Setup out{VoxelWorld::create({512, 512, 512}, 32).value(), nullptr, {}, {}};
        TerrainOptions terrain;
        terrain.seed = 3;
        terrain.baseHeight = 0.3;
        terrain.amplitude = 0.2;
        terrain.frequency = 0.004;
        (void)generateTerrain(out.world, terrain);
        out.faces = std::make_unique<FaceScene>(out.world, RTC_BUILD_QUALITY_HIGH);
        out.flyover = makeView(
            out.world, Camera::lookAt({256, 260, -40}, {256, 140, 300}, 60, 1280, 720).value());
        // First person: 2.5 voxels above the ground at (256, 24), looking along +z, 5 degrees
        // down.
        int ground = 511;
        while (ground > 0 && !out.world.solid(256, ground, 24)) --ground;
        out.firstPerson = makeView(
            out.world, Camera::create({256.5, ground + 3.5, 24.5}, 0, -5, 60, 1280, 720).value());
        return out;
    }();
    return s;
}

double threadSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Casts every ray with luxel's batch call (castCameraRays for primary rays, else castRayBatch or
// occludedBatch), with Embree, with luxel one ray at a time (castRay or occluded: the "scalar"
// column) and with castRayShared (the shared kernel as written, which was castRay before the CPU
// got its own loop: the "before" column), on this thread, each timed by the thread's CPU clock;
// reports the rates and luxel's (batch) ratio to Embree. Each contender takes all the rays and
// returns how many it found something for.
template <typename Luxel, typename Embree, typename Scalar, typename Before>
void race(benchmark::State& state, const std::vector<Ray>& rays, Luxel&& luxel, Embree&& embree,
          Scalar&& scalar, Before&& before) {
    double luxelSeconds = 0, embreeSeconds = 0, scalarSeconds = 0, beforeSeconds = 0;
    long found = 0;
    for (auto _ : state) {
        const double t0 = threadSeconds();
        found += luxel(rays);
        const double t1 = threadSeconds();
        found += embree(rays);
        const double t2 = threadSeconds();
        found += scalar(rays);
        const double t3 = threadSeconds();
        found += before(rays);
        const double t4 = threadSeconds();
        luxelSeconds += t1 - t0;
        embreeSeconds += t2 - t1;
        scalarSeconds += t3 - t2;
        beforeSeconds += t4 - t3;
    }
    benchmark::DoNotOptimize(found);
    const double mrays = 1e-6 * static_cast<double>(rays.size()) * state.iterations();
    state.counters["rays"] = static_cast<double>(rays.size());
    state.counters["luxel_Mrays/cpu_s"] = mrays / luxelSeconds;
    state.counters["embree_Mrays/cpu_s"] = mrays / embreeSeconds;
    state.counters["scalar_Mrays/cpu_s"] = mrays / scalarSeconds;
    state.counters["before_Mrays/cpu_s"] = mrays / beforeSeconds;
    state.counters["luxel/embree"] = embreeSeconds / luxelSeconds;
}

// One ray at a time.
template <typename Cast>
auto each(Cast&& cast) {
    return [cast](const std::vector<Ray>& rays) {
        long found = 0;
        for (const Ray& r : rays) found += cast(r);
        return found;
    };
}

// luxel's batch calls (one ray per SIMD lane), in blocks as a renderer would issue them.
constexpr std::size_t kBatch = 4096;

long luxelNearest(const VoxelWorld& world, const std::vector<Ray>& rays) {
    static thread_local std::vector<Hit> hits(kBatch);
    long found = 0;
    for (std::size_t first = 0; first < rays.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, rays.size() - first);
        castRayBatch(world, std::span(rays).subspan(first, n), std::span(hits).first(n));
        for (std::size_t i = 0; i < n; ++i) found += hits[i].hit;
    }
    return found;
}

// Camera rays: castCameraRays, whose tiles (kCameraTileRays consecutive rays, here runs of 64
// pixels of an image row) skip the empty space in front of them together. Also sums the loop
// iterations it makes, which differ from castRay's `steps` (the skip is one of them).
long luxelCamera(const VoxelWorld& world, const std::vector<Ray>& rays, double* steps = nullptr) {
    static thread_local std::vector<Hit> hits(kBatch);
    long found = 0;
    for (std::size_t first = 0; first < rays.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, rays.size() - first);
        castCameraRays(world, std::span(rays).subspan(first, n), std::span(hits).first(n));
        for (std::size_t i = 0; i < n; ++i) {
            found += hits[i].hit;
            if (steps) *steps += hits[i].steps;
        }
    }
    return found;
}

long luxelOccluded(const VoxelWorld& world, const std::vector<Ray>& rays) {
    static thread_local std::vector<std::uint8_t> blocked(kBatch);
    long found = 0;
    for (std::size_t first = 0; first < rays.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, rays.size() - first);
        occludedBatch(world, std::span(rays).subspan(first, n), std::span(blocked).first(n));
        for (std::size_t i = 0; i < n; ++i) found += blocked[i];
    }
    return found;
}

// Both find the same first voxel (or both miss) on this fraction of the rays: the check that they
// answer the same question.
// Also luxel's loop iterations per ray (voxel visits plus box jumps), what its time scales with.
template <typename Same>
void agreement(benchmark::State& state, const VoxelWorld& world, const std::vector<Ray>& rays,
               Same&& same) {
    long agree = 0;
    double steps = 0;
    for (const Ray& r : rays) {
        agree += same(r);
        steps += castRay(world, r).steps;
    }
    const double n = std::max<double>(1.0, static_cast<double>(rays.size()));
    state.counters["agree"] = rays.empty() ? 1.0 : static_cast<double>(agree) / n;
    state.counters["steps/ray"] = steps / n;
}

enum class Cam { Flyover, FirstPerson };

const View& view(Cam cam) {
    Setup& s = setup();
    return cam == Cam::Flyover ? s.flyover : s.firstPerson;
}

bool sameNearest(const Setup& s, const Ray& r) {
    const Hit mine = castRay(s.world, r);
    const auto theirs = s.faces->cast(r);
    return mine.hit == theirs.hit && (!mine.hit || mine.voxel == theirs.voxel);
}

void voxelPrimary(benchmark::State& state, Cam cam) {
    const Setup& s = setup();
    const View& v = view(cam);
    race(
        state, v.primary, [&](const auto& rays) { return luxelCamera(s.world, rays); },
        each([&](const Ray& r) { return s.faces->cast(r).hit; }),
        each([&](const Ray& r) { return castRay(s.world, r).hit; }),
        each([&](const Ray& r) { return castRayShared(s.world, r).hit; }));
    agreement(state, s.world, v.primary, [&](const Ray& r) { return sameNearest(s, r); });
    // The batch column's own loop count: castCameraRays's iterations, where `steps/ray` is
    // castRay's.
    double batchSteps = 0;
    luxelCamera(s.world, v.primary, &batchSteps);
    state.counters["batch_steps/ray"] =
        batchSteps / std::max<double>(1.0, static_cast<double>(v.primary.size()));
    // The same rays through castRayBatch's SIMD lanes, no tile skip: the lanes against the
    // one-ray loop (the scalar column) on camera rays (docs/algorithms/voxel-traversal.md §4.6).
    long found = 0;
    const double t0 = threadSeconds();
    for (benchmark::IterationCount i = 0; i < state.iterations(); ++i)
        found += luxelNearest(s.world, v.primary);
    const double lanesSeconds = threadSeconds() - t0;
    benchmark::DoNotOptimize(found);
    state.counters["lanes_Mrays/cpu_s"] =
        1e-6 * static_cast<double>(v.primary.size()) * state.iterations() / lanesSeconds;
}

void voxelShadow(benchmark::State& state, Cam cam) {
    const Setup& s = setup();
    const View& v = view(cam);
    race(
        state, v.shadow, [&](const auto& rays) { return luxelOccluded(s.world, rays); },
        each([&](const Ray& r) { return s.faces->occluded(r); }),
        each([&](const Ray& r) { return occluded(s.world, r); }),
        each([&](const Ray& r) { return castRayShared(s.world, r).hit; }));
    agreement(state, s.world, v.shadow,
              [&](const Ray& r) { return castRay(s.world, r).hit == s.faces->occluded(r); });
}

void voxelReflection(benchmark::State& state, Cam cam) {
    const Setup& s = setup();
    const View& v = view(cam);
    race(
        state, v.reflection, [&](const auto& rays) { return luxelNearest(s.world, rays); },
        each([&](const Ray& r) { return s.faces->cast(r).hit; }),
        each([&](const Ray& r) { return castRay(s.world, r).hit; }),
        each([&](const Ray& r) { return castRayShared(s.world, r).hit; }));
    agreement(state, s.world, v.reflection, [&](const Ray& r) { return sameNearest(s, r); });
}

}  // namespace

BENCHMARK_CAPTURE(voxelPrimary, flyover, Cam::Flyover)
    ->Name("voxel/primary/flyover")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(voxelPrimary, firstPerson, Cam::FirstPerson)
    ->Name("voxel/primary/first-person")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(voxelShadow, flyover, Cam::Flyover)
    ->Name("voxel/shadow/flyover")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(voxelShadow, firstPerson, Cam::FirstPerson)
    ->Name("voxel/shadow/first-person")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(voxelReflection, flyover, Cam::Flyover)
    ->Name("voxel/reflection/flyover")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(voxelReflection, firstPerson, Cam::FirstPerson)
    ->Name("voxel/reflection/first-person")
    ->Unit(benchmark::kMillisecond);
