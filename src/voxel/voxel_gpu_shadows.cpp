// VoxelGpuRenderer's sun visibility arrays (bindings 11..14): built on the CPU as render() does,
// uploaded once and kept until the sun, its radius, the settings or the world change.
#include <optional>
#include <string>

#include "luxel/core/memory.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

Status VoxelGpuRenderer::State::setShadowArrays(const ShadowUpload& u) {
    auto p = uploaded(std::vector<shared::ShadowParams>{u.params});
    if (!p) return p.error();
    auto m = uploaded(u.moments);
    if (!m) return m.error();
    auto f = uploaded(u.field);
    if (!f) return f.error();
    auto l = uploaded(u.levels);
    if (!l) return l.error();
    shadow = {*p, *m, *f, *l};
    shadowBytes = sizeof(shared::ShadowParams) + u.moments.size() * 4 + u.field.size() * 4 +
                  u.levels.size() * 4;
    return Ok{};
}

Status VoxelGpuRenderer::State::prepareShadows(const ShadeOptions& options) {
    voxel_gpu::ShadowKey key;
    key.given = options.sunVisibility;
    if (key.given) {
        key.direction = key.given->sun().direction;
        key.angularRadius = key.given->sun().angularRadius;
        key.settings = key.given->settings();
    } else {
        key.direction = {options.sunDirection.x, options.sunDirection.y, options.sunDirection.z};
        key.angularRadius = options.sunAngularRadius;
        key.settings = options.shadowSettings;
    }
    if (shadowKey && shadowKey->matches(key)) return Ok{};
    if (key.settings.method == ShadowMethod::Exact) {
        return Error(
            "sun visibility 'exact' (render.shadows, --shadows) has no GPU twin: it traces "
            "the world per light sample; render it on the CPU or use msm, vsm, sdf, blend, "
            "flood or hard");
    }
    if (usesPenumbraMsm(key.settings)) return Error(kPenumbraMsmGpuError);
    if (key.given && key.given->world().size() != size) {
        return Error("options.sunVisibility was built for another world");
    }
    const std::uint64_t needed = estimateVoxelShadowGpuMemory(size, key.settings);
    if (limit > 0 && bytes + outputBytes + needed > limit) {
        return Error(std::string("sun visibility '") + shadowMethodName(key.settings.method) +
                     "' needs " + formatBytes(needed) + " of device memory more, " +
                     formatBytes(limit) + " in all are available");
    }
    std::optional<SunVisibility> built;
    const SunVisibility* visibility = key.given;
    if (!visibility) {
        auto b = SunVisibility::build(*sourceWorld, sourceTextures,
                                      {key.direction, key.angularRadius}, key.settings);
        if (!b) return b.error();
        built.emplace(std::move(*b));
        visibility = &*built;
    }
    auto upload = shadowUploadOf(*visibility);
    if (!upload) return upload.error();
    if (Status st = setShadowArrays(*upload); !st) return st;
    shadowKey = key;
    return Ok{};
}

}  // namespace luxel::voxel
