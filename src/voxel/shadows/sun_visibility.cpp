// SunVisibility: builds what its method needs and dispatches each query to it.
#include "luxel/voxel/shadows/sun_visibility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "gpu/shaders/shared/soft_shadow.h"
#include "luxel/core/memory.h"
#include "luxel/voxel/shadows/distance_field.h"
#include "luxel/voxel/shadows/light_levels.h"
#include "luxel/voxel/shadows/moment_map.h"
#include "luxel/voxel/shadows/sdf_shadow.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel {
namespace sh = gpu::shared;

const char* shadowMethodName(ShadowMethod method) {
    switch (method) {
        case ShadowMethod::Hard:
            return "hard";
        case ShadowMethod::Exact:
            return "exact";
        case ShadowMethod::Msm:
            return "msm";
        case ShadowMethod::Vsm:
            return "vsm";
        case ShadowMethod::Sdf:
            return "sdf";
        case ShadowMethod::Blend:
            return "blend";
        case ShadowMethod::FloodFill:
            return "flood";
    }
    return "hard";
}

bool parseShadowMethod(const std::string& name, ShadowMethod& method) {
    for (ShadowMethod m :
         {ShadowMethod::Hard, ShadowMethod::Exact, ShadowMethod::Msm, ShadowMethod::Vsm,
          ShadowMethod::Sdf, ShadowMethod::Blend, ShadowMethod::FloodFill}) {
        if (name == shadowMethodName(m)) {
            method = m;
            return true;
        }
    }
    return false;
}

struct SunVisibility::State {
    const VoxelWorld* world = nullptr;
    const TextureSet* textures = nullptr;
    SunLight sun;
    ShadowSettings settings;
    Vec3d l;  // unit, towards the sun
    std::optional<MomentShadowMap> moments;
    std::optional<DistanceField> field;
    std::optional<LightLevels> levels;
};

SunVisibility::SunVisibility(std::unique_ptr<State> state) : state_(std::move(state)) {}
SunVisibility::SunVisibility(SunVisibility&&) noexcept = default;
SunVisibility& SunVisibility::operator=(SunVisibility&&) noexcept = default;
SunVisibility::~SunVisibility() = default;

std::uint64_t estimateSunVisibilityBytes(Int3 worldSize, const ShadowSettings& settings) {
    const ShadowMethod m = settings.method;
    const std::uint64_t voxels = static_cast<std::uint64_t>(std::max(worldSize.x, 0)) *
                                 std::max(worldSize.y, 0) * std::max(worldSize.z, 0);
    std::uint64_t bytes = 0;
    if (m == ShadowMethod::Msm || m == ShadowMethod::Vsm || m == ShadowMethod::Blend) {
        const std::uint64_t texels = static_cast<std::uint64_t>(settings.mapSize) *
                                     static_cast<std::uint64_t>(settings.mapSize);
        bytes += texels * (3 * 16 + 16);  // raw moments, two filter passes, stored words
        if (settings.msmFilter == ShadowSettings::MsmFilter::PenumbraSized) {
            const std::uint64_t side = static_cast<std::uint64_t>(settings.mapSize) + 1;
            bytes += side * side * 32;  // summed-area table of the moments, in double
        }
    }
    if (m == ShadowMethod::Sdf || m == ShadowMethod::Blend) {
        // Solid and empty masks, two squared-distance grids (double) with their nearest-feature
        // indices, the stored distances and feature words.
        bytes += voxels * (2 + 2 * 8 + 2 * 4 + 4 + 4);
    }
    if (m == ShadowMethod::FloodFill) bytes += voxels * (1 + 12);  // levels and the BFS queue
    return bytes;
}

Result<SunVisibility> SunVisibility::build(const VoxelWorld& world, const TextureSet* textures,
                                           const SunLight& sun, const ShadowSettings& settings) {
    const Vec3d d = sun.direction;
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z) || length(d) == 0.0) {
        return Error("sun direction must be finite and non-zero");
    }
    if (!std::isfinite(sun.angularRadius) || sun.angularRadius < 0.0 || sun.angularRadius >= 1.5) {
        return Error("sun angular radius must be in [0, 1.5) radians");
    }
    if (settings.exactSamples < 1 || settings.exactSamples > 1 << 16) {
        return Error("shadow samples must be in 1..65536");
    }
    if (settings.mapSize < 1 || settings.mapSize > 8192) {
        return Error("shadow map size must be in 1..8192");
    }
    if (settings.sdfMaxSteps < 1 || settings.sdfMaxSteps > 4096) {
        return Error("SDF shadow steps must be in 1..4096");
    }
    if (Status fits =
            checkMemory(estimateSunVisibilityBytes(world.size(), settings),
                        std::string("sun visibility '") + shadowMethodName(settings.method) + "'");
        !fits) {
        return fits.error();
    }
    auto state = std::make_unique<State>();
    state->world = &world;
    state->textures = textures;
    state->sun = sun;
    state->settings = settings;
    state->l = normalize(d);
    const ShadowMethod m = settings.method;
    if (m == ShadowMethod::Msm || m == ShadowMethod::Vsm || m == ShadowMethod::Blend) {
        state->moments.emplace(MomentShadowMap::build(world, textures, state->l, settings,
                                                      std::tan(sun.angularRadius)));
    }
    if (m == ShadowMethod::Sdf || m == ShadowMethod::Blend) {
        state->field.emplace(DistanceField::build(world));
    }
    if (m == ShadowMethod::FloodFill) state->levels.emplace(LightLevels::build(world));
    return SunVisibility(std::move(state));
}

namespace {

// A 32-bit hash of a query's position (deterministic jitter for the exact method).
std::uint32_t hashPoint(Vec3d p) {
    std::uint32_t h = 2166136261u;
    for (int a = 0; a < 3; ++a) {
        const auto q = static_cast<std::int64_t>(std::llround(p[a] * 4096.0));
        for (int b = 0; b < 8; ++b)
            h = (h ^ static_cast<std::uint32_t>((q >> (8 * b)) & 0xff)) * 16777619u;
    }
    return h;
}

std::uint32_t nextRandom(std::uint32_t& s) {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
}

// Cone-sampled visibility: the strata of a square grid mapped to the sun's disk by Shirley and
// Chiu's concentric map, one jittered ray each, traced exactly (cutouts let light through).
float exactVisibility(const VoxelWorld& world, const TextureSet* textures, Vec3d l,
                      double angularRadius, int samples, const ShadowQuery& q, Vec3d n) {
    const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(samples))));
    const Vec3d helper = std::abs(l.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
    const Vec3d tu = normalize(cross(helper, l)), tv = cross(l, tu);
    const double w = std::tan(angularRadius);
    std::uint32_t rng = hashPoint(q.point) | 1u;
    int lit = 0;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const double a = 2.0 * (i + (nextRandom(rng) >> 8) * 0x1p-24) / side - 1.0;
            const double b = 2.0 * (j + (nextRandom(rng) >> 8) * 0x1p-24) / side - 1.0;
            double r = 0, phi = 0;
            constexpr double kQuarterPi = 0.78539816339744831;
            if (a == 0 && b == 0) {
            } else if (std::abs(a) > std::abs(b)) {
                r = a, phi = kQuarterPi * (b / a);
            } else {
                r = b, phi = 2.0 * kQuarterPi - kQuarterPi * (a / b);
            }
            const Vec3d dir =
                normalize(l + (tu * (r * std::cos(phi)) + tv * (r * std::sin(phi))) * w);
            if (dot(dir, n) <= 0.0) continue;  // below the face's horizon
            lit += !castToSurface(world, textures, Ray{q.point, dir}).hit.hit;
        }
    }
    return static_cast<float>(lit) / (side * side);
}

}  // namespace

float SunVisibility::visibility(const ShadowQuery& query) const {
    const State& s = *state_;
    const Vec3d n{double(query.normal.x), double(query.normal.y), double(query.normal.z)};
    if (dot(n, s.l) <= 0.0) return 0.0f;
    const ShadowSettings& set = s.settings;
    const Vec3d offset = query.point + n * set.normalOffset;
    auto msm = [&](bool vsm) { return s.moments->visibility(offset, vsm, set); };
    auto sdf = [&] {
        return sdfSunVisibility(*s.field, query.point + n * set.sdfNormalOffset, s.l,
                                std::tan(s.sun.angularRadius), set.sdfMaxSteps,
                                set.sdfDistance == ShadowSettings::SdfDistance::Cubes);
    };
    switch (set.method) {
        case ShadowMethod::Hard:
            return castToSurface(*s.world, s.textures, Ray{query.point, s.l}).hit.hit ? 0.0f : 1.0f;
        case ShadowMethod::Exact:
            return exactVisibility(*s.world, s.textures, s.l, s.sun.angularRadius, set.exactSamples,
                                   query, n);
        case ShadowMethod::Msm:
        case ShadowMethod::Vsm: {
            const MomentShadowMap::Lookup r = msm(set.method == ShadowMethod::Vsm);
            return r.valid ? r.visibility : 1.0f;
        }
        case ShadowMethod::Sdf:
            return sdf().visibility;
        case ShadowMethod::Blend: {
            // Evaluate only what the weight needs (docs: corrected MRMA, cost).
            const float footprint = static_cast<float>(query.footprint);
            const float a0 = sh::mrmaWeight(footprint, float(set.blendNear), float(set.blendFar),
                                            set.sdfNear, true, true);
            MomentShadowMap::Lookup m;
            SdfShadowResult d;
            if (a0 < 1.0f) d = sdf();
            if (a0 > 0.0f || !d.valid) m = msm(false);
            if (a0 <= 0.0f && d.valid) m.valid = true;  // not needed, not evaluated
            if (a0 >= 1.0f) d.valid = true;
            const float a = sh::mrmaWeight(footprint, float(set.blendNear), float(set.blendFar),
                                           set.sdfNear, d.valid, m.valid);
            if (a >= 1.0f && !m.valid) return d.visibility;  // neither valid: the SDF's guess
            return sh::mrmaCombine(m.visibility, d.visibility, a, set.minInBand);
        }
        case ShadowMethod::FloodFill: {
            const Vec3d c = query.point + n * 0.5;
            return float(s.levels->level(int(std::floor(c.x)), int(std::floor(c.y)),
                                         int(std::floor(c.z)))) /
                   LightLevels::kMaxLevel;
        }
    }
    return 1.0f;
}

const SunLight& SunVisibility::sun() const {
    return state_->sun;
}
const ShadowSettings& SunVisibility::settings() const {
    return state_->settings;
}
const MomentShadowMap* SunVisibility::momentMap() const {
    return state_->moments ? &*state_->moments : nullptr;
}
const DistanceField* SunVisibility::distanceField() const {
    return state_->field ? &*state_->field : nullptr;
}
const LightLevels* SunVisibility::lightLevels() const {
    return state_->levels ? &*state_->levels : nullptr;
}
const VoxelWorld& SunVisibility::world() const {
    return *state_->world;
}

}  // namespace luxel::voxel
