// Voxel radiance cascades (docs/algorithms/voxel-radiance-cascades.md): the parts of a real-time
// frame on a shipped scene, in CPU time: one lighting pass (a bounce), the picture at 640x360,
// and the one-off build. `--benchmark_filter=voxel_cascades`; the CPU column is the whole
// process (all threads): on an idle 2-core machine a frame takes about half of it.
#include <benchmark/benchmark.h>

#include <string>

#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/voxel_scene.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

VoxelScene& cottage() {
    static VoxelScene scene = [] {
        auto loaded =
            loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 640, 360);
        if (!loaded) throw std::runtime_error(loaded.error().message());
        return std::move(*loaded);
    }();
    return scene;
}

void BM_VoxelCascadesBuild(benchmark::State& state) {
    VoxelScene& scene = cottage();
    for (auto _ : state) {
        auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
        benchmark::DoNotOptimize(cascades.ok());
    }
}

void BM_VoxelCascadesPass(benchmark::State& state) {
    VoxelScene& scene = cottage();
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    for (auto _ : state) benchmark::DoNotOptimize(cascades->iterate());
}

void BM_VoxelCascadesPicture(benchmark::State& state) {
    VoxelScene& scene = cottage();
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    cascades->solve();
    for (auto _ : state) {
        auto image = cascades->render(scene.camera);
        benchmark::DoNotOptimize(image.ok());
    }
    state.counters["Mpixel/s"] = benchmark::Counter(
        double(scene.camera.width()) * scene.camera.height() * 1e-6, benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_VoxelCascadesBuild)
    ->Name("voxel_cascades/build/cottage")
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelCascadesPass)
    ->Name("voxel_cascades/pass/cottage")
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelCascadesPicture)
    ->Name("voxel_cascades/picture_640x360/cottage")
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);
