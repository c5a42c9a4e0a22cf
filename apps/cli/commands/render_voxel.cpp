// `luxel render` for voxel scenes: DDA ray casting with shading, shadows and reflections, on the
// CPU or (--backend) the GPU; or, with --solver path, the path tracer (CPU or GPU); or, with
// --solver ao, CPU sky visibility; or, with --solver rc, radiance cascades (lighting passes and
// picture on the CPU or the GPU).
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "commands/render_outputs.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/gpu/context.h"
#include "luxel/post/finish.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/sky_visibility.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

// The path tracer's line of the summary: its settings and the noise left.
void printPathSummary(const voxel::PathTraceOptions& path, double relativeError) {
    std::printf("  path tracing: %d samples per pixel, at most %d bounces, seed %llu, ",
                path.samplesPerPixel, path.maxBounces, static_cast<unsigned long long>(path.seed));
    if (std::isnan(relativeError)) {
        std::printf("standard error n/a (needs 2 samples or more, and light)\n");
    } else {
        std::printf("relative standard error %.3f%%\n", 100.0 * relativeError);
    }
}

// Sky visibility's line of the summary: its settings.
void printAoSummary(const voxel::SkyVisibilityOptions& ao) {
    std::printf("  sky visibility: %d rays per point, radius %g voxels, seed %llu\n", ao.rays,
                ao.radius, static_cast<unsigned long long>(ao.seed));
}

// The radiance cascades' line of the summary: their layout, memory and times, and the pixels
// of the `pixels` the adaptive pass drew again.
void printCascadeSummary(const voxel::CascadeImage& c, const voxel::ShadeOptions& shading,
                         double pixels) {
    const std::string passages =
        c.stats.passages > 0 ? " (" + std::to_string(c.stats.passages) + " runs through glass)"
                             : std::string();
    std::printf(
        "  radiance cascades: %d faces, %d levels from spacing %d (%lld probes), "
        "%lld segments%s, %s; build %.3f s, %d bounces %.3f s, picture %.3f s\n",
        c.stats.faces, c.stats.levels, c.stats.spacing, static_cast<long long>(c.stats.probes),
        static_cast<long long>(c.stats.segments), passages.c_str(),
        formatBytes(c.stats.bytes).c_str(), c.stats.buildSeconds, c.stats.bounces, c.lightSeconds,
        c.renderSeconds);
    std::printf("  picture: %d samples per pixel, %d pixels (%.2f%%) again with %d samples\n",
                voxel::samplesPerPixel(shading), c.refinedPixels,
                pixels > 0 ? 100.0 * c.refinedPixels / pixels : 0.0, shading.adaptiveSamples);
}

bool endsWithExr(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

Result<Image> renderOnGpu(gpu::Context& context, const voxel::VoxelScene& scene,
                          const voxel::Camera& camera) {
    auto renderer = voxel::VoxelGpuRenderer::create(context, scene.world, &scene.textures);
    if (!renderer) return renderer.error();
    return renderer->render(camera, scene.shading);
}

// `v` turned about the y axis by `degrees`, +z towards +x (as a camera's yaw turns its view).
Vec3 turnedAboutVertical(Vec3 v, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    return {static_cast<float>(v.x * c + v.z * s), v.y, static_cast<float>(v.z * c - v.x * s)};
}

}  // namespace

post::PostOptions applyPostFlags(post::PostOptions scene, const PostFlags& flags) {
    if (flags.bloom) scene.bloom.strength = *flags.bloom;
    if (flags.internalScale) scene.internalScale = *flags.internalScale;
    if (flags.sharpness) scene.sharpness = *flags.sharpness;
    if (flags.upscaler) scene.upscaler = *flags.upscaler;
    if (flags.exposure) scene.tone.exposureStops = *flags.exposure;
    if (flags.tone) scene.tone.curve = *flags.tone;
    return scene;
}

void addVoxelSurfaceFlags(CLI::App& app, VoxelSurfaceFlags& flags) {
    app.add_option("--lighting", flags.lighting,
                   "voxel: classic or physical (default: the scene's)");
    app.add_option("--specular", flags.specular, "voxel, physical: none, blinn-phong or ggx");
    app.add_option("--fresnel", flags.fresnel, "voxel, physical: schlick or exact");
    app.add_flag("--no-refraction", flags.noRefraction,
                 "voxel, physical: transmissive materials render opaque");
    app.add_option("--shadows", flags.shadows,
                   "voxel, physical: sun visibility hard, exact, msm, vsm, sdf, blend or flood "
                   "(the scene's render.shadows settings otherwise; turns shadows on)");
    app.add_flag("--no-emitter-light", flags.noEmitterLight,
                 "voxel, physical: emissive voxels light no other surface");
    app.add_option("--emitter-rays", flags.emitterRays,
                   "voxel, physical: shadow rays per emissive face, 1.." +
                       std::to_string(voxel::kMaxEmitterRays) + " (default: the scene's, else 4)")
        ->check(wholeIn(1, voxel::kMaxEmitterRays));
    app.add_option("--sky-ambient-rays", flags.skyAmbientRays,
                   "voxel, physical: rays per shaded point that find the sky a face sees, 0.." +
                       std::to_string(voxel::kMaxSkyAmbientRays) +
                       " (0: the constant share render.sky_ambient; default: the scene's, else 0)")
        ->check(wholeIn(0, voxel::kMaxSkyAmbientRays));
}

Status applyVoxelSurfaceFlags(const VoxelSurfaceFlags& flags, voxel::ShadeOptions& o) {
    using Options = voxel::ShadeOptions;
    if (flags.lighting == "classic") {
        o.lighting = Options::Lighting::Classic;
    } else if (flags.lighting == "physical") {
        o.lighting = Options::Lighting::Physical;
    } else if (!flags.lighting.empty()) {
        return Error("--lighting '" + flags.lighting + "' is not classic or physical");
    }
    if (flags.specular == "none") {
        o.specular = Options::Specular::None;
    } else if (flags.specular == "blinn-phong") {
        o.specular = Options::Specular::BlinnPhong;
    } else if (flags.specular == "ggx") {
        o.specular = Options::Specular::Ggx;
    } else if (!flags.specular.empty()) {
        return Error("--specular '" + flags.specular + "' is not none, blinn-phong or ggx");
    }
    if (flags.fresnel == "schlick") {
        o.fresnel = Options::FresnelModel::Schlick;
    } else if (flags.fresnel == "exact") {
        o.fresnel = Options::FresnelModel::Exact;
    } else if (!flags.fresnel.empty()) {
        return Error("--fresnel '" + flags.fresnel + "' is not schlick or exact");
    }
    if (flags.noRefraction) o.refraction = false;
    if (flags.noEmitterLight) o.emitterLight = false;
    if (flags.emitterRays != 0) o.emitterRays = flags.emitterRays;
    if (flags.skyAmbientRays >= 0) o.skyAmbientRays = flags.skyAmbientRays;
    if (!flags.shadows.empty()) {
        voxel::ShadowMethod method;
        if (!voxel::parseShadowMethod(flags.shadows, method)) {
            return Error("--shadows '" + flags.shadows +
                         "' is not hard, exact, msm, vsm, sdf, blend or flood");
        }
        o.shadowSettings.method = method;
        o.shadows = true;
    }
    return Ok{};
}

void addVoxFrameOption(CLI::App& app, int& frame) {
    app.add_option("--frame", frame,
                   "MagicaVoxel worlds: the animation frame to show (default: the scene's "
                   "\"frame\", else 0)")
        ->check(wholeIn(0, 1 << 30));
}

int renderVoxelScene(const VoxelRenderRequest& request, voxel::VoxelScene loaded) {
    voxel::VoxelScene* scene = &loaded;
    if (request.sunYawDegrees != 0) {
        scene->shading.sunDirection =
            turnedAboutVertical(scene->shading.sunDirection, request.sunYawDegrees);
    }
    if (Status s = applyVoxelSurfaceFlags(request.surfaces, scene->shading); !s) {
        return reportError(s.error());
    }
    const double loadSeconds = request.loadSeconds;
    if (request.samples != 0) {
        if (request.samples < 1 || request.samples > voxel::kMaxSamplesPerPixel) {
            return reportError(
                Error("--samples must be in 1.." + std::to_string(voxel::kMaxSamplesPerPixel)));
        }
        scene->shading.samplesPerPixel = request.samples;
    }
    if (request.adaptiveSamples >= 0) {
        if (!request.cascadeSolver) {
            return reportError(Error("--adaptive-samples applies to --solver rc"));
        }
        if (request.adaptiveSamples > voxel::kMaxSamplesPerPixel) {
            return reportError(Error("--adaptive-samples must be in 0.." +
                                     std::to_string(voxel::kMaxSamplesPerPixel)));
        }
        scene->shading.adaptiveSamples = request.adaptiveSamples;
    }
    if (!request.filter.empty()) {
        const auto filter = voxel::parseTextureFilter(request.filter);
        if (!filter) {
            return reportError(Error("--filter '" + request.filter +
                                     "' is not nearest, trilinear or anisotropic"));
        }
        scene->shading.textureFilter = *filter;
    }
    const VoxelSurfaceFlags& f = request.surfaces;
    // --samples applies to every solver that draws a picture from camera rays; the path tracer
    // jitters its own.
    const bool surfaceFlags = !request.filter.empty() || !f.lighting.empty() ||
                              !f.specular.empty() || !f.fresnel.empty() || f.noRefraction ||
                              !f.shadows.empty() || f.noEmitterLight || f.emitterRays != 0 ||
                              f.skyAmbientRays >= 0;
    // The flags the other solvers refuse, named once, with what the solver takes instead.
    const auto rayCasterOnly = [](const char* flags, const char* solverTakes) {
        return Error(std::string(flags) +
                     " and the surface flags (--lighting, --specular, --fresnel, "
                     "--no-refraction, --shadows, --no-emitter-light, --emitter-rays, "
                     "--sky-ambient-rays) apply to "
                     "the ray caster; --solver " +
                     solverTakes);
    };
    if (request.pathSolver && (surfaceFlags || request.samples != 0)) {
        return reportError(
            rayCasterOnly("--samples, --filter", "path takes --spp and --max-bounces"));
    }
    if (request.aoSolver && surfaceFlags) {
        return reportError(
            rayCasterOnly("--filter", "ao takes --ao-rays, --ao-radius and --samples"));
    }
    if (request.cascadeSolver && surfaceFlags) {
        return reportError(
            rayCasterOnly("--filter", "rc takes --rc-spacing, --bounces and --samples"));
    }
    // The cascades' lighting passes and picture run on the GPU too (the build on the CPU), and so
    // does the path tracer; sky visibility is CPU only.
    const bool cpuSolver = request.aoSolver;
    if (!request.pathStdError.empty() && !endsWithExr(request.pathStdError)) {
        return reportError(Error("--std-error '" + request.pathStdError +
                                 "' must be an .exr file (linear float)"));
    }
    if (request.cascadeSolver) {
        if (Status s = voxel::validateCascades(request.cascades); !s) return reportError(s.error());
    }
    if (cpuSolver && request.backend == gpu::Backend::Gpu) {
        return reportError(Error("--solver ao runs on the CPU; --backend gpu does not apply"));
    }
    auto context = cpuSolver ? Result<std::unique_ptr<gpu::Context>>(nullptr)
                             : chooseGpuBackend(request.backend, request.device, request.quiet);
    if (!context) return reportError(context.error());
    const post::PostOptions post = applyPostFlags(scene->post, request.post);
    const int width = scene->camera.width(), height = scene->camera.height();
    const voxel::Camera camera =
        post.internalScale < 1.0f
            ? post::resizedCamera(scene->camera, post::internalSide(width, post.internalScale),
                                  post::internalSide(height, post.internalScale))
            : scene->camera;
    // Refuse before the first frame buffer (`luxel info` reports the same estimate).
    // The path tracer adds its running sums (estimatePathTraceMemory; on the GPU also their
    // download). Sky visibility adds its visibility image and its radiance: 4 floats a pixel.
    const std::uint64_t pathBytes =
        request.pathSolver
            ? (*context ? voxel::estimatePathTraceGpuMemory(scene->world, &scene->textures,
                                                            camera.width(), camera.height(), 0)
                        : voxel::estimatePathTraceMemory(camera.width(), camera.height()))
                  .host
        : request.aoSolver ? std::uint64_t(camera.width()) * camera.height() * 16
                           : 0;
    if (Status s = checkRenderMemory(
            width, height, frameBytes(width, height, post, *context != nullptr) + pathBytes);
        !s) {
        return reportError(s.error());
    }
    Stopwatch renderTime;
    Image internal, standardError;
    double relativeError = 0.0;
    voxel::CascadeImage cascaded;
    if (request.pathSolver) {
        auto traced = *context ? voxel::pathTraceGpu(**context, scene->world, camera,
                                                     scene->shading, request.path, &scene->textures)
                               : voxel::pathTrace(scene->world, camera, scene->shading,
                                                  request.path, &scene->textures);
        if (!traced) return reportError(traced.error());
        relativeError = traced->relativeError;
        internal = std::move(traced->radiance);
        standardError = std::move(traced->standardError);
    } else if (request.aoSolver) {
        auto shaded = voxel::renderSkyVisibility(scene->world, camera, scene->shading, request.ao,
                                                 &scene->textures);
        if (!shaded) return reportError(shaded.error());
        internal = std::move(shaded->radiance);
    } else if (request.cascadeSolver) {
        std::string note;  // why the GPU's picture was drawn on the CPU
        auto shaded = *context ? voxel::renderRadianceCascadesGpu(**context, scene->world, camera,
                                                                  scene->shading, request.cascades,
                                                                  &scene->textures, &note)
                               : voxel::renderRadianceCascades(scene->world, camera, scene->shading,
                                                               request.cascades, &scene->textures);
        if (!shaded) return reportError(shaded.error());
        cascaded = std::move(*shaded);
        internal = std::move(cascaded.radiance);
        // An automatic spacing doubled for the runs through glass: which, and why.
        if (!cascaded.stats.spacingNote.empty()) {
            std::fprintf(stderr, "luxel: note: %s\n", cascaded.stats.spacingNote.c_str());
        }
        if (!note.empty()) std::fprintf(stderr, "luxel: note: %s\n", note.c_str());
    } else if (*context) {
        auto image = renderOnGpu(**context, *scene, camera);
        if (!image) return reportError(image.error());
        internal = std::move(*image);
    } else {
        internal = voxel::render(scene->world, camera, scene->shading, &scene->textures);
    }
    const double renderSeconds = renderTime.seconds();
    const Image radiance = post::processInternal(internal, width, height, post);
    // EXR keeps linear radiance; PNG gets the display transform. Both carry the provenance.
    RenderImages images;
    images.out = request.out;
    images.png = request.png;
    images.linear = &radiance;
    images.linearName = "radiance";
    images.displayHdr = &radiance;
    images.tone = post.tone;
    images.autoExposure = request.autoExposure;
    images.quiet = request.quiet;
    images.metadata = voxelMetadata(request.scene, scene->shading, post, width, height,
                                    context->get(), renderSeconds);
    if (request.pathSolver) {
        setMetadata(images.metadata, "luxel.solver", "path");
        setMetadata(images.metadata, "luxel.lighting", "path");
        setNumber(images.metadata, "luxel.samples", request.path.samplesPerPixel);
        setNumber(images.metadata, "luxel.path.max_bounces", request.path.maxBounces);
        setMetadata(images.metadata, "luxel.seed", std::to_string(request.path.seed));
        setNumber(images.metadata, "luxel.path.relative_error", relativeError);
    }
    if (request.aoSolver) {
        setMetadata(images.metadata, "luxel.solver", "ao");
        setMetadata(images.metadata, "luxel.lighting", "sky visibility");
        setNumber(images.metadata, "luxel.ao.rays", request.ao.rays);
        setNumber(images.metadata, "luxel.ao.radius", request.ao.radius);
        setMetadata(images.metadata, "luxel.seed", std::to_string(request.ao.seed));
    }
    if (request.cascadeSolver) {
        setMetadata(images.metadata, "luxel.solver", "rc");
        setMetadata(images.metadata, "luxel.lighting", "radiance cascades");
        setNumber(images.metadata, "luxel.rc.spacing", cascaded.stats.spacing);
        setNumber(images.metadata, "luxel.rc.levels", cascaded.stats.levels);
        setNumber(images.metadata, "luxel.rc.bounces", cascaded.stats.bounces);
        setNumber(images.metadata, "luxel.rc.adaptive_samples", scene->shading.adaptiveSamples);
        setNumber(images.metadata, "luxel.rc.refined_pixels", cascaded.refinedPixels);
    }
    if (request.sunYawDegrees != 0)
        setNumber(images.metadata, "luxel.sun_yaw", request.sunYawDegrees);
    ImageMetadata errorMetadata = images.metadata;
    if (Status s = writeRenderImages(std::move(images)); !s) return reportError(s.error());
    if (!request.pathStdError.empty()) {
        // At the internal size: the post pipeline does not apply to an error estimate.
        setMetadata(errorMetadata, "luxel.content", "standard error, linear");
        if (Status s = writeImages({{request.pathStdError, &standardError, &errorMetadata}}); !s) {
            return reportError(s.error());
        }
    }
    if (request.stats) std::printf("stats solve_seconds=%.6f\n", renderSeconds);
    if (!request.quiet) {
        const Int3 s = scene->world.size();
        const double pixels = static_cast<double>(radiance.width()) * radiance.height();
        const std::string transport =
            request.pathSolver ? "path traced"
            : request.aoSolver ? "sky visibility"
            : request.cascadeSolver
                ? "radiance cascades"
                : std::to_string(scene->shading.maxReflections) + " reflections";
        std::printf("%s: voxel world %dx%dx%d (%llu solid), image %dx%d, %s, %s\n",
                    request.scene.c_str(), s.x, s.y, s.z,
                    static_cast<unsigned long long>(scene->world.solidCount()), radiance.width(),
                    radiance.height(), transport.c_str(),
                    *context ? ("gpu: " + (**context).device().name).c_str() : "cpu");
        if (request.pathSolver) {
            printPathSummary(request.path, relativeError);
        } else if (request.aoSolver) {
            printAoSummary(request.ao);
        } else if (request.cascadeSolver) {
            printCascadeSummary(cascaded, scene->shading,
                                double(internal.width()) * internal.height());
        } else {
            std::printf("  %d samples per pixel, %s textures\n",
                        voxel::samplesPerPixel(scene->shading),
                        voxel::textureFilterName(scene->shading.textureFilter));
        }
        std::printf("  world %.3f s, render %.3f s incl. upload (%.2f Mpixel/s)\n", loadSeconds,
                    renderSeconds, pixels / renderSeconds * 1e-6);
        if (post.internalScale < 1.0f || post.bloom.strength > 0.0f) {
            std::printf("  internal %dx%d (%s upscaler), bloom %.2f\n", internal.width(),
                        internal.height(), post::upscalerName(post.upscaler), post.bloom.strength);
        }
        std::printf("  wrote %s%s%s%s%s\n", request.out.c_str(),
                    request.out.empty() || request.png.empty() ? "" : ", ", request.png.c_str(),
                    request.pathStdError.empty() ? "" : ", ", request.pathStdError.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
