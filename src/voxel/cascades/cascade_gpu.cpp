// The voxel radiance cascades' lighting passes on the GPU (radiance_cascades_gpu.h): the state's
// codes, corners and bins flattened into the buffers of src/gpu/shaders/shared/
// voxel_cascades_layout.h, and the four dispatches of a pass (the picture:
// cascade_picture_gpu.cpp).
#include <bit>
#include <cmath>
#include <cstring>

#include "../../gpu/shaders/shared/medium_layout.h"
#include "../../gpu/shaders/shared/voxel_cascades_layout.h"
#include "cascade_gpu_state.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/radiance_cascades_gpu.h"

namespace luxel::voxel {

using namespace cascades;
using gpu::shared::RgbTexel;

namespace {

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

RgbTexel texel(Rgb c) {
    return RgbTexel{c.r, c.g, c.b};
}

Result<std::shared_ptr<gpu::Buffer>> uploaded(gpu::Context& context,
                                              std::span<const std::byte> data,
                                              std::uint64_t bytes = 0) {
    auto buffer = context.createBuffer(std::max<std::uint64_t>({bytes, data.size(), 16}));
    if (!buffer) return buffer.error();
    if (!data.empty()) {
        if (Status s = context.upload(**buffer, data); !s) return s.error();
    }
    return *buffer;
}

// The faces' albedo, emitted radiance, direct sun and emitter irradiance sections, and the sky
// means of the levels and the faces.
void packLight(const RadianceCascades::State& state, std::vector<RgbTexel>& light,
               std::vector<RgbTexel>& sky) {
    const FaceData& faces = state.faces;
    const std::size_t count = faces.table.size();
    light.assign(4 * count, RgbTexel{0, 0, 0});
    for (std::size_t f = 0; f < count; ++f) {
        light[f] = texel(faces.albedo[f]);
        light[count + f] = texel(faceEmitted(faces, int(f)));
        light[2 * count + f] = texel(faceDirectSun(state, int(f)));
        light[3 * count + f] = texel(faces.emitterIrradiance[f]);
    }
    sky.clear();
    for (const LevelData& level : state.levels) {
        for (Rgb c : level.sky) sky.push_back(texel(c));
    }
    for (Rgb c : faces.sky) sky.push_back(texel(c));
}

// Each passage as 5 words: face, next code, transmittance (float bits).
std::vector<std::uint32_t> packPassages(const std::vector<Passage>& passages) {
    std::vector<std::uint32_t> words;
    words.reserve(passages.size() * LUXEL_CASCADE_PASSAGE_WORDS);
    for (const Passage& p : passages) {
        const Rgb& t = p.transmittance;
        words.insert(words.end(),
                     {p.face, p.next, std::bit_cast<std::uint32_t>(t.r),
                      std::bit_cast<std::uint32_t>(t.g), std::bit_cast<std::uint32_t>(t.b)});
    }
    return words;
}
static_assert(kPassage == LUXEL_CASCADE_PASSAGE && kMaxPassages == LUXEL_CASCADE_MAX_PASSAGES);
static_assert(sizeof(Passage) == LUXEL_CASCADE_PASSAGE_WORDS * 4);

}  // namespace

RadianceCascadesGpu::RadianceCascadesGpu(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RadianceCascadesGpu::RadianceCascadesGpu(RadianceCascadesGpu&&) noexcept = default;
RadianceCascadesGpu& RadianceCascadesGpu::operator=(RadianceCascadesGpu&&) noexcept = default;
RadianceCascadesGpu::~RadianceCascadesGpu() = default;

Result<RadianceCascadesGpu> RadianceCascadesGpu::create(gpu::Context& context,
                                                        RadianceCascades& cascades) {
    auto impl = std::make_unique<Impl>();
    impl->context = &context;
    impl->state = cascades.state_.get();
    impl->casts = impl->state->casts;
    const RadianceCascades::State& state = *impl->state;
    const FaceData& faces = state.faces;
    const std::size_t faceCount = faces.table.size();

    // The passages through glass and water come first: a passage code's index addresses them
    // (src/gpu/shaders/voxel/cascades_chain.glsl).
    std::vector<std::uint32_t> codes = packPassages(state.passages);
    std::vector<Corners> corners;
    std::vector<float> solidAngle;
    std::uint32_t radiance = 0, means = 0, sky = 0;
    for (std::size_t k = 0; k < state.levels.size(); ++k) {
        const LevelData& level = state.levels[k];
        impl->codeOffset.push_back(std::uint32_t(codes.size()));
        codes.insert(codes.end(), level.codes.begin(), level.codes.end());
        impl->cornerOffset.push_back(std::uint32_t(corners.size()));
        corners.insert(corners.end(), level.corners.begin(), level.corners.end());
        impl->radianceOffset.push_back(radiance);
        radiance += std::uint32_t(level.level.probeCount() * level.bins.count());
        impl->meanOffset.push_back(means);
        if (k > 0) means += std::uint32_t(level.level.probeCount() * level.bins.count() / 4);
        impl->skyOffset.push_back(sky);
        sky += std::uint32_t(level.bins.count());
        impl->solidAngleOffset.push_back(std::uint32_t(solidAngle.size()));
        for (double a : level.bins.solidAngle) solidAngle.push_back(float(a));
    }
    impl->faceSkyOffset = sky;
    impl->faceCornerOffset = std::uint32_t(corners.size());
    const std::uint32_t faceCodeBase = std::uint32_t(codes.size());
    codes.insert(codes.end(), faces.codes.begin(), faces.codes.end());
    corners.insert(corners.end(), faces.corners.begin(), faces.corners.end());
    std::vector<std::uint32_t> faceInfo(2 * faceCount), cosineBins;
    for (std::size_t f = 0; f < faceCount; ++f) {
        faceInfo[2 * f] = faces.table[int(f)].normal;
        faceInfo[2 * f + 1] = faceCodeBase + faces.codeOffset[f];
    }
    gpu::shared::CascadeGatherParams& gather = impl->gatherParams;
    gather.faces = std::uint32_t(faceCount);
    gather.levelBins = std::uint32_t(state.levels.front().bins.count());
    gather.cornerOffset = impl->faceCornerOffset;
    gather.skyOffset = impl->faceSkyOffset;
    for (int n = 0; n < 6; ++n) {
        const auto& seen = faces.bins.cosine[n];
        gather.normalFirst[n] = std::uint32_t(cosineBins.size() / 2);
        gather.normalCount[n] = std::uint32_t(seen.bin.size());
        for (std::size_t i = 0; i < seen.bin.size(); ++i) {
            cosineBins.push_back(std::uint32_t(seen.bin[i]));
            cosineBins.push_back(std::bit_cast<std::uint32_t>(seen.weight[i]));
        }
    }
    static_assert(sizeof(Corners) == 64, "the shaders read 8 probe indices and 8 weights");

    std::vector<RgbTexel> light, skyMeans;
    packLight(state, light, skyMeans);
    for (Rgb e : faces.irradiance) light.push_back(texel(e));  // section 4: the irradiance so far
    const std::uint64_t texelBytes = sizeof(RgbTexel);
    struct Upload {
        std::shared_ptr<gpu::Buffer>* target;
        std::span<const std::byte> data;
        std::uint64_t bytes;
    };
    for (const Upload& u :
         {Upload{&impl->codes, bytesOf(codes), 0}, Upload{&impl->corners, bytesOf(corners), 0},
          Upload{&impl->light, bytesOf(light), 6 * faceCount * texelBytes},
          Upload{&impl->sky, bytesOf(skyMeans), 0},
          Upload{&impl->means, {}, std::uint64_t(means) * texelBytes},
          Upload{&impl->radiance, {}, std::uint64_t(radiance) * texelBytes},
          Upload{&impl->solidAngle, bytesOf(solidAngle), 0},
          Upload{&impl->faceInfo, bytesOf(faceInfo), 0},
          Upload{&impl->cosineBins, bytesOf(cosineBins), 0}}) {
        auto buffer = uploaded(context, u.data, u.bytes);
        if (!buffer) return Error("radiance cascades on the GPU: " + buffer.error().message());
        *u.target = std::move(*buffer);
    }
    using namespace gpu::shared;
    struct Made {
        gpu::Program** target;
        const char* name;
        int buffers, push;
    };
    for (const Made& m :
         {Made{&impl->outgoing, "cascades_outgoing", 1, sizeof(CascadeOutgoingParams)},
          Made{&impl->merge, "cascades_merge", 6, sizeof(CascadeMergeParams)},
          Made{&impl->childMean, "cascades_child_mean", 3, sizeof(CascadeChildMeanParams)},
          Made{&impl->gather, "cascades_gather", 7, sizeof(CascadeGatherParams)}}) {
        auto program = context.program(m.name, m.buffers, m.push);
        if (!program) return program.error();
        *m.target = *program;
    }
    return RadianceCascadesGpu(std::move(impl));
}

namespace {

// The device's copy is stale once setLight built the faces and segments again (new glass
// materials or refraction): its tables no longer match the CPU object's.
Status checkCurrent(const RadianceCascadesGpu::Impl& impl) {
    if (impl.state->casts == impl.casts) return Ok{};
    return Error(
        "radiance cascades on the GPU: the glass's materials changed, so the faces and "
        "segments were built again; create the GPU passes again");
}

}  // namespace

Status RadianceCascadesGpu::uploadLight() {
    if (Status s = checkCurrent(*impl_); !s) return s;
    std::vector<RgbTexel> light, sky;
    packLight(*impl_->state, light, sky);
    if (Status s = impl_->context->upload(*impl_->light, bytesOf(light)); !s) return s;
    return impl_->context->upload(*impl_->sky, bytesOf(sky));
}

Result<double> RadianceCascadesGpu::iterate(int passes) {
    using namespace gpu::shared;
    if (Status s = checkCurrent(*impl_); !s) return s.error();
    Impl& g = *impl_;
    const RadianceCascades::State& state = *g.state;
    const std::uint32_t faceCount = std::uint32_t(state.faces.table.size());
    std::vector<gpu::Dispatch> dispatches;
    for (int pass = 0; pass < passes; ++pass) {
        gpu::Dispatch out{"cascades_outgoing", g.outgoing, {g.light.get()}, {}, {0, 0, 0}};
        out.setPush(CascadeOutgoingParams{faceCount, 0, 0, 0});
        out.setLinearThreads(faceCount);
        dispatches.push_back(out);
        for (std::size_t k = state.levels.size(); k-- > 0;) {
            const LevelData& level = state.levels[k];
            const std::uint32_t probes = std::uint32_t(level.level.probeCount());
            const std::uint32_t bins = std::uint32_t(level.bins.count());
            const bool top = level.level.top;
            CascadeMergeParams merge{probes,
                                     bins,
                                     top ? 1u : 0u,
                                     faceCount,
                                     g.codeOffset[k],
                                     top ? 0u : g.cornerOffset[k],
                                     g.radianceOffset[k],
                                     top ? 0u : g.meanOffset[k + 1],
                                     g.skyOffset[k],
                                     0,
                                     0,
                                     0};
            gpu::Dispatch m{"cascades_merge",
                            g.merge,
                            {g.codes.get(), g.corners.get(), g.light.get(), g.sky.get(),
                             g.means.get(), g.radiance.get()},
                            {},
                            {0, 0, 0}};
            m.setPush(merge);
            m.setLinearThreads(std::uint64_t(probes) * bins);
            dispatches.push_back(m);
            if (k == 0) continue;
            CascadeChildMeanParams mean{probes,
                                        std::uint32_t(level.bins.side),
                                        g.radianceOffset[k],
                                        g.meanOffset[k],
                                        g.solidAngleOffset[k],
                                        0,
                                        0,
                                        0};
            gpu::Dispatch c{"cascades_child_mean",
                            g.childMean,
                            {g.radiance.get(), g.solidAngle.get(), g.means.get()},
                            {},
                            {0, 0, 0}};
            c.setPush(mean);
            c.setLinearThreads(std::uint64_t(probes) * bins / 4);
            dispatches.push_back(c);
        }
        gpu::Dispatch gather{"cascades_gather",
                             g.gather,
                             {g.codes.get(), g.corners.get(), g.light.get(), g.sky.get(),
                              g.radiance.get(), g.faceInfo.get(), g.cosineBins.get()},
                             {},
                             {0, 0, 0}};
        gather.setPush(g.gatherParams);
        gather.setLinearThreads(faceCount);
        dispatches.push_back(gather);
    }
    auto timings = g.context->run(dispatches);
    if (!timings) return timings.error();
    g.state->stats.bounces += passes;
    double last = 0.0;
    const std::size_t perPass = dispatches.size() / std::size_t(std::max(passes, 1));
    for (std::size_t i = timings->size() - std::min(timings->size(), perPass); i < timings->size();
         ++i) {
        last += (*timings)[i].milliseconds;
    }
    return last;
}

Status RadianceCascadesGpu::download() {
    if (Status s = checkCurrent(*impl_); !s) return s;
    const std::size_t count = impl_->state->faces.table.size();
    std::vector<RgbTexel> light(6 * count);
    if (Status s =
            impl_->context->download(*impl_->light, std::as_writable_bytes(std::span(light)));
        !s) {
        return s;
    }
    std::vector<Rgb>& irradiance = impl_->state->faces.irradiance;
    for (std::size_t f = 0; f < count; ++f) {
        const RgbTexel& t = light[4 * count + f];
        irradiance[f] = Rgb(t.r, t.g, t.b);
    }
    return Ok{};
}

Result<double> RadianceCascadesGpu::iterateOnce() {
    const std::vector<Rgb> before = impl_->state->faces.irradiance;
    auto ran = iterate(1);
    if (!ran) return ran.error();
    if (Status s = download(); !s) return s.error();
    return relativeChange(before, impl_->state->faces.irradiance);
}

Result<int> RadianceCascadesGpu::solve() {
    const CascadeOptions& options = impl_->state->options;
    const int limit = options.bounces > 0 ? options.bounces : kMaxCascadeBounces;
    std::vector<Rgb> before = impl_->state->faces.irradiance;
    int passes = 0;
    while (passes < limit) {
        auto ran = iterate(1);
        if (!ran) return ran.error();
        ++passes;
        if (options.bounces > 0 && passes < limit) continue;
        if (Status s = download(); !s) return s.error();
        if (options.bounces > 0) break;
        const std::vector<Rgb>& after = impl_->state->faces.irradiance;
        if (relativeChange(before, after) < options.tolerance) break;
        before = after;
    }
    return passes;
}

}  // namespace luxel::voxel
