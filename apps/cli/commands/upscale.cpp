// `luxel upscale`: how much a lower internal resolution costs in quality and saves in time, per
// upscaler, on a voxel scene (CPU renders; metrics on the tone-mapped images).
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "luxel/core/image_io.h"
#include "luxel/core/image_quality.h"
#include "luxel/core/timer.h"
#include "luxel/post/temporal.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

struct UpscaleArgs {
    std::string scene, size, outDir;
    float scale = 0.5f;
    int frames = 16;
};

struct Row {
    std::string method;
    Image display;
    double ms = 0;
};

int runUpscale(const UpscaleArgs& args) {
    auto file = loadScene(args.scene, args.size);
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::Voxel) {
        return reportError(Error(args.scene + " is " + sceneKindPhrase(file->kind()) +
                                 "; luxel upscale takes a voxel scene"));
    }
    const voxel::VoxelScene& s = file->voxel();
    const ToneMapSettings tone = s.post.tone;
    const int w = s.camera.width(), h = s.camera.height();
    const voxel::Camera low = post::resizedCamera(s.camera, post::internalSide(w, args.scale),
                                                  post::internalSide(h, args.scale));
    // The native render and up to five display rows, an upscaled and a sharpened image, and the
    // temporal upscaler's history, output and depth, at the output size; the internal render.
    const std::uint64_t needed =
        imageBytes(w, h, 3) * 11 + imageBytes(low.width(), low.height(), 3) * 3;
    if (Status st = checkRenderMemory(w, h, needed); !st) return reportError(st.error());
    std::vector<Row> rows;
    Stopwatch nativeTime;
    const Image native = voxel::render(s.world, s.camera, s.shading, &s.textures);
    rows.push_back({"native", toneMap(native, tone), nativeTime.milliseconds()});
    Stopwatch lowTime;
    const Image internal = voxel::render(s.world, low, s.shading, &s.textures);
    const double lowMs = lowTime.milliseconds();
    for (auto [name, upscaler, sharpness] :
         {std::tuple{"bilinear", post::Upscaler::Bilinear, 0.0f},
          std::tuple{"edge", post::Upscaler::Edge, 0.0f},
          std::tuple{"edge+sharpen", post::Upscaler::Edge, 0.5f}}) {
        Stopwatch t;
        Image up = post::upscale(internal, w, h, upscaler);
        if (sharpness > 0) up = post::sharpen(up, sharpness);
        rows.push_back({name, toneMap(up, tone), lowMs + t.milliseconds()});
    }
    if (args.frames > 0) {
        post::TemporalUpscaler temporal(w, h);
        double lastMs = 0;
        for (int f = 0; f < args.frames; ++f) {
            Stopwatch t;
            const Vec2d j = temporal.nextJitter();
            const Image colour = post::renderJittered(s.world, low, s.shading, &s.textures, j);
            const Image depth = post::primaryDepth(s.world, low, j);
            temporal.accumulate(colour, depth, post::viewOf(s.camera), j);
            lastMs = t.milliseconds();
        }
        rows.push_back(
            {"temporal x" + std::to_string(args.frames), toneMap(temporal.output(), tone), lastMs});
    }
    std::printf("%s: %dx%d, internal %dx%d (scale %.2f), cpu\n", args.scene.c_str(), w, h,
                low.width(), low.height(), args.scale);
    std::printf("  %-16s %9s %8s %10s\n", "method", "PSNR dB", "SSIM", "ms/frame");
    for (const Row& row : rows) {
        const double p = psnr(row.display, rows[0].display).value();
        const double q = ssim(row.display, rows[0].display).value();
        std::printf("  %-16s %9.2f %8.4f %10.1f\n", row.method.c_str(), p, q, row.ms);
        if (!args.outDir.empty()) {
            const std::string path = args.outDir + "/" + row.method + ".png";
            if (Status st = writePng(path, row.display); !st) return reportError(st.error());
        }
    }
    std::printf("  (temporal: the last frame's time, depth rays included; static camera)\n");
    return 0;
}

}  // namespace

Runner addUpscaleCommand(CLI::App& app) {
    auto args = std::make_shared<UpscaleArgs>();
    app.add_option("scene", args->scene, "voxel scene file (.json)")->required();
    app.add_option("--scale", args->scale, "internal resolution scale")
        ->check(finiteIn(double(post::kMinInternalScale), 1.0))
        ->capture_default_str();
    app.add_option("--size", args->size, "output size WIDTHxHEIGHT (default: the scene camera's)");
    app.add_option("--frames", args->frames, "temporal upscaler frames (0: skip it)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    app.add_option("--out-dir", args->outDir, "also write each method's PNG into this folder");
    return [args] { return runUpscale(*args); };
}

}  // namespace luxel::cli
