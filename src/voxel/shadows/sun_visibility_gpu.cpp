// SunVisibilityGpu: upload of a SunVisibility's arrays and the batch visibility pass.
#include "luxel/voxel/shadows/sun_visibility_gpu.h"

#include <bit>
#include <cmath>

#include "luxel/gpu/context.h"
#include "luxel/voxel/shadows/distance_field.h"
#include "luxel/voxel/shadows/light_levels.h"
#include "luxel/voxel/shadows/moment_map.h"
#include "voxel/shadows/shadow_upload.h"

namespace luxel::voxel {
namespace shared = gpu::shared;

Result<ShadowUpload> shadowUploadOf(const SunVisibility& v) {
    const ShadowSettings& s = v.settings();
    if (s.method == ShadowMethod::Exact) {
        return Error("exact sun visibility has no GPU twin (it traces the world per sample)");
    }
    if (usesPenumbraMsm(s)) return Error(kPenumbraMsmGpuError);
    ShadowUpload u;
    shared::ShadowParams& p = u.params;
    const Vec3d l = normalize(v.sun().direction);
    p.lightX = float(l.x), p.lightY = float(l.y), p.lightZ = float(l.z);
    p.tanRadius = float(std::tan(v.sun().angularRadius));
    const Int3 size = v.world().size();
    p.sizeX = size.x, p.sizeY = size.y, p.sizeZ = size.z;
    p.depthBias = float(s.depthBias);
    p.momentBias = momentBiasOf(s);
    p.lightBleed = float(s.lightBleedReduction);
    p.normalOffset = float(s.normalOffset);
    p.sdfNormalOffset = float(s.sdfNormalOffset);
    p.blendNear = float(s.blendNear), p.blendFar = float(s.blendFar);
    p.method = static_cast<shared::uint>(s.method);
    p.sdfMaxSteps = static_cast<shared::uint>(s.sdfMaxSteps);
    p.flags = (s.sdfNear ? LUXEL_SHADOW_SDF_NEAR : 0u) |
              (s.minInBand ? LUXEL_SHADOW_MIN_IN_BAND : 0u) |
              (s.sdfDistance == ShadowSettings::SdfDistance::Cubes ? LUXEL_SHADOW_SDF_CUBES : 0u);
    p.mapSize = 1;
    if (const MomentShadowMap* m = v.momentMap()) {
        const LightFrame& f = m->frame();
        p.uX = float(f.u.x), p.uY = float(f.u.y), p.uZ = float(f.u.z), p.uMin = float(f.uMin);
        p.vX = float(f.v.x), p.vY = float(f.v.y), p.vZ = float(f.v.z), p.vMin = float(f.vMin);
        p.texel = float(f.texel), p.depthTop = float(f.top), p.depthRange = float(f.range);
        p.mapSize = f.size;
        p.flags |= m->quantized() ? LUXEL_SHADOW_QUANTIZED : 0u;
        u.moments = m->words();
    }
    // Values, then the feature words as float bits (shadow_layout.h).
    auto fieldWords = [&](const DistanceField& d) {
        u.field = d.values();
        for (std::uint32_t w : d.features()) u.field.push_back(std::bit_cast<float>(w));
    };
    if (const DistanceField* d = v.distanceField()) {
        fieldWords(*d);
    } else if (s.method == ShadowMethod::Hard) {
        fieldWords(DistanceField::build(v.world()));
    }
    if (const LightLevels* lv = v.lightLevels()) {
        const std::vector<std::uint8_t>& b = lv->levels();
        u.levels.assign((b.size() + 3) / 4, 0u);
        for (std::size_t i = 0; i < b.size(); ++i)
            u.levels[i >> 2] |= std::uint32_t(b[i]) << (8 * (i & 3));
    }
    if (u.moments.empty()) u.moments.push_back(0);
    if (u.field.empty()) u.field.push_back(0.0f);
    if (u.levels.empty()) u.levels.push_back(0);
    return u;
}

struct SunVisibilityGpu::State {
    gpu::Context* context = nullptr;
    gpu::Program* program = nullptr;
    std::shared_ptr<gpu::Buffer> params, moments, field, levels;
};

SunVisibilityGpu::SunVisibilityGpu(std::unique_ptr<State> state) : state_(std::move(state)) {}
SunVisibilityGpu::SunVisibilityGpu(SunVisibilityGpu&&) noexcept = default;
SunVisibilityGpu& SunVisibilityGpu::operator=(SunVisibilityGpu&&) noexcept = default;
SunVisibilityGpu::~SunVisibilityGpu() = default;

namespace {

template <typename T>
Result<std::shared_ptr<gpu::Buffer>> uploaded(gpu::Context& context, const std::vector<T>& data) {
    auto b = context.createBuffer(data.size() * sizeof(T));
    if (!b) return b.error();
    if (Status s = context.upload(**b, std::as_bytes(std::span(data))); !s) return s.error();
    return *b;
}

}  // namespace

Result<SunVisibilityGpu> SunVisibilityGpu::create(gpu::Context& context,
                                                  const SunVisibility& visibility) {
    auto upload = shadowUploadOf(visibility);
    if (!upload) return upload.error();
    auto state = std::make_unique<State>();
    state->context = &context;
    auto program = context.program("shadow_visibility", 6, sizeof(shared::ShadowBatchPush));
    if (!program) return program.error();
    state->program = *program;
    const std::vector<shared::ShadowParams> params{upload->params};
    auto p = uploaded(context, params);
    if (!p) return p.error();
    auto m = uploaded(context, upload->moments);
    if (!m) return m.error();
    auto f = uploaded(context, upload->field);
    if (!f) return f.error();
    auto l = uploaded(context, upload->levels);
    if (!l) return l.error();
    state->params = *p, state->moments = *m, state->field = *f, state->levels = *l;
    return SunVisibilityGpu(std::move(state));
}

std::array<gpu::Buffer*, 4> SunVisibilityGpu::buffers() const {
    return {state_->params.get(), state_->moments.get(), state_->field.get(), state_->levels.get()};
}

Result<std::vector<float>> SunVisibilityGpu::evaluate(std::span<const ShadowQuery> queries,
                                                      std::vector<gpu::PassTiming>* timings) {
    std::vector<float> out(queries.size());
    if (queries.empty()) return out;
    State& s = *state_;
    std::vector<shared::ShadowQueryGpu> in(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const ShadowQuery& q = queries[i];
        in[i] = {float(q.point.x), float(q.point.y), float(q.point.z), float(q.footprint),
                 q.normal.x,       q.normal.y,       q.normal.z,       0};
    }
    auto qb = uploaded(*s.context, in);
    if (!qb) return qb.error();
    auto ob = s.context->createBuffer(out.size() * sizeof(float));
    if (!ob) return ob.error();
    gpu::Dispatch d;
    d.name = "sun visibility";
    d.program = s.program;
    d.buffers = {s.params.get(), s.moments.get(), s.field.get(),
                 s.levels.get(), qb->get(),       ob->get()};
    d.setPush(shared::ShadowBatchPush{static_cast<shared::uint>(queries.size())});
    d.setLinearThreads(queries.size());
    auto passes = s.context->run(std::span(&d, 1));
    if (!passes) return passes.error();
    if (timings) timings->insert(timings->end(), passes->begin(), passes->end());
    if (Status st = s.context->download(**ob, std::as_writable_bytes(std::span(out))); !st) {
        return st.error();
    }
    return out;
}

}  // namespace luxel::voxel
