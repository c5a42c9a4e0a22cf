// Voxel radiance cascades (docs/algorithms/voxel-radiance-cascades.md): the parts of a real-time
// frame on a shipped scene, in CPU time: one lighting pass (a bounce), the picture at 640x360 and
// a whole frame (a pass and the picture) on each shipped scene (the five small ones and the three
// 256x96x256 terrains, whose cascades take about 5 s and 860 MiB each to build), and the one-off
// build on the cottage.
// `--benchmark_filter=voxel_cascades`; the CPU column is the whole
// process (all threads): on an idle 2-core machine a frame takes about half of it. The `_gpu`
// benchmarks time the same pass, picture and frame of each scene on the GPU by its timestamps
// (transfers excluded); they are skipped without a Vulkan device and on a CPU device (lavapipe).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "luxel/gpu/context.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

// scenes/voxel/<name>.json at 640x360, loaded once.
VoxelScene& shippedScene(const std::string& name) {
    static std::map<std::string, VoxelScene> scenes;
    auto found = scenes.find(name);
    if (found != scenes.end()) return found->second;
    auto loaded =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/" + name + ".json", 640, 360);
    if (!loaded) throw std::runtime_error(loaded.error().message());
    return scenes.emplace(name, std::move(*loaded)).first->second;
}

VoxelScene& cottage() {
    return shippedScene("cottage");
}

void BM_VoxelCascadesBuild(benchmark::State& state) {
    VoxelScene& scene = cottage();
    for (auto _ : state) {
        auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
        benchmark::DoNotOptimize(cascades.ok());
    }
}

void BM_VoxelCascadesPass(benchmark::State& state, const std::string& name) {
    VoxelScene& scene = shippedScene(name);
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    if (!cascades) {
        state.SkipWithError(cascades.error().message().c_str());
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(cascades->iterate());
}

void BM_VoxelCascadesPicture(benchmark::State& state, const std::string& name) {
    VoxelScene& scene = shippedScene(name);
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    if (!cascades) {
        state.SkipWithError(cascades.error().message().c_str());
        return;
    }
    cascades->solve();
    for (auto _ : state) {
        auto image = cascades->render(scene.camera);
        benchmark::DoNotOptimize(image.ok());
    }
    state.counters["Mpixel/s"] = benchmark::Counter(
        double(scene.camera.width()) * scene.camera.height() * 1e-6, benchmark::Counter::kIsRate);
}

// A real-time frame (docs/algorithms/voxel-radiance-cascades.md §5): one lighting pass and the
// picture at 640x360, after a solve, on a shipped scene.
void BM_VoxelCascadesFrame(benchmark::State& state, const std::string& name) {
    VoxelScene& scene = shippedScene(name);
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    if (!cascades) {
        state.SkipWithError(cascades.error().message().c_str());
        return;
    }
    cascades->solve();
    for (auto _ : state) {
        benchmark::DoNotOptimize(cascades->iterate());
        auto image = cascades->render(scene.camera);
        benchmark::DoNotOptimize(image.ok());
    }
}

// A hardware Vulkan device, or null (with the reason in `why`).
gpu::Context* hardwareGpu(std::string& why) {
    static std::string reason;
    static std::unique_ptr<gpu::Context> context = [] {
        auto c = gpu::Context::create();
        if (!c) {
            reason = "no Vulkan device: " + c.error().message();
            return std::unique_ptr<gpu::Context>();
        }
        if ((*c)->device().type == "cpu") {
            reason = "the Vulkan device is a CPU (" + (*c)->device().name + ")";
            return std::unique_ptr<gpu::Context>();
        }
        return std::move(*c);
    }();
    why = reason;
    return context.get();
}

// What a GPU benchmark times: one lighting pass, the picture at the scene's 640x360 after a
// solve, or a real-time frame (a pass, then the picture).
enum class GpuPart { Pass, Picture, Frame };

void BM_VoxelCascadesGpu(benchmark::State& state, const std::string& name, GpuPart part) {
    std::string why;
    gpu::Context* context = hardwareGpu(why);
    if (!context) {
        state.SkipWithError(why.c_str());
        return;
    }
    VoxelScene& scene = shippedScene(name);
    auto cascades = RadianceCascades::create(scene.world, &scene.textures, scene.shading);
    auto gpu = cascades ? RadianceCascadesGpu::create(*context, *cascades)
                        : Result<RadianceCascadesGpu>(cascades.error());
    if (!gpu || (part != GpuPart::Pass && !gpu->solve())) {
        state.SkipWithError(gpu ? "the lighting passes failed" : gpu.error().message().c_str());
        return;
    }
    // Untimed warm-up: the first picture makes its pipeline and uploads the world, which a
    // real-time loop does once.
    if (part != GpuPart::Pass && !gpu->render(scene.camera)) {
        state.SkipWithError("the warm-up picture failed");
        return;
    }
    for (auto _ : state) {
        double ms = 0;
        if (part != GpuPart::Picture) {
            auto pass = gpu->iterate(1);
            if (!pass) {
                state.SkipWithError(pass.error().message().c_str());
                return;
            }
            ms += *pass;
        }
        if (part != GpuPart::Pass) {
            double pictureMs = 0;
            auto image = gpu->render(scene.camera, &pictureMs);
            if (!image) {
                state.SkipWithError(image.error().message().c_str());
                return;
            }
            ms += pictureMs;
        }
        state.SetIterationTime(ms * 1e-3);
    }
    state.SetLabel(context->device().name);
}

}  // namespace

BENCHMARK(BM_VoxelCascadesBuild)
    ->Name("voxel_cascades/build/cottage")
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);
// voxel_cascades/<kind>/<scene>: each shipped scene's pass, then picture, then frame.
constexpr const char* kScenes[] = {"cottage",    "fence",   "garden",          "glass",
                                   "thin-walls", "terrain", "terrain-evening", "terrain-direct"};
const bool kSceneBenchmarks = [] {
    using Run = void (*)(benchmark::State&, const std::string&);
    const std::pair<const char*, Run> kinds[] = {{"pass", BM_VoxelCascadesPass},
                                                 {"picture_640x360", BM_VoxelCascadesPicture},
                                                 {"frame_640x360", BM_VoxelCascadesFrame}};
    for (const auto& [kind, run] : kinds) {
        for (const char* scene : kScenes) {
            const std::string name = std::string("voxel_cascades/") + kind + "/" + scene;
            benchmark::RegisterBenchmark(name.c_str(), run, std::string(scene))
                ->MeasureProcessCPUTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    const std::pair<const char*, GpuPart> gpuKinds[] = {{"pass_gpu", GpuPart::Pass},
                                                        {"picture_gpu_640x360", GpuPart::Picture},
                                                        {"frame_gpu_640x360", GpuPart::Frame}};
    for (const auto& [kind, part] : gpuKinds) {
        for (const char* scene : kScenes) {
            const std::string name = std::string("voxel_cascades/") + kind + "/" + scene;
            benchmark::RegisterBenchmark(name.c_str(), BM_VoxelCascadesGpu, std::string(scene),
                                         part)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    return true;
}();
