// PathTracerGpu: the world through VoxelGpuRenderer's buffers, the emitters, the per-pixel sums,
// and dispatches of path_trace.comp.glsl in bands of rows and chunks of samples (CPU reference:
// PathTracer in path_trace.h).
#include "luxel/voxel/path_trace_gpu.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "gpu/shaders/shared/path_trace_layout.h"
#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/core/memory.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/voxel_gpu.h"
#include "voxel/sun_disk.h"

namespace luxel::voxel {

namespace shared = gpu::shared;

namespace {

// Rows per band and samples per dispatch: at most kMaxPathsPerDispatch paths, at least one row
// and one sample.
struct DispatchShape {
    int rows = 1;
    int samples = 1;
};

DispatchShape dispatchShape(int width, int height) {
    DispatchShape s;
    const std::int64_t budget = kMaxPathsPerDispatch;
    s.rows = static_cast<int>(std::clamp<std::int64_t>(budget / width, 1, std::max(height, 1)));
    s.samples = static_cast<int>(std::clamp<std::int64_t>(budget / (std::int64_t(width) * s.rows),
                                                          1, kPathSamplesPerDownload));
    return s;
}

// The path options as the shader reads them.
shared::PathTracePush pathPush(const ShadeOptions& shading, const PathTraceOptions& options,
                               int emitters) {
    shared::PathTracePush p{};
    p.seedLow = static_cast<std::uint32_t>(options.seed);
    p.seedHigh = static_cast<std::uint32_t>(options.seed >> 32);
    p.maxBounces = static_cast<std::uint32_t>(options.maxBounces);
    p.rouletteAfter = static_cast<std::uint32_t>(options.rouletteAfter);
    p.emitters = static_cast<std::uint32_t>(emitters);
    // Normalised in double, as the CPU tracer's SunDisk does, then rounded.
    const Vec3 d = shading.sunDirection;
    const Vec3d sun = normalize(Vec3d{d.x, d.y, d.z});
    p.sunX = float(sun.x), p.sunY = float(sun.y), p.sunZ = float(sun.z);
    p.sunIrradianceR = shading.sunIrradiance.r;
    p.sunIrradianceG = shading.sunIrradiance.g;
    p.sunIrradianceB = shading.sunIrradiance.b;
    p.materialFlags =
        (shading.refraction ? LUXEL_PATH_REFRACTION : 0u) |
        (shading.fresnel == ShadeOptions::FresnelModel::Exact ? LUXEL_PATH_FRESNEL_EXACT : 0u) |
        (options.sunThroughGlass && shading.lightPassesMedia() ? LUXEL_PATH_SUN_CHAINS : 0u);
    // The disk as SunDisk has it, in double, rounded once.
    const SunDisk disk = SunDisk::make(d, shading.sunAngularRadius);
    packSunDisk(disk, p);
    if (!disk.delta()) p.sunPdf = float(disk.pdf());
    return p;
}

// Which texture slots' materials emit (the plain one last): with the world, all the emitter list
// depends on.
std::vector<bool> emittingSlots(const MaterialTable& materials) {
    std::vector<bool> out;
    for (int slot = 0; slot < LUXEL_VOXEL_PLAIN_MATERIAL; ++slot) {
        out.push_back(materials.forSlot(slot).emission.maxComponent() > 0.0f);
    }
    out.push_back(materials.plain().emission.maxComponent() > 0.0f);
    return out;
}

std::string sizeText(const Camera& camera) {
    return std::to_string(camera.width()) + "x" + std::to_string(camera.height());
}

// What the host's part of the estimate is for, in checkMemory's refusal.
std::string hostWhat(const Camera& camera) {
    return "path tracing " + sizeText(camera) + " on the GPU (the running sums and a download)";
}

}  // namespace

PathTraceMemory estimatePathTraceGpuMemory(const VoxelWorld& world, const TextureSet* textures,
                                           int width, int height, int emitters) {
    const std::uint64_t pixels =
        std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0));
    PathTraceMemory m;
    m.host = pixels * (sizeof(PathPixelSums) + sizeof(shared::PathPixelSums));
    // The world without the ray caster's image (binding 6 is not allocated for path tracing).
    m.world = estimateVoxelGpuMemory(world.size(), world.chunkSize(), textures, 0, 0);
    m.sums = pixels * sizeof(shared::PathPixelSums);
    m.emitters = std::uint64_t(std::max(emitters, 1)) * sizeof(shared::PathEmitterVoxel);
    return m;
}

struct PathTracerGpu::State {
    gpu::Context* context = nullptr;
    std::unique_ptr<VoxelGpuRenderer> owned;  // null when the world's upload is borrowed
    VoxelGpuRenderer* world = nullptr;
    const VoxelWorld* source = nullptr;
    const TextureSet* textures = nullptr;
    Camera camera;
    ShadeOptions shading;
    PathTraceOptions options;
    gpu::Program* program = nullptr;
    std::shared_ptr<gpu::Buffer> emitters, sums;
    std::uint64_t emittersBytes = 0, sumsBytes = 0;  // their sizes
    int emitterCount = 0;
    // What the uploaded emitters were found in: the world's generation, the emitting slots and
    // whether emitters are sampled at all (0: none uploaded yet).
    std::uint64_t emitterGeneration = 0;
    std::vector<bool> emitterSlots;
    bool emittersSampled = false;
    std::uint64_t emitterUploadBytes = 0;
    std::vector<PathPixelSums> totals;  // the running sums, in double
    int samples = 0;
    bool ready = false;  // false after a restart that failed half way: no samples until another
    double gpuMilliseconds = 0.0;

    // A new accumulation of this view (create and restart): the checks, the memory, the emitters
    // when the world or their materials changed, the sums when the image grew.
    Status prepare(const Camera& newCamera, const ShadeOptions& newShading,
                   const PathTraceOptions& newOptions) {
        if (Status s = validatePathTrace(newShading, newOptions, newCamera); !s) return s;
        const std::vector<bool> slots = emittingSlots(newShading.materials);
        const bool findEmitters =
            emitterGeneration == 0 || emitterGeneration != world->worldGeneration() ||
            emittersSampled != newOptions.sampleEmitters || emitterSlots != slots;
        PathEmitters found;
        if (findEmitters && newOptions.sampleEmitters) {
            found = PathEmitters::find(*source, newShading.materials);
        }
        PathTraceMemory need =
            estimatePathTraceGpuMemory(*source, textures, newCamera.width(), newCamera.height(),
                                       findEmitters ? found.size() : emitterCount);
        // The world is on the device already (make checks the estimate before its upload).
        need.world = world->deviceBytes();
        const std::uint64_t device = context->device().deviceLocalBytes;
        if (device > 0 && need.device() > device) {
            return Error("path tracing " + sizeText(newCamera) + " on the GPU needs " +
                         formatBytes(need.device()) + " of device memory (world " +
                         formatBytes(need.world) + ", sums " + formatBytes(need.sums) + ", " +
                         std::to_string(findEmitters ? found.size() : emitterCount) + " emitters " +
                         formatBytes(need.emitters) + "), the device has " + formatBytes(device));
        }
        // The running sums are replaced, not added to: count what stays.
        const std::uint64_t held = totals.size() * sizeof(PathPixelSums);
        if (Status s = checkMemory(need.host > held ? need.host - held : 0, hostWhat(newCamera));
            !s) {
            return s;
        }
        // From here the old view is gone; a failure leaves the tracer waiting for a restart.
        ready = false;
        samples = 0;
        if (findEmitters) {
            emitterGeneration = 0;  // until the upload succeeds
            std::vector<shared::PathEmitterVoxel> voxels;
            for (const Int3& v : found.voxels()) voxels.push_back({v.x, v.y, v.z, 0});
            if (voxels.empty()) voxels.push_back({});
            const std::uint64_t bytes = voxels.size() * sizeof(shared::PathEmitterVoxel);
            if (Status st = context->ensureBuffer(emitters, emittersBytes, bytes); !st) return st;
            if (Status st = context->upload(*emitters, std::as_bytes(std::span(voxels))); !st) {
                return st;
            }
            emitterUploadBytes += bytes;
            emitterCount = found.size();
            emitterGeneration = world->worldGeneration();
            emitterSlots = slots;
            emittersSampled = newOptions.sampleEmitters;
        }
        if (!sums || sumsBytes < need.sums) {
            sums.reset();
            sumsBytes = 0;
            auto b = context->createBuffer(need.sums);
            if (!b) return b.error();
            sums = *b;
            sumsBytes = need.sums;
        }
        camera = newCamera, shading = newShading, options = newOptions;
        totals.assign(std::size_t(newCamera.width()) * newCamera.height(), PathPixelSums{});
        ready = true;
        return Ok{};
    }

    // One submission of `count` samples per pixel (<= kPathSamplesPerDownload) from `first`,
    // then the sums downloaded and added to the totals.
    Status trace(int first, int count) {
        // The ray caster's parameters for this camera and the path tracer's light; no sun
        // visibility arrays (the path tracer's sun is a shadow ray).
        ShadeOptions o = shading;
        o.shadows = false;
        o.materialReflectivity = nullptr;
        auto bound = world->bindings(camera, o);
        if (!bound) return bound.error();
        std::vector<gpu::Buffer*> buffers = *bound;
        buffers.push_back(emitters.get());
        buffers.push_back(sums.get());
        const int width = camera.width(), height = camera.height();
        const DispatchShape shape = dispatchShape(width, height);
        shared::PathTracePush push = pathPush(shading, options, emitterCount);
        std::vector<gpu::Dispatch> dispatches;
        for (int done = 0; done < count; done += shape.samples) {
            const int chunk = std::min(shape.samples, count - done);
            for (int row = 0; row < height; row += shape.rows) {
                const int rows = std::min(shape.rows, height - row);
                gpu::Dispatch d;
                d.name = "path trace rows " + std::to_string(row) + " samples " +
                         std::to_string(first + done);
                d.program = program;
                d.buffers = buffers;
                push.rowOffset = static_cast<std::uint32_t>(row);
                push.rows = static_cast<std::uint32_t>(rows);
                push.firstSample = static_cast<std::uint32_t>(first + done);
                push.samples = static_cast<std::uint32_t>(chunk);
                push.accumulate = done > 0 ? 1u : 0u;
                d.setPush(push);
                d.setThreads(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(rows));
                dispatches.push_back(std::move(d));
            }
        }
        auto passes = context->run(dispatches);
        if (!passes) return passes.error();
        for (const gpu::PassTiming& t : *passes) gpuMilliseconds += t.milliseconds;
        std::vector<shared::PathPixelSums> pixels(totals.size());
        if (Status st = context->download(*sums, std::as_writable_bytes(std::span(pixels))); !st) {
            return st;
        }
        // Undo the shift: with m = count, sum x = m s0 + S1 and sum x^2 = m s0^2 + 2 s0 S1 + S2.
        const double m = count;
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            const shared::PathPixelSums& p = pixels[i];
            PathPixelSums& t = totals[i];
            const double shift[4] = {p.shiftR, p.shiftG, p.shiftB, p.shiftL};
            const double sum[4] = {p.sumR, p.sumG, p.sumB, p.sumL};
            const double squares[4] = {p.squaresR, p.squaresG, p.squaresB, p.squaresL};
            for (int c = 0; c < 3; ++c) {
                t.sum[c] += m * shift[c] + sum[c];
                t.sumSquares[c] += m * shift[c] * shift[c] + 2.0 * shift[c] * sum[c] + squares[c];
            }
            t.luminance += m * shift[3] + sum[3];
            t.luminanceSquares += m * shift[3] * shift[3] + 2.0 * shift[3] * sum[3] + squares[3];
        }
        return Ok{};
    }
};

PathTracerGpu::PathTracerGpu(std::unique_ptr<State> state) : state_(std::move(state)) {}
PathTracerGpu::PathTracerGpu(PathTracerGpu&&) noexcept = default;
PathTracerGpu& PathTracerGpu::operator=(PathTracerGpu&&) noexcept = default;
PathTracerGpu::~PathTracerGpu() = default;

Result<PathTracerGpu> PathTracerGpu::create(gpu::Context& context, const VoxelWorld& world,
                                            const Camera& camera, const ShadeOptions& shading,
                                            const PathTraceOptions& options,
                                            const TextureSet* textures) {
    return make(context, nullptr, world, camera, shading, options, textures);
}

Result<PathTracerGpu> PathTracerGpu::create(gpu::Context& context, VoxelGpuRenderer& uploaded,
                                            const VoxelWorld& world, const Camera& camera,
                                            const ShadeOptions& shading,
                                            const PathTraceOptions& options) {
    return make(context, &uploaded, world, camera, shading, options, nullptr);
}

Result<PathTracerGpu> PathTracerGpu::make(gpu::Context& context, VoxelGpuRenderer* uploaded,
                                          const VoxelWorld& world, const Camera& camera,
                                          const ShadeOptions& shading,
                                          const PathTraceOptions& options,
                                          const TextureSet* textures) {
    if (Status s = validatePathTrace(shading, options, camera); !s) return s.error();
    auto state = std::make_unique<State>();
    State& s = *state;
    s.context = &context;
    s.source = &world;
    s.textures = textures;
    s.world = uploaded;
    // The estimate before anything is allocated or uploaded (prepare checks it again with the
    // emitters found).
    const PathTraceMemory need =
        estimatePathTraceGpuMemory(world, textures, camera.width(), camera.height(), 0);
    const std::uint64_t device = context.device().deviceLocalBytes;
    const std::uint64_t deviceNeed = need.device() - (uploaded ? need.world : 0);
    if (device > 0 && deviceNeed > device) {
        return Error("path tracing " + sizeText(camera) + " on the GPU needs " +
                     formatBytes(deviceNeed) + " of device memory (world " +
                     formatBytes(uploaded ? 0 : need.world) + ", sums " + formatBytes(need.sums) +
                     "), the device has " + formatBytes(device));
    }
    if (Status st = checkMemory(need.host, hostWhat(camera)); !st) return st.error();
    auto program = context.program("path_trace", LUXEL_PATH_BUFFERS, sizeof(shared::PathTracePush));
    if (!program) return program.error();
    s.program = *program;
    if (!uploaded) {
        auto renderer = VoxelGpuRenderer::create(context, world, textures);
        if (!renderer) return renderer.error();
        s.owned = std::make_unique<VoxelGpuRenderer>(std::move(*renderer));
        s.world = s.owned.get();
    }
    if (Status st = s.prepare(camera, shading, options); !st) return st.error();
    return PathTracerGpu(std::move(state));
}

Status PathTracerGpu::restart(const Camera& camera, const ShadeOptions& shading,
                              const PathTraceOptions& options) {
    State& s = *state_;
    if (Status st = s.prepare(camera, shading, options); !st) {
        s.samples = 0;
        std::fill(s.totals.begin(), s.totals.end(), PathPixelSums{});
        return st;
    }
    return Ok{};
}

Status PathTracerGpu::addSamples(int count) {
    State& s = *state_;
    if (!s.ready) {
        return Error("path tracing on the GPU: the last restart failed; restart the tracer again");
    }
    if (count < 1 || count > kMaxPathSamples - s.samples) {
        return Error("path tracing: " + std::to_string(count) + " more samples after " +
                     std::to_string(s.samples) + " is outside 1.." +
                     std::to_string(kMaxPathSamples) + " in all");
    }
    s.gpuMilliseconds = 0.0;
    // Each download's samples count as soon as they are in the totals, so after an error the
    // image is that of samplesDone() samples.
    for (int left = count; left > 0;) {
        const int chunk = std::min(kPathSamplesPerDownload, left);
        if (Status st = s.trace(s.samples, chunk); !st) return st;
        s.samples += chunk;
        left -= chunk;
    }
    return Ok{};
}

int PathTracerGpu::samplesDone() const {
    return state_->samples;
}

double PathTracerGpu::lastGpuMilliseconds() const {
    return state_->gpuMilliseconds;
}

const VoxelGpuRenderer& PathTracerGpu::uploaded() const {
    return *state_->world;
}

std::uint64_t PathTracerGpu::emitterUploadBytes() const {
    return state_->emitterUploadBytes;
}

PathTraceImage PathTracerGpu::image() const {
    const State& s = *state_;
    return pathTraceImageOf(s.totals, s.camera.width(), s.camera.height(), s.samples);
}

Result<PathTraceImage> pathTraceGpu(gpu::Context& context, const VoxelWorld& world,
                                    const Camera& camera, const ShadeOptions& shading,
                                    const PathTraceOptions& options, const TextureSet* textures) {
    auto tracer = PathTracerGpu::create(context, world, camera, shading, options, textures);
    if (!tracer) return tracer.error();
    if (Status s = tracer->addSamples(options.samplesPerPixel); !s) return s.error();
    return tracer->image();
}

}  // namespace luxel::voxel
