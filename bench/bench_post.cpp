// Post-processing: bloom and upscaler passes (CPU, and GPU with timestamps), and the quality of
// lower internal resolutions on the shipped voxel scenes: PSNR and SSIM of the tone-mapped image
// against the native render, and the time per frame (render + upscale).
//   build/release/bench/luxel_bench --benchmark_filter=Post
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <stdexcept>

#include "luxel/core/image_quality.h"
#include "luxel/gpu/context.h"
#include "luxel/post/bloom.h"
#include "luxel/post/post_gpu.h"
#include "luxel/post/temporal.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/scene/scene_file.h"
#include "luxel/voxel/render_image.h"
#include "post/post_test_images.h"

namespace {

using namespace luxel;

gpu::Context* postGpu() {
    static std::unique_ptr<gpu::Context> context = [] {
        auto c = gpu::Context::create();
        return c ? std::move(*c) : nullptr;
    }();
    return context.get();
}

void BM_PostBloomCpu(benchmark::State& state) {
    const Image hdr = test::randomHdr(960, 540, 1);
    for (auto _ : state) benchmark::DoNotOptimize(post::bloom(hdr, {0.1f, 5, false}));
}
BENCHMARK(BM_PostBloomCpu)->Unit(benchmark::kMillisecond);

void BM_PostUpscaleCpu(benchmark::State& state) {
    const Image low = test::randomHdr(480, 270, 2);
    const auto upscaler = static_cast<post::Upscaler>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(post::upscale(low, 960, 540, upscaler));
    state.SetLabel(post::upscalerName(upscaler));
}
BENCHMARK(BM_PostUpscaleCpu)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// GPU dispatch time only (timestamps), transfers excluded.
void BM_PostGpu(benchmark::State& state) {
    gpu::Context* context = postGpu();
    if (!context) {
        state.SkipWithError("no Vulkan device");
        return;
    }
    const bool bloom = state.range(0) == 0;
    const Image hdr = test::randomHdr(960, 540, 1), low = test::randomHdr(480, 270, 2);
    for (auto _ : state) {
        std::vector<gpu::PassTiming> timings;
        const auto result = bloom ? post::bloomGpu(*context, hdr, {0.1f, 5, false}, &timings)
                                  : post::upscaleEdgeGpu(*context, low, 960, 540, &timings);
        if (!result) {
            state.SkipWithError(result.error().message().c_str());
            return;
        }
        double ms = 0;
        for (const auto& t : timings) ms += t.milliseconds;
        state.SetIterationTime(ms * 1e-3);
    }
    state.SetLabel(std::string(bloom ? "bloom 960x540, " : "edge upscale to 960x540, ") +
                   context->device().name);
}
BENCHMARK(BM_PostGpu)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond);

struct SceneCase {
    voxel::VoxelScene scene;
    Image reference;  // tone-mapped native render
};

SceneCase& sceneCase(const std::string& name) {
    static std::map<std::string, std::unique_ptr<SceneCase>> cases;
    auto& c = cases[name];
    if (!c) {
        auto file = scene::loadSceneFile(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/" + name,
                                         {ImageSize{480, 270}});
        if (!file) throw std::runtime_error(file.error().message());
        c = std::make_unique<SceneCase>(SceneCase{std::move(file->voxel()), {}});
        const auto& s = c->scene;
        c->reference =
            toneMap(voxel::render(s.world, s.camera, s.shading, &s.textures), s.post.tone);
    }
    return *c;
}

// method: 0 native, 1 half + bilinear, 2 half + edge, 3 half + temporal (16 static frames).
void BM_PostSceneQuality(benchmark::State& state, const std::string& name) {
    SceneCase& c = sceneCase(name);
    const auto& s = c.scene;
    const int method = static_cast<int>(state.range(0));
    const int w = s.camera.width(), h = s.camera.height();
    const voxel::Camera low = post::resizedCamera(s.camera, w / 2, h / 2);
    Image out;
    for (auto _ : state) {
        if (method == 0) {
            out = voxel::render(s.world, s.camera, s.shading, &s.textures);
        } else if (method < 3) {
            out = post::upscale(voxel::render(s.world, low, s.shading, &s.textures), w, h,
                                method == 1 ? post::Upscaler::Bilinear : post::Upscaler::Edge);
        } else {
            state.PauseTiming();
            post::TemporalUpscaler temporal(w, h);
            for (int f = 0; f < 15; ++f) {
                const Vec2d j = temporal.nextJitter();
                temporal.accumulate(post::renderJittered(s.world, low, s.shading, &s.textures, j),
                                    post::primaryDepth(s.world, low, j), post::viewOf(s.camera), j);
            }
            state.ResumeTiming();  // the 16th frame is timed
            const Vec2d j = temporal.nextJitter();
            out =
                temporal.accumulate(post::renderJittered(s.world, low, s.shading, &s.textures, j),
                                    post::primaryDepth(s.world, low, j), post::viewOf(s.camera), j);
        }
    }
    const Image display = toneMap(out, s.post.tone);
    state.counters["psnr_db"] = method == 0 ? 0.0 : psnr(display, c.reference).value();
    state.counters["ssim"] = ssim(display, c.reference).value();
    const char* labels[] = {"native", "0.5x bilinear", "0.5x edge", "0.5x temporal (16 frames)"};
    state.SetLabel(name + " 480x270 " + labels[method]);
}
BENCHMARK_CAPTURE(BM_PostSceneQuality, terrain, std::string("terrain.json"))
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PostSceneQuality, garden, std::string("garden.json"))
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond);

}  // namespace
