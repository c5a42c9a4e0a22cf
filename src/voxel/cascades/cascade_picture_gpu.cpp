// The voxel radiance cascades' picture on the GPU (radiance_cascades_gpu.h;
// docs/algorithms/voxel-radiance-cascades.md §4.3): the world through VoxelGpuRenderer's buffers,
// the faces' table and the GGX albedo table uploaded once, and one dispatch of
// cascades_picture.comp.glsl over the image reading the light buffer the lighting passes write,
// then one over the pixels adaptive_samples.h picks on the downloaded image.
#include <algorithm>
#include <bit>
#include <chrono>
#include <span>
#include <string>

#include "../../gpu/shaders/shared/medium_layout.h"
#include "../../gpu/shaders/shared/path_trace_layout.h"
#include "../ggx_albedo.h"
#include "../solver_surface.h"
#include "../sun_disk.h"
#include "adaptive_samples.h"
#include "cascade_gpu_state.h"
#include "cascade_picture.h"
#include "luxel/core/memory.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/path_trace.h"

namespace luxel::voxel {

namespace shared = gpu::shared;
using namespace cascades;

static_assert(LUXEL_PICTURE_FOLLOW_DEPTH == kSolverFollowDepth,
              "cascades_picture.comp.glsl unrolls the solver's follow depth");
static_assert(float(LUXEL_PICTURE_FOLLOW_ROUGHNESS) == kSolverFollowRoughness);
static_assert(float(LUXEL_PICTURE_SHARP_ALPHA) == kSolverSharpAlpha);
static_assert(float(LUXEL_PICTURE_ROUGH_ALPHA) == kSolverRoughAlpha);
static_assert(LUXEL_PICTURE_CAMERA_AIR_EXITS == kPictureCameraAirExits &&
              LUXEL_PICTURE_FOLLOWED_AIR_EXITS == kPictureFollowedAirExits);
// path_surface.glsl reads the picture's flags as the path tracer's.
static_assert(LUXEL_PICTURE_REFRACTION == LUXEL_PATH_REFRACTION &&
              LUXEL_PICTURE_FRESNEL_EXACT == LUXEL_PATH_FRESNEL_EXACT);

std::vector<shared::CascadeFaceSlot> cascades::faceSlots(const FaceTable& table) {
    const std::uint64_t slots = std::bit_ceil(std::max<std::uint64_t>(2 * table.size(), 16));
    const std::uint32_t mask = std::uint32_t(slots - 1);
    std::vector<shared::CascadeFaceSlot> out(
        slots, shared::CascadeFaceSlot{0, 0, LUXEL_PICTURE_EMPTY_SLOT, 0});
    for (int id = 0; id < table.size(); ++id) {
        const Face& f = table[id];
        const std::uint32_t low = shared::cascadeFaceKeyLow(f.voxel.x, f.voxel.y, f.normal);
        const std::uint32_t high = std::uint32_t(f.voxel.z);
        std::uint32_t slot = shared::cascadeFaceHash(low, high) & mask;
        while (out[slot].id != LUXEL_PICTURE_EMPTY_SLOT) slot = (slot + 1) & mask;
        out[slot] = {low, high, std::uint32_t(id), 0};
    }
    return out;
}

namespace {

// The adaptive pass's pixel list and results (shared/cascade_picture_layout.h).
constexpr std::size_t kRefineBinding = 22;

std::string sizeText(const Camera& camera) {
    return std::to_string(camera.width()) + "x" + std::to_string(camera.height());
}

// The GGX albedo table's nodes, as directionalAlbedoGgx interpolates them.
std::vector<float> albedoTable() {
    constexpr int side = LUXEL_PICTURE_ALBEDO_SIDE;
    std::vector<float> out(side * side);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            out[i * side + j] =
                float(directionalAlbedoGgx(double(i) / (side - 1), double(j) / (side - 1)));
        }
    return out;
}

// The sun, the materials' flags and the picture's ray counts as the shader reads them.
shared::CascadePicturePush picturePush(const ShadeOptions& shading, std::uint32_t faces,
                                       std::uint32_t slotMask) {
    shared::CascadePicturePush p{};
    p.seedLow = std::uint32_t(kReflectionSeed);
    p.seedHigh = std::uint32_t(kReflectionSeed >> 32);
    p.sunRays = kPictureSunRays;
    p.specularRays = kPictureSpecularRays;
    p.materialFlags =
        (shading.refraction ? LUXEL_PICTURE_REFRACTION : 0u) |
        (shading.fresnel == ShadeOptions::FresnelModel::Exact ? LUXEL_PICTURE_FRESNEL_EXACT : 0u) |
        (shading.materials.anyTransmission() ? LUXEL_PICTURE_TRANSMISSION : 0u);
    p.faces = faces;
    p.slotMask = slotMask;
    // The disk as SunDisk has it, in double, rounded once.
    const SunDisk disk = SunDisk::make(shading.sunDirection, shading.sunAngularRadius);
    p.sunX = float(disk.axis.x), p.sunY = float(disk.axis.y), p.sunZ = float(disk.axis.z);
    p.sunIrradianceR = shading.sunIrradiance.r;
    p.sunIrradianceG = shading.sunIrradiance.g;
    p.sunIrradianceB = shading.sunIrradiance.b;
    p.sunOverPdfScale = disk.radianceOverPdf(Rgb(1.0f)).r;
    packSunDisk(disk, p);
    return p;
}

// Refuses, with the bytes, a picture whose world, faces' table, image and adaptive pass's pixel
// list with its results (at most kAdaptiveMaxShare of the pixels, 16 bytes each) exceed `budget`
// (0: the device's memory).
Status checkRoom(const gpu::Context& context, const Camera& camera, std::uint64_t world,
                 std::uint64_t table, std::uint64_t budget) {
    const std::uint64_t pixels = std::uint64_t(camera.width()) * camera.height();
    const std::uint64_t image = pixels * 3 * sizeof(float);
    const std::uint64_t list =
        std::max<std::uint64_t>(16, std::uint64_t(kAdaptiveMaxShare * double(pixels)) * 16);
    const std::uint64_t need = world + table + image + list;
    const std::uint64_t room = budget > 0 ? budget : context.device().deviceLocalBytes;
    if (room > 0 && need > room) {
        return Error("the radiance cascades' picture " + sizeText(camera) + " on the GPU needs " +
                     formatBytes(need) + " of device memory (world " + formatBytes(world) +
                     ", faces' table " + formatBytes(table) + ", image " + formatBytes(image) +
                     ", adaptive pixel list " + formatBytes(list) + "), " +
                     (budget > 0 ? "the budget is " : "the device has ") + formatBytes(room));
    }
    return Ok{};
}

// The world, the faces' table and the albedo table on the device, after the memory check.
Result<std::unique_ptr<PictureGpu>> makePicture(gpu::Context& context,
                                                const RadianceCascades::State& state,
                                                const Camera& camera, std::uint64_t budget,
                                                VoxelGpuRenderer* uploaded) {
    const std::vector<shared::CascadeFaceSlot> slots = faceSlots(state.faces.table);
    const std::vector<float> albedo = albedoTable();
    // A world uploaded by another pass is already on the device (its owner counted it).
    const std::uint64_t world = uploaded ? 0
                                         : estimateVoxelGpuMemory(state.world->size(),
                                                                  state.world->chunkSize(),
                                                                  state.textures, 0, 0),
                        table = slots.size() * sizeof(shared::CascadeFaceSlot);
    if (Status s = checkRoom(context, camera, world, table, budget); !s) return s.error();
    auto picture = std::make_unique<PictureGpu>();
    auto program = context.program("cascades_picture", LUXEL_PICTURE_BUFFERS,
                                   sizeof(shared::CascadePicturePush));
    if (!program) return program.error();
    picture->program = *program;
    if (uploaded) {
        picture->world = uploaded;
    } else {
        auto own = VoxelGpuRenderer::create(context, *state.world, state.textures);
        if (!own) return own.error();
        picture->ownWorld = std::make_unique<VoxelGpuRenderer>(std::move(*own));
        picture->world = picture->ownWorld.get();
    }
    picture->slotMask = std::uint32_t(slots.size() - 1);
    picture->worldBytes = world;
    picture->tableBytes = table;
    for (auto [target, data] : {std::pair{&picture->slots, std::as_bytes(std::span(slots))},
                                std::pair{&picture->albedo, std::as_bytes(std::span(albedo))}}) {
        auto buffer = context.createBuffer(data.size());
        if (!buffer) return buffer.error();
        if (Status s = context.upload(**buffer, data); !s) return s.error();
        *target = std::move(*buffer);
    }
    return picture;
}

// The faces' far emitter share and near lists, and the lamps the glossy surfaces light-sample,
// on the device, when the CPU object has computed them since the last upload.
Status uploadNearEmitters(gpu::Context& context, const FaceData& faces, PictureGpu& picture) {
    if (picture.nearUploaded && picture.emitterVersion == faces.emitterVersion) return Ok{};
    const std::size_t count = std::size_t(faces.table.size());
    std::vector<shared::RgbTexel> far(count, shared::RgbTexel{0, 0, 0});
    for (std::size_t f = 0; f < count && f < faces.emitterFar.size(); ++f) {
        const Rgb& c = faces.emitterFar[f];
        far[f] = {c.r, c.g, c.b};
    }
    std::vector<std::uint32_t> offsets = faces.nearOffset;
    offsets.resize(count + 1, offsets.empty() ? 0 : offsets.back());
    const std::vector<shared::CascadeNearEmitter>& list = faces.nearEmitters;
    const GlossyLamps& glossy = faces.glossy;
    picture.nearBytes = 0;
    for (auto [target, data] :
         {std::pair{&picture.emitterFar, std::as_bytes(std::span(far))},
          std::pair{&picture.nearOffset, std::as_bytes(std::span(offsets))},
          std::pair{&picture.nearEmitters, std::as_bytes(std::span(list))},
          std::pair{&picture.glossyPicks, std::as_bytes(std::span(glossy.picks))},
          std::pair{&picture.glossyLamps, std::as_bytes(std::span(glossy.lamps))}}) {
        auto buffer = context.createBuffer(std::max<std::uint64_t>(data.size(), 16));
        if (!buffer) return buffer.error();
        if (!data.empty()) {
            if (Status s = context.upload(**buffer, data); !s) return s;
        }
        *target = std::move(*buffer);
        picture.nearBytes += data.size();
    }
    picture.lampCells = glossy.empty() ? Int3{} : glossy.cells;
    picture.emitterVersion = faces.emitterVersion;
    picture.nearUploaded = true;
    return Ok{};
}

}  // namespace

void RadianceCascadesGpu::useUploadedWorld(VoxelGpuRenderer& world) {
    impl_->uploadedWorld = &world;
    impl_->picture.reset();  // made again over `world` at the next render
}

Result<Image> RadianceCascadesGpu::render(const Camera& camera, double* gpuMilliseconds,
                                          std::uint64_t memoryBudget, int* refinedPixels) {
    Impl& g = *impl_;
    const RadianceCascades::State& state = *g.state;
    const int width = camera.width(), height = camera.height();
    if (std::int64_t(width) * height > kMaxPathPixels) {
        return Error("radiance cascades: image " + sizeText(camera) + " has more than " +
                     std::to_string(kMaxPathPixels) + " pixels");
    }
    if (!g.picture) {
        auto made = makePicture(*g.context, state, camera, memoryBudget, g.uploadedWorld);
        if (!made) return made.error();
        g.picture = std::move(*made);
    }
    PictureGpu& p = *g.picture;
    if (Status s = uploadNearEmitters(*g.context, state.faces, p); !s) return s.error();
    if (Status s =
            checkRoom(*g.context, camera, p.worldBytes, p.tableBytes + p.nearBytes, memoryBudget);
        !s) {
        return s.error();
    }
    const std::uint64_t imageBytes = std::uint64_t(width) * height * 3 * sizeof(float);
    if (Status s = g.context->ensureBuffer(p.image, p.imageBytes, imageBytes); !s) {
        return s.error();
    }
    if (Status s = g.context->ensureBuffer(p.refine, p.refineBytes, 16); !s) return s.error();
    // The ray caster's parameters for this camera, without its sun visibility arrays (the
    // picture's sun is shadow rays).
    ShadeOptions o = state.shading;
    o.shadows = false;
    o.materialReflectivity = nullptr;
    auto bound = p.world->bindings(camera, o);
    if (!bound) return bound.error();
    gpu::Dispatch d;
    d.name = "cascades picture " + sizeText(camera);
    d.program = p.program;
    d.buffers = *bound;
    for (gpu::Buffer* b : {g.light.get(), p.slots.get(), p.albedo.get(), p.image.get(),
                           p.emitterFar.get(), p.nearOffset.get(), p.nearEmitters.get(),
                           p.refine.get(), p.glossyPicks.get(), p.glossyLamps.get()}) {
        d.buffers.push_back(b);
    }
    shared::CascadePicturePush push =
        picturePush(state.shading, std::uint32_t(state.faces.table.size()), p.slotMask);
    push.lampCellsX = std::uint32_t(p.lampCells.x);
    push.lampCellsY = std::uint32_t(p.lampCells.y);
    push.lampCellsZ = std::uint32_t(p.lampCells.z);
    d.setPush(push);
    d.setThreads(std::uint64_t(width), std::uint64_t(height));
    Image out(width, height, 3);
    const auto draw = [&]() -> Status {
        auto timings = g.context->run(std::span(&d, 1));
        if (!timings) return timings.error();
        if (gpuMilliseconds && !timings->empty()) *gpuMilliseconds += timings->front().milliseconds;
        return Ok{};
    };
    if (gpuMilliseconds) *gpuMilliseconds = 0.0;
    if (Status s = draw(); !s) return s.error();
    if (Status s = g.context->download(*p.image,
                                       std::as_writable_bytes(std::span(out.data(), out.size())));
        !s) {
        return s.error();
    }
    // The adaptive pass: the CPU's rule on the first pass's image, then the same shader over the
    // list with more rays, writing those pixels over the first pass's (§4.2).
    const int refine = adaptiveSamples(state.shading);
    const std::vector<std::uint32_t> pixels =
        refine > 0 ? adaptivePixels(out, state.shading.adaptiveContrast)
                   : std::vector<std::uint32_t>{};
    if (refinedPixels) *refinedPixels = int(pixels.size());
    if (pixels.empty()) return out;
    // The pass writes each listed pixel's RGB ahead of the list, and only those come back: the
    // image stays as the first download left it elsewhere.
    const std::span<const std::byte> list = std::as_bytes(std::span(pixels));
    std::vector<float> refined(pixels.size() * 3);
    const std::span<std::byte> results = std::as_writable_bytes(std::span(refined));
    if (Status s = g.context->ensureBuffer(p.refine, p.refineBytes, results.size() + list.size());
        !s) {
        return s.error();
    }
    if (Status s = g.context->upload(*p.refine, list, results.size()); !s) return s.error();
    d.buffers[kRefineBinding] = p.refine.get();
    push.refineCount = std::uint32_t(pixels.size());
    push.refineSamples = std::uint32_t(refine);
    d.setPush(push);
    d.setThreads(std::uint64_t(width), (pixels.size() + width - 1) / std::uint64_t(width));
    if (Status s = draw(); !s) return s.error();
    if (Status s = g.context->download(*p.refine, results); !s) return s.error();
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const int x = int(pixels[i] % std::uint32_t(width)),
                  y = int(pixels[i] / std::uint32_t(width));
        for (int c = 0; c < 3; ++c) out.at(x, y, c) = refined[3 * i + std::size_t(c)];
    }
    return out;
}

Result<CascadeImage> renderRadianceCascadesGpu(gpu::Context& context, const VoxelWorld& world,
                                               const Camera& camera, const ShadeOptions& shading,
                                               const CascadeOptions& options,
                                               const TextureSet* textures, std::string* note) {
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        return std::chrono::duration<double>(Clock::now() - start).count();
    };
    auto cascades = RadianceCascades::create(world, textures, shading, options);
    if (!cascades) return cascades.error();
    if (note) note->clear();
    CascadeImage out;
    auto start = Clock::now();
    auto gpu = RadianceCascadesGpu::create(context, *cascades);
    if (!gpu) return gpu.error();
    if (auto solved = gpu->solve(); !solved) return solved.error();
    out.lightSeconds = since(start);
    start = Clock::now();
    Result<Image> image = gpu->render(camera, nullptr, 0, &out.refinedPixels);
    if (!image) {
        // solve() downloaded the faces' irradiance: the CPU draws the same picture.
        if (note) {
            *note =
                "the radiance cascades' picture was drawn on the CPU: " + image.error().message();
        }
        image = cascades->render(camera, &out.refinedPixels);
        if (!image) return image.error();
    }
    out.renderSeconds = since(start);
    out.radiance = std::move(*image);
    out.stats = cascades->stats();
    return out;
}

}  // namespace luxel::voxel
