// Voxel mode: fly camera (mouse look with the right button, WASD/QE), the solver (ray caster, sky
// visibility, progressive path tracer; C cycles), reflection count, shading toggles, sun
// direction, click-to-edit (left removes, Shift+left adds) and saving the edited world as .vox
// (Ctrl+S or the panel's button).
#pragma once

#include <set>

#include "luxel/voxel/voxel_scene.h"
#include "render_worker.h"
#include "renderer_voxel.h"
#include "viewer_mode.h"
#include "voxel_controls.h"

namespace luxel::viewer {

class ModeVoxel : public ViewerMode {
  public:
    // `width` x `height`: internal resolution; `savePath`: where Ctrl+S writes the world;
    // `solver`: the starting solver and its settings.
    ModeVoxel(voxel::VoxelScene scene, int width, int height, float exposure,
              std::unique_ptr<VoxelFrameSource> source, std::string savePath,
              const VoxelSolverOptions& solver = {});

    void handleEvent(const SDL_Event& event, const ViewRect& view) override;
    void update(double seconds) override;
    void drawPanel() override;
    void drawStats() override;
    std::shared_ptr<const Frame> latestFrame(bool* fresh) override;
    bool frameCurrent() override;
    // Current, and the path tracer has reached its target.
    bool frameConverged() override;
    int internalWidth() const override { return state_.width; }
    int internalHeight() const override { return state_.height; }
    void setInternalSize(int width, int height) override {
        state_.width = width;
        state_.height = height;
        changed();
    }
    std::string name() const override { return "voxel"; }

  private:
    // Something that changes the light: the next state restarts the path tracer.
    void changed() { dirty_ = restart_ = true; }
    void handleKey(SDL_Keycode key, bool shift, bool ctrl);
    void save();
    void move(Vec3d direction, double distance);
    void setSun(double azimuthDegrees, double elevationDegrees);
    void drawSurfacePanel();  // lighting, shadows, surfaces, bloom, upscaling

    VoxelState state_;
    Int3 worldSize_;
    double sunAzimuth_ = 0, sunElevation_ = 45, sunLength_ = 1;
    float editColour_[3] = {0.9f, 0.35f, 0.2f};
    std::set<SDL_Keycode> held_;
    bool looking_ = false;
    std::uint64_t generation_ = 0;
    bool dirty_ = true;
    bool restart_ = true;  // since the last post, more changed than exposure or the target
    VoxelSaver saver_;     // before worker_: it copies the world the worker takes
    RenderWorker<RendererVoxel> worker_;
};

}  // namespace luxel::viewer
