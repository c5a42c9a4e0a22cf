// What octree mode's keys, mouse and panel change: the orbit/fly camera and the render options
// (mode and opacity transfer, shadows, scattering, sun). Display-free: the mode maps SDL input and
// ImGui widgets onto these calls, and tests drive them directly.
#pragma once

#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"
#include "octree_camera.h"

namespace luxel::viewer {

// What the render thread draws (a cheap copy; see RenderWorker).
struct OctreeViewState {
    Vec3d position;
    double yawDegrees = 0, pitchDegrees = 0, fovYDegrees = 60;
    int width = 240, height = 135;  // internal resolution
    octree::OctreeRenderOptions render;
    float exposure = 0.0f;
};

// Discrete input: one key press each.
enum class OctreeAction {
    ToggleCamera,  // orbit <-> fly
    CycleMode,     // surface -> volume -> additive
    ToggleShadows,
    ToggleScattering,
    OpacityUp,  // opacity scale x sqrt(2) / sqrt(2)
    OpacityDown,
    ThresholdUp,  // surface threshold +/- 8
    ThresholdDown,
    SunAzimuthDown,  // 15 degrees
    SunAzimuthUp,
    SunElevationUp,  // 10 degrees
    SunElevationDown,
    ExposureDown,  // half a stop
    ExposureUp,
    ResetView,  // the scene's camera, orbiting its target
};

// Slider ranges, shared by the panel and the clamps.
inline constexpr float kMinOpacityScale = 1.0f / 1024.0f;
inline constexpr float kMaxOpacityScale = 64.0f;
inline constexpr float kMaxSunRadius = 45.0f;  // degrees, as validateRenderOptions
inline constexpr float kMaxPhaseG = 0.95f;

class OctreeControls {
  public:
    // `extent`: the octree's content box, whose centre the orbit target is chosen by.
    OctreeControls(const voxel::Camera& sceneCamera, Int3 extent,
                   const octree::OctreeRenderOptions& render, int width, int height,
                   float exposure);

    void apply(OctreeAction action);
    // A drag of (dx, dy) window pixels: orbits the target, or (fly) looks around.
    void drag(double dx, double dy);
    void zoom(double notches);
    // Fly, or move the orbit target: voxels along the view's forward and right, and world up.
    void travel(double forward, double right, double up);
    void turn(double yawDegrees, double pitchDegrees);
    void setOrbiting(bool orbit);
    void orbitVolumeCentre();

    void setMode(octree::OctreeMode mode);
    void setOpacityScale(float scale);  // clamped to [kMinOpacityScale, kMaxOpacityScale]
    void setThreshold(int threshold);   // clamped to 1..255
    // The opacity transfer window, clamped to 0..255 with low < high (the other end moves).
    void setOpacityWindow(int low, int high);
    void setShadows(bool on);
    void setSunRadius(float degrees);  // 0 hard; above, soft over at least 4 samples
    void setScattering(bool on);
    void setAlbedo(float albedo);  // clamped to [0, 1]
    void setPhaseG(float g);       // clamped to [-kMaxPhaseG, kMaxPhaseG]
    void setSun(double azimuthDegrees, double elevationDegrees);
    void setExposure(float stops);
    void setSize(int width, int height);  // internal resolution

    const OrbitFlyCamera& camera() const { return camera_; }
    const octree::OctreeRenderOptions& options() const { return state_.render; }
    double sunAzimuth() const { return sunAzimuth_; }
    double sunElevation() const { return sunElevation_; }
    float exposure() const { return state_.exposure; }
    OctreeViewState state() const;

    // Whether anything changed since the last call (then the mode posts a new state).
    bool takeChanged();

  private:
    void changed() { changed_ = true; }

    voxel::Camera sceneCamera_;
    Int3 extent_;
    OrbitFlyCamera camera_;
    OctreeViewState state_;  // camera fields filled in by state()
    double sunAzimuth_ = 0, sunElevation_ = 45;
    bool changed_ = true;
};

}  // namespace luxel::viewer
