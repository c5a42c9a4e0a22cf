// SunVisibility: dispatches a query to the structures its method built.
#include "luxel/voxel/shadows/sun_visibility.h"

#include <cmath>

#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel {

struct SunVisibility::State {
    const VoxelWorld* world = nullptr;
    const TextureSet* textures = nullptr;
    SunLight sun;
    ShadowSettings settings;
};

SunVisibility::SunVisibility(std::unique_ptr<State> state) : state_(std::move(state)) {}
SunVisibility::SunVisibility(SunVisibility&&) noexcept = default;
SunVisibility& SunVisibility::operator=(SunVisibility&&) noexcept = default;
SunVisibility::~SunVisibility() = default;

Result<SunVisibility> SunVisibility::build(const VoxelWorld& world, const TextureSet* textures,
                                           const SunLight& sun, const ShadowSettings& settings) {
    auto state = std::make_unique<State>();
    state->world = &world;
    state->textures = textures;
    state->sun = sun;
    state->settings = settings;
    return SunVisibility(std::move(state));
}

float SunVisibility::visibility(const ShadowQuery& query) const {
    const Vec3d n{double(query.normal.x), double(query.normal.y), double(query.normal.z)};
    const Vec3d l = normalize(state_->sun.direction);
    if (dot(n, l) <= 0.0) return 0.0f;
    const Ray ray{query.point, l};
    return castToSurface(*state_->world, state_->textures, ray).hit.hit ? 0.0f : 1.0f;
}

const SunLight& SunVisibility::sun() const {
    return state_->sun;
}
const ShadowSettings& SunVisibility::settings() const {
    return state_->settings;
}

}  // namespace luxel::voxel
