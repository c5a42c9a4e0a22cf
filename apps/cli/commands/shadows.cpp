// `luxel shadows SCENE... [--size WxH] [--samples M] [--frames N] [--sun-step DEG] [--methods
// LIST] [--sun-radius DEG] [--blend-band NEAR,FAR] [--out-dir DIR] [--markdown]`: sun visibility of
// the primary hits of each voxel scene by every shadow method against the cone-sampled ground truth
// (M rays per point): penumbra MAE, whole-image MAE, leak and false-shadow rates, seams in the
// blend band, flicker over a sun turning by DEG per frame, and CPU time (build + evaluate) per
// frame.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "luxel/core/image_io.h"
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/voxel/shadows/shadow_metrics.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::cli {
namespace {

using voxel::ShadowMethod;
using voxel::ShadowSettings;

struct ShadowsArgs {
    std::vector<std::string> scenes;
    std::string size = "240x135", methods, outDir;
    int samples = 256, frames = 1;
    double sunStep = 1.0;
    double sunRadius = -1.0;        // degrees; < 0: the scene's
    std::vector<double> blendBand;  // near, far; empty: the scene's
    bool markdown = false;
};

struct Variant {
    std::string name;
    ShadowSettings settings;
};

// Every method the report compares, on the scene's own settings.
std::vector<Variant> allVariants(const ShadowSettings& base) {
    std::vector<Variant> v;
    auto add = [&](const char* name, ShadowMethod m, auto&& tweak) {
        ShadowSettings s = base;
        s.method = m;
        tweak(s);
        v.push_back({name, s});
    };
    auto none = [](ShadowSettings&) {};
    add("hard", ShadowMethod::Hard, none);
    add("msm", ShadowMethod::Msm,
        [](ShadowSettings& s) { s.momentStorage = ShadowSettings::MomentStorage::Float32; });
    add("msm16", ShadowMethod::Msm,
        [](ShadowSettings& s) { s.momentStorage = ShadowSettings::MomentStorage::Quantized16; });
    add("vsm", ShadowMethod::Vsm, none);
    add("sdf", ShadowMethod::Sdf, none);
    add("sdf-centres", ShadowMethod::Sdf,
        [](ShadowSettings& s) { s.sdfDistance = ShadowSettings::SdfDistance::Centres; });
    add("blend", ShadowMethod::Blend, [](ShadowSettings& s) {
        s.sdfNear = true;
        s.minInBand = false;
    });
    add("blend-msm-near", ShadowMethod::Blend, [](ShadowSettings& s) {
        s.sdfNear = false;
        s.minInBand = false;
    });
    add("blend-min", ShadowMethod::Blend, [](ShadowSettings& s) {
        s.sdfNear = true;
        s.minInBand = true;
    });
    auto penumbra = [](ShadowSettings& s) {
        s.momentStorage = ShadowSettings::MomentStorage::Float32;
        s.msmFilter = ShadowSettings::MsmFilter::PenumbraSized;
    };
    add("msm-penumbra", ShadowMethod::Msm, penumbra);
    add("blend-penumbra", ShadowMethod::Blend, [&](ShadowSettings& s) {
        penumbra(s);
        s.sdfNear = true;
        s.minInBand = false;
    });
    add("blend-msm-near-penumbra", ShadowMethod::Blend, [&](ShadowSettings& s) {
        penumbra(s);
        s.sdfNear = false;
        s.minInBand = false;
    });
    add("flood", ShadowMethod::FloodFill, none);
    return v;
}

Result<std::vector<Variant>> chooseVariants(const ShadowSettings& base, const std::string& list) {
    std::vector<Variant> all = allVariants(base);
    if (list.empty()) return all;
    std::vector<Variant> chosen;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        auto it =
            std::find_if(all.begin(), all.end(), [&](const Variant& v) { return v.name == name; });
        if (it == all.end()) {
            std::string names;
            for (const Variant& v : all) names += (names.empty() ? "" : ", ") + v.name;
            return Error("--methods: unknown method '" + name + "' (known: " + names + ")");
        }
        chosen.push_back(*it);
    }
    return chosen;
}

// The primary hits of the scene camera: shading points, their mask and camera distances.
struct Primary {
    std::vector<voxel::ShadowQuery> queries;
    std::vector<std::uint8_t> mask;
};

Primary primaryHits(const voxel::VoxelScene& scene) {
    const voxel::Camera& cam = scene.camera;
    Primary p;
    const std::size_t n = static_cast<std::size_t>(cam.width()) * cam.height();
    p.queries.resize(n);
    p.mask.resize(n);
    const voxel::TextureSet* textures = scene.textures.size() > 0 ? &scene.textures : nullptr;
    parallelForRange(cam.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < cam.width(); ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * cam.width() + x;
                const voxel::Ray ray = cam.primaryRay(x, y);
                const voxel::SurfaceHit s = voxel::castToSurface(scene.world, textures, ray);
                const Int3 nrm = s.hit.normal;
                p.mask[i] = s.hit.hit && (nrm.x != 0 || nrm.y != 0 || nrm.z != 0);
                p.queries[i] = {s.hit.point, nrm, s.hit.hit ? s.hit.t * length(ray.direction) : 0};
            }
        }
    });
    return p;
}

struct Timed {
    std::vector<float> v;
    double milliseconds = 0;
};

Result<Timed> evaluate(const voxel::VoxelScene& scene, const Primary& primary, Vec3d sun,
                       double radius, const ShadowSettings& settings) {
    Stopwatch clock;
    const voxel::TextureSet* textures = scene.textures.size() > 0 ? &scene.textures : nullptr;
    auto vis = voxel::SunVisibility::build(scene.world, textures, {sun, radius}, settings);
    if (!vis) return vis.error();
    Timed t;
    t.v.assign(primary.queries.size(), 1.0f);
    parallelForRange(static_cast<int>(primary.queries.size()), 256, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (primary.mask[i]) t.v[i] = vis->visibility(primary.queries[i]);
        }
    });
    t.milliseconds = clock.milliseconds();
    return t;
}

Vec3d turnedSun(Vec3 sun, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
    return {c * sun.x + s * sun.z, double(sun.y), -s * sun.x + c * sun.z};
}

Status writeVisibility(const std::string& path, const std::vector<float>& v, int w, int h) {
    Image image(w, h, 1);
    std::copy(v.begin(), v.end(), image.data());
    return writePng(path, image, PngEncoding::Linear);
}

int runScene(const ShadowsArgs& args, const std::string& path) {
    auto file = loadScene(path, args.size);
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::Voxel) {
        return reportError(Error(path + ": " + sceneKindPhrase(file->kind()) +
                                 "; luxel shadows works on voxel scenes"));
    }
    const voxel::VoxelScene& scene = file->voxel();
    ShadowSettings base = scene.shading.shadowSettings;
    if (args.blendBand.size() == 2) {
        base.blendNear = args.blendBand[0];
        base.blendFar = args.blendBand[1];
    }
    auto variants = chooseVariants(base, args.methods);
    if (!variants) return reportError(variants.error());
    const double radius = args.sunRadius >= 0.0 ? args.sunRadius * std::numbers::pi / 180.0
                                                : scene.shading.sunAngularRadius;
    const int w = scene.camera.width(), h = scene.camera.height();
    // Per pixel: the primary hit and its mask, then per frame the truth, a mask and one
    // visibility per method; and one written image.
    const std::uint64_t perPixel =
        sizeof(voxel::ShadowQuery) + 1 +
        static_cast<std::uint64_t>(args.frames) * (sizeof(float) + 1 + variants->size() * 4) +
        sizeof(float);
    if (Status s = checkRenderMemory(
            w, h, perPixel * static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h));
        !s) {
        return reportError(s.error());
    }
    const Primary primary = primaryHits(scene);

    ShadowSettings truthSettings = base;
    truthSettings.method = ShadowMethod::Exact;
    truthSettings.exactSamples = args.samples;
    std::vector<std::vector<float>> truth;
    std::vector<std::vector<std::uint8_t>> masks(args.frames, primary.mask);
    double truthMs = 0;
    std::vector<std::vector<std::vector<float>>> images(variants->size());
    std::vector<double> ms(variants->size(), 0.0);
    for (int f = 0; f < args.frames; ++f) {
        const Vec3d sun = turnedSun(scene.shading.sunDirection, f * args.sunStep);
        auto t = evaluate(scene, primary, sun, radius, truthSettings);
        if (!t) return reportError(t.error());
        truth.push_back(std::move(t->v));
        truthMs += t->milliseconds / args.frames;
        for (std::size_t k = 0; k < variants->size(); ++k) {
            auto e = evaluate(scene, primary, sun, radius, (*variants)[k].settings);
            if (!e) return reportError(e.error());
            images[k].push_back(std::move(e->v));
            ms[k] += e->milliseconds / args.frames;
        }
    }
    // Pixels in the blend band (where both methods mix), for the seam metric.
    std::vector<std::uint8_t> band(primary.mask.size());
    for (std::size_t i = 0; i < band.size(); ++i) {
        const double d = primary.queries[i].footprint;
        band[i] = primary.mask[i] && d > base.blendNear && d < base.blendFar;
    }
    std::vector<float> allTruth;
    std::vector<std::uint8_t> allMask;
    for (int f = 0; f < args.frames; ++f) {
        allTruth.insert(allTruth.end(), truth[f].begin(), truth[f].end());
        allMask.insert(allMask.end(), primary.mask.begin(), primary.mask.end());
    }

    const char* rowFormat =
        args.markdown
            ? "| %-15s | %8.4f | %+8.4f | %8.4f | %8.4f | %8.4f | %8.4f | %8.4f | %9.1f |\n"
            : "  %-15s %8.4f %+8.4f %8.4f %8.4f %8.4f %8.4f %8.4f %9.1f\n";
    const char* bold = args.markdown ? "**" : "";
    std::printf(
        "%s%s%s%s: %dx%d, %lld surface pixels (%lld in penumbra), blend band %g..%g, "
        "sun radius %.2f deg, truth %d rays, %d frame%s\n",
        args.markdown ? "\n" : "", bold, path.c_str(), bold, w, h,
        static_cast<long long>(std::count(primary.mask.begin(), primary.mask.end(), 1)),
        static_cast<long long>(
            voxel::compareVisibility(truth[0], truth[0], primary.mask).penumbraPixels),
        base.blendNear, base.blendFar, radius * 180.0 / std::numbers::pi, args.samples, args.frames,
        args.frames == 1 ? "" : "s");
    if (args.markdown) {
        std::printf(
            "\n| method | pen. MAE | pen. bias | MAE | leak | false | seam | flicker | CPU ms |\n"
            "|---|---|---|---|---|---|---|---|---|\n");
    } else {
        std::printf("  %-15s %8s %8s %8s %8s %8s %8s %8s %9s\n", "method", "pen.MAE", "pen.bias",
                    "MAE", "leak", "false", "seam", "flicker", "CPU ms");
    }
    std::printf(args.markdown ? "| %-15s | %8s | %8s | %8s | %8s | %8s | %8s | %8s | %9.1f |\n"
                              : "  %-15s %8s %8s %8s %8s %8s %8s %8s %9.1f\n",
                "exact (truth)", "-", "-", "-", "-", "-", "-", "-", truthMs);
    for (std::size_t k = 0; k < variants->size(); ++k) {
        std::vector<float> all;
        for (const auto& frame : images[k]) all.insert(all.end(), frame.begin(), frame.end());
        const voxel::ShadowErrors e = voxel::compareVisibility(all, allTruth, allMask);
        const double seam = voxel::seamMetric(images[k][0], truth[0], w, h, band, primary.mask);
        const double flicker = voxel::temporalFlicker(images[k], truth, masks);
        std::printf(rowFormat, (*variants)[k].name.c_str(), e.maePenumbra, e.biasPenumbra, e.maeAll,
                    e.leakRate, e.falseShadowRate, seam, flicker, ms[k]);
    }
    if (!args.outDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(args.outDir, ec);
        const std::string stem = std::filesystem::path(path).stem().string();
        const std::string prefix = (std::filesystem::path(args.outDir) / stem).string();
        if (Status s = writeVisibility(prefix + "-exact.png", truth[0], w, h); !s) {
            return reportError(s.error());
        }
        for (std::size_t k = 0; k < variants->size(); ++k) {
            const std::string out = prefix + "-" + (*variants)[k].name + ".png";
            if (Status s = writeVisibility(out, images[k][0], w, h); !s) {
                return reportError(s.error());
            }
        }
    }
    return 0;
}

int runShadows(const ShadowsArgs& args) {
    for (const std::string& path : args.scenes) {
        if (int rc = runScene(args, path); rc != 0) return rc;
    }
    return 0;
}

}  // namespace

Runner addShadowsCommand(CLI::App& app) {
    auto args = std::make_shared<ShadowsArgs>();
    app.add_option("scenes", args->scenes, "voxel scenes (.json)")->required();
    app.add_option("--size", args->size, "image size WxH")->capture_default_str();
    app.add_option("--samples", args->samples, "ground-truth rays per point")
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    app.add_option("--frames", args->frames, "frames of a turning sun (flicker)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--sun-step", args->sunStep, "degrees the sun turns per frame")
        ->check(finiteIn(-90.0, 90.0))
        ->capture_default_str();
    app.add_option(
        "--methods", args->methods,
        "comma-separated subset of hard, msm, msm16, vsm, sdf, sdf-centres, blend, "
        "blend-msm-near, blend-min, msm-penumbra, blend-penumbra, blend-msm-near-penumbra, flood");
    app.add_option("--sun-radius", args->sunRadius,
                   "sun angular radius in degrees (default: the scene's)")
        ->check(finiteIn(0.0, 20.0));
    app.add_option("--blend-band", args->blendBand,
                   "NEAR,FAR: the blend band (default: the scene's)")
        ->delimiter(',')
        ->expected(2)
        ->check(finiteIn(0.0, 1e6));
    app.add_option("--out-dir", args->outDir, "write each method's V image (PNG) here");
    app.add_flag("--markdown", args->markdown, "print the tables as Markdown");
    return [args] { return runShadows(*args); };
}

}  // namespace luxel::cli
