// VoxelGpuRenderer's passes: the per-render parameters, banded dispatches of
// voxel_render.comp.glsl (CPU reference: render() in shading.cpp) and castRays' voxel_cast.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <string>

#include "gpu/shaders/shared/sky_ambient.h"
#include "gpu/shaders/shared/sky_preetham.h"
#include "gpu/shaders/shared/texture_filter.h"
#include "gpu/shaders/shared/voxel_shading.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/sky_model.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/cast_batch.h"
#include "voxel/material_gpu.h"
#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

using voxel_gpu::bytesOf;

namespace {

static_assert(LUXEL_VOXEL_MAX_CUTOUTS == kMaxCutoutContinuations);
static_assert(int(TextureFilter::Nearest) == LUXEL_TEXTURE_NEAREST &&
              int(TextureFilter::Trilinear) == LUXEL_TEXTURE_TRILINEAR &&
              int(TextureFilter::Anisotropic) == LUXEL_TEXTURE_ANISOTROPIC);

// Rows per dispatch: keeps every dispatch short on slow devices.
constexpr int kBandRows = 64;

}  // namespace

Status VoxelGpuRenderer::State::sendParams(const shared::VoxelRenderParams& p) {
    const auto data = std::as_bytes(std::span(&p, 1));
    if (std::equal(data.begin(), data.end(), paramsHeld.begin(), paramsHeld.end())) {
        return Ok{};
    }
    paramsHeld.clear();
    if (Status st = send(*params, data, sent.parameters); !st) return st;
    paramsHeld.assign(data.begin(), data.end());
    return Ok{};
}

void VoxelGpuRenderer::State::fillWorld(shared::VoxelRenderParams& p, int stepCap) const {
    p.sizeX = size.x, p.sizeY = size.y, p.sizeZ = size.z;
    p.chunkShift = static_cast<std::uint32_t>(std::countr_zero(static_cast<unsigned>(chunkSize)));
    p.chunksX = chunks.x, p.chunksY = chunks.y, p.chunksZ = chunks.z;
    p.bricksX = (size.x + 3) / 4, p.bricksY = (size.y + 3) / 4, p.bricksZ = (size.z + 3) / 4;
    p.stepCap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
    p.flags = reachCurrent ? LUXEL_VOXEL_REACH_CURRENT : 0u;
}

Status VoxelGpuRenderer::prepareRender(const Camera& camera, const ShadeOptions& options,
                                       bool image) {
    State& s = *state_;
    if (options.materialReflectivity) {
        return Error(
            "the GPU voxel renderer takes reflectivity per texture, not a per-voxel callback");
    }
    const int w = camera.width(), h = camera.height();
    const std::uint64_t outputBytes = static_cast<std::uint64_t>(w) * h * 16;
    if (image) {
        if (Status st = s.context->ensureBuffer(s.output, s.outputBytes, outputBytes); !st) {
            return st.error();
        }
    }

    shared::VoxelRenderParams p{};
    s.fillWorld(p, options.stepCap);
    p.width = w, p.height = h;
    p.textureCount = s.textureCount;
    p.flags |= (options.faceShading ? LUXEL_VOXEL_FACE_SHADING : 0u) |
               (options.shadows ? LUXEL_VOXEL_SHADOWS : 0u) |
               (options.textures ? LUXEL_VOXEL_PROCEDURAL_TEXTURE : 0u) |
               (options.reflectionMode == ShadeOptions::ReflectionMode::EnergyConserving
                    ? LUXEL_VOXEL_ENERGY_CONSERVING
                    : 0u);
    const Vec3d pos = camera.position(), f = camera.forward(), r = camera.right(), u = camera.up();
    p.positionX = float(pos.x), p.positionY = float(pos.y), p.positionZ = float(pos.z);
    // Camera::create's tanHalf_ and rayAt's aspect, rounded to float.
    p.tanHalf = float(std::tan(0.5 * camera.fovYDegrees() * (std::numbers::pi / 180.0)));
    p.aspect = float(static_cast<double>(w) / h);
    p.forwardX = float(f.x), p.forwardY = float(f.y), p.forwardZ = float(f.z);
    p.rightX = float(r.x), p.rightY = float(r.y), p.rightZ = float(r.z);
    p.upX = float(u.x), p.upY = float(u.y), p.upZ = float(u.z);
    p.maxReflections = static_cast<std::uint32_t>(std::max(options.maxReflections, 0));
    p.ambient = options.ambient;
    p.sunX = options.sunDirection.x, p.sunY = options.sunDirection.y,
    p.sunZ = options.sunDirection.z;
    p.reflectivity = options.reflectivity;
    p.skyTopR = options.skyTop.r, p.skyTopG = options.skyTop.g, p.skyTopB = options.skyTop.b;
    p.skyHorizonR = options.skyHorizon.r, p.skyHorizonG = options.skyHorizon.g,
    p.skyHorizonB = options.skyHorizon.b;
    if (options.skyModel == ShadeOptions::SkyModel::Preetham) {
        // The CPU's coefficients (skyColor in shading.cpp evaluates the same floats).
        const PreethamCoefficients c =
            preethamSky(options.skyTurbidity, options.sunDirection, options.skyZenithLuminance);
        p.skyModel = LUXEL_SKY_PREETHAM;
        for (int i = 0; i < 5; ++i) {
            p.skyPerez[i] = c.luminance[i];
            p.skyPerez[5 + i] = c.x[i];
            p.skyPerez[10 + i] = c.y[i];
        }
        for (int i = 0; i < 3; ++i) p.skyZenithOverF0[i] = c.zenithOverF0[i];
    }
    p.textureStrength = options.textureStrength;
    p.textureTexels = static_cast<std::uint32_t>(std::max(options.textureTexels, 1));
    if (options.lighting == ShadeOptions::Lighting::Physical) {
        p.flags |=
            LUXEL_VOXEL_PHYSICAL | (options.refraction ? LUXEL_VOXEL_REFRACTION : 0u) |
            (options.fresnel == ShadeOptions::FresnelModel::Exact ? LUXEL_VOXEL_FRESNEL_EXACT : 0u);
        p.specular = options.specular == ShadeOptions::Specular::Ggx ? LUXEL_VOXEL_SPECULAR_GGX
                     : options.specular == ShadeOptions::Specular::BlinnPhong
                         ? LUXEL_VOXEL_SPECULAR_BLINN_PHONG
                         : LUXEL_VOXEL_SPECULAR_NONE;
        p.sunIrradianceR = options.sunIrradiance.r, p.sunIrradianceG = options.sunIrradiance.g,
        p.sunIrradianceB = options.sunIrradiance.b;
        p.skyAmbient = options.skyAmbient;
        p.skyAmbientRays = static_cast<std::uint32_t>(
            std::clamp(options.skyAmbientRays, 0, LUXEL_SKY_AMBIENT_MAX_RAYS));
        // As shading_physical.cpp: the sun's image in a mirror bounds the GGX alpha.
        p.alphaMin = std::max(0.5f * static_cast<float>(options.sunAngularRadius), 1e-3f);
        p.maxReflections = static_cast<std::uint32_t>(
            std::clamp(options.maxReflections, 0, LUXEL_VOXEL_MAX_DEPTH));
    }
    if (options.lighting == ShadeOptions::Lighting::Physical) {
        p.flags |= options.normalMaps ? LUXEL_VOXEL_NORMAL_MAPS : 0u;
        // Hard is the shadow ray of the pass itself (it sees cutouts, as the CPU's); every other
        // method reads the arrays at 11..14.
        const ShadowMethod method = options.sunVisibility ? options.sunVisibility->settings().method
                                                          : options.shadowSettings.method;
        if (options.shadows && method != ShadowMethod::Hard) {
            if (Status st = s.prepareShadows(options); !st) return st.error();
            p.flags |= LUXEL_VOXEL_SUN_VISIBILITY;
        }
    }
    std::vector<shared::VoxelMaterial> m = gpuMaterials(options.materials);
    if (options.lighting == ShadeOptions::Lighting::Physical && options.emitterLight && image) {
        if (Status st = s.prepareEmitters(options, m); !st) return st.error();
        if (!s.emittersEmpty) p.flags |= LUXEL_VOXEL_EMITTER_LIGHT;
        p.emitterRays =
            static_cast<std::uint32_t>(std::clamp(options.emitterRays, 1, kMaxEmitterRays));
        p.emitterFloor = s.emitterFloor;
    }
    if (!voxel_gpu::sameBytes(m, s.materialsHeld)) {
        s.materialsHeld.clear();
        if (Status st = s.send(*s.materials, bytesOf(m), s.sent.materials); !st) return st.error();
        s.materialsHeld = std::move(m);
    }
    // Anti-aliasing and filtering as render_image.cpp's shadePixel and shading.cpp.
    const int samples = samplesPerPixel(options);
    p.samplesPerPixel = static_cast<std::uint32_t>(samples);
    p.textureFilter = static_cast<std::uint32_t>(options.textureFilter);
    p.maxAnisotropy = static_cast<std::uint32_t>(std::max(options.maxAnisotropy, 1));
    p.coneSpread = static_cast<float>(primaryCone(camera).spread / std::sqrt(double(samples)));
    if (Status st = s.sendParams(p); !st) return st.error();
    return Ok{};
}

Result<std::vector<gpu::Buffer*>> VoxelGpuRenderer::bindings(const Camera& camera,
                                                             const ShadeOptions& options) {
    if (Status st = prepareRender(camera, options, /*image=*/false); !st) return st.error();
    std::vector<gpu::Buffer*> buffers = renderBuffers();
    buffers[6] = state_->params.get();  // no image: the parameters stand in, as at 10
    return buffers;
}

std::vector<gpu::Buffer*> VoxelGpuRenderer::renderBuffers() const {
    const State& s = *state_;
    return {s.params.get(),     s.voxels.get(),    s.chunkSolid.get(), s.textureInfo.get(),
            s.texels.get(),     s.srgb.get(),      s.output.get(),     s.brickMasks.get(),
            s.brickReach.get(), s.materials.get(), s.params.get(),     s.shadow[0].get(),
            s.shadow[1].get(),  s.shadow[2].get(), s.shadow[3].get()};
}

Result<Image> VoxelGpuRenderer::render(const Camera& camera, const ShadeOptions& options,
                                       std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    Stopwatch upload;
    if (Status st = prepareRender(camera, options, /*image=*/true); !st) return st.error();
    const int w = camera.width(), h = camera.height();
    if (timings) timings->push_back({"upload parameters (CPU)", upload.milliseconds()});

    std::vector<gpu::Dispatch> dispatches;
    for (int row = 0; row < h; row += kBandRows) {
        gpu::Dispatch d;
        d.name = "voxel render rows " + std::to_string(row);
        d.program = s.program;
        d.buffers = renderBuffers();
        for (const auto& b : s.emitters) d.buffers.push_back(b.get());
        const int rows = std::min(kBandRows, h - row);
        d.setPush(shared::VoxelBandPush{static_cast<std::uint32_t>(row),
                                        static_cast<std::uint32_t>(rows)});
        d.setThreads(static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(rows));
        dispatches.push_back(std::move(d));
    }
    auto passes = s.context->run(dispatches);
    if (!passes) return passes.error();
    if (timings) {
        double total = 0;
        for (const gpu::PassTiming& t : *passes) total += t.milliseconds;
        timings->push_back({"voxel render (GPU)", total});
    }

    Stopwatch download;
    // The RGBA copy, its staging buffer and the RGB image exist together on the host.
    const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    if (Status st = checkMemory(pixels * (16 + 16 + 12), "downloading a " + std::to_string(w) +
                                                             "x" + std::to_string(h) + " frame");
        !st) {
        return st.error();
    }
    std::vector<float> rgba(static_cast<std::size_t>(w) * h * 4);
    if (Status st = s.context->download(*s.output, std::as_writable_bytes(std::span(rgba))); !st) {
        return st.error();
    }
    Image image(w, h, 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float* px = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            image.setRgb(x, y, {px[0], px[1], px[2]});
        }
    }
    if (timings) timings->push_back({"download image (CPU)", download.milliseconds()});
    return image;
}

Result<std::vector<Hit>> VoxelGpuRenderer::castRays(std::span<const Ray> rays, double tMax,
                                                    int stepCap, ChunkSkip skip,
                                                    std::vector<gpu::PassTiming>* timings) {
    State& s = *state_;
    std::vector<Hit> hits(rays.size());
    if (rays.empty()) return hits;
    const std::vector<shared::VoxelCastRay> in =
        castRaysForGpu(rays, tMax, skip == ChunkSkip::Enabled);
    const std::uint64_t outBytes = rays.size() * sizeof(shared::VoxelCastHit);
    auto rayBuffer = s.context->createBuffer(in.size() * sizeof(shared::VoxelCastRay));
    if (!rayBuffer) return rayBuffer.error();
    auto hitBuffer = s.context->createBuffer(outBytes);
    if (!hitBuffer) return hitBuffer.error();
    shared::VoxelRenderParams p{};
    s.fillWorld(p, stepCap);
    if (Status st = s.sendParams(p); !st) return st.error();
    if (Status st = s.send(**rayBuffer, bytesOf(in), s.sent.rays); !st) return st.error();

    gpu::Dispatch d;
    d.name = "voxel cast rays";
    d.program = s.castProgram;
    d.buffers = {s.params.get(),   s.voxels.get(),     s.chunkSolid.get(), rayBuffer->get(),
                 hitBuffer->get(), s.brickMasks.get(), s.brickReach.get()};
    const std::uint32_t cap = p.stepCap;
    d.setPush(shared::VoxelCastPush{static_cast<std::uint32_t>(rays.size()), cap});
    d.setLinearThreads(rays.size());
    auto out = runCastPass(*s.context, d, **hitBuffer, rays.size(), timings);
    if (!out) return out.error();
    for (std::size_t i = 0; i < out->size(); ++i) hits[i] = hitFromGpu((*out)[i]);
    return hits;
}

}  // namespace luxel::voxel
