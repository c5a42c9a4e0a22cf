// Octree mode's state changes, clamped to what validateRenderOptions accepts.
#include "octree_controls.h"

#include <algorithm>
#include <cmath>

namespace luxel::viewer {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;
constexpr int kSoftShadowSamples = 4;

}  // namespace

OctreeControls::OctreeControls(const voxel::Camera& sceneCamera, Int3 extent,
                               const octree::OctreeRenderOptions& render, int width, int height,
                               float exposure)
    : sceneCamera_(sceneCamera),
      extent_(extent),
      camera_(sceneCamera, orbitTarget(sceneCamera, extent)) {
    state_.width = width;
    state_.height = height;
    state_.render = render;
    state_.exposure = exposure;
    const Vec3 s = render.sunDirection;
    const double length = std::sqrt(double(s.x) * s.x + double(s.y) * s.y + double(s.z) * s.z);
    if (length > 0) {
        sunAzimuth_ = std::atan2(s.x, s.z) / kDegrees;
        sunElevation_ = std::asin(std::clamp(s.y / length, -1.0, 1.0)) / kDegrees;
    }
}

void OctreeControls::apply(OctreeAction action) {
    octree::OctreeRenderOptions& o = state_.render;
    switch (action) {
        case OctreeAction::ToggleCamera:
            setOrbiting(!camera_.orbiting());
            break;
        case OctreeAction::CycleMode:
            setMode(o.mode == octree::OctreeMode::Surface    ? octree::OctreeMode::Volume
                    : o.mode == octree::OctreeMode::Volume   ? octree::OctreeMode::Additive
                    : o.mode == octree::OctreeMode::Additive ? octree::OctreeMode::Tiles
                                                             : octree::OctreeMode::Surface);
            break;
        case OctreeAction::ToggleShadows:
            setShadows(!o.shadows);
            break;
        case OctreeAction::ToggleScattering:
            setScattering(!o.scattering);
            break;
        case OctreeAction::OpacityUp:
            setOpacityScale(o.opacityScale * std::sqrt(2.0f));
            break;
        case OctreeAction::OpacityDown:
            setOpacityScale(o.opacityScale / std::sqrt(2.0f));
            break;
        case OctreeAction::ThresholdUp:
            setThreshold(o.threshold + 8);
            break;
        case OctreeAction::ThresholdDown:
            setThreshold(o.threshold - 8);
            break;
        case OctreeAction::SunAzimuthDown:
            setSun(sunAzimuth_ - 15.0, sunElevation_);
            break;
        case OctreeAction::SunAzimuthUp:
            setSun(sunAzimuth_ + 15.0, sunElevation_);
            break;
        case OctreeAction::SunElevationUp:
            setSun(sunAzimuth_, sunElevation_ + 10.0);
            break;
        case OctreeAction::SunElevationDown:
            setSun(sunAzimuth_, sunElevation_ - 10.0);
            break;
        case OctreeAction::ExposureDown:
            setExposure(state_.exposure - 0.5f);
            break;
        case OctreeAction::ExposureUp:
            setExposure(state_.exposure + 0.5f);
            break;
        case OctreeAction::ResetView: {
            const bool orbit = camera_.orbiting();
            camera_ = OrbitFlyCamera(sceneCamera_, orbitTarget(sceneCamera_, extent_));
            camera_.setOrbiting(orbit);
            changed();
            break;
        }
    }
}

void OctreeControls::drag(double dx, double dy) {
    if (dx == 0 && dy == 0) return;
    if (camera_.orbiting()) {
        camera_.orbitDrag(dx, dy);
    } else {
        camera_.look(dx, dy);
    }
    changed();
}

void OctreeControls::zoom(double notches) {
    camera_.zoom(notches);
    changed();
}

void OctreeControls::travel(double forward, double right, double up) {
    camera_.move(camera_.forward() * forward + camera_.right() * right + Vec3d{0, up, 0});
    changed();
}

void OctreeControls::turn(double yawDegrees, double pitchDegrees) {
    camera_.turn(yawDegrees, pitchDegrees);
    changed();
}

void OctreeControls::setOrbiting(bool orbit) {
    camera_.setOrbiting(orbit);
    changed();
}

void OctreeControls::orbitVolumeCentre() {
    camera_.setTarget({extent_.x * 0.5, extent_.y * 0.5, extent_.z * 0.5});
    camera_.setOrbiting(true);
    changed();
}

void OctreeControls::setMode(octree::OctreeMode mode) {
    state_.render.mode = mode;
    changed();
}

void OctreeControls::setOpacityScale(float scale) {
    if (!std::isfinite(scale)) return;
    state_.render.opacityScale = std::clamp(scale, kMinOpacityScale, kMaxOpacityScale);
    changed();
}

void OctreeControls::setThreshold(int threshold) {
    state_.render.threshold = static_cast<std::uint8_t>(std::clamp(threshold, 1, 255));
    changed();
}

void OctreeControls::setOpacityWindow(int low, int high) {
    low = std::clamp(low, 0, 254);
    high = std::clamp(high, 1, 255);
    if (high <= low) {
        if (low != state_.render.windowLow)
            high = low + 1;  // the low end moved up
        else
            low = high - 1;  // the high end moved down
    }
    state_.render.windowLow = static_cast<std::uint8_t>(low);
    state_.render.windowHigh = static_cast<std::uint8_t>(high);
    changed();
}

void OctreeControls::setShadows(bool on) {
    state_.render.shadows = on;
    changed();
}

void OctreeControls::setSunRadius(float degrees) {
    if (!std::isfinite(degrees)) return;
    octree::OctreeRenderOptions& o = state_.render;
    o.sunRadiusDegrees = std::clamp(degrees, 0.0f, kMaxSunRadius);
    // One sample is a hard shadow whatever the radius (octree_render.h): a visible radius needs
    // several.
    if (o.sunRadiusDegrees > 0 && o.shadowSamples < kSoftShadowSamples) {
        o.shadowSamples = kSoftShadowSamples;
    }
    changed();
}

void OctreeControls::setScattering(bool on) {
    state_.render.scattering = on;
    changed();
}

void OctreeControls::setAlbedo(float albedo) {
    if (!std::isfinite(albedo)) return;
    state_.render.albedo = std::clamp(albedo, 0.0f, 1.0f);
    changed();
}

void OctreeControls::setPhaseG(float g) {
    if (!std::isfinite(g)) return;
    state_.render.phaseG = std::clamp(g, -kMaxPhaseG, kMaxPhaseG);
    changed();
}

void OctreeControls::setSun(double azimuthDegrees, double elevationDegrees) {
    if (!std::isfinite(azimuthDegrees) || !std::isfinite(elevationDegrees)) return;
    sunAzimuth_ = std::fmod(std::fmod(azimuthDegrees + 180.0, 360.0) + 360.0, 360.0) - 180.0;
    sunElevation_ = std::clamp(elevationDegrees, -90.0, 90.0);
    const Vec3d d = viewDirection(sunAzimuth_, sunElevation_);
    state_.render.sunDirection =
        Vec3{static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)};
    changed();
}

void OctreeControls::setSize(int width, int height) {
    state_.width = width;
    state_.height = height;
    changed();
}

void OctreeControls::setExposure(float stops) {
    if (!std::isfinite(stops)) return;
    state_.exposure = std::clamp(stops, -10.0f, 10.0f);
    changed();
}

OctreeViewState OctreeControls::state() const {
    OctreeViewState s = state_;
    s.position = camera_.position();
    s.yawDegrees = camera_.yawDegrees();
    s.pitchDegrees = camera_.pitchDegrees();
    s.fovYDegrees = camera_.fovYDegrees();
    return s;
}

bool OctreeControls::takeChanged() {
    const bool was = changed_;
    changed_ = false;
    return was;
}

}  // namespace luxel::viewer
