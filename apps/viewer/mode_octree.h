// Octree mode: the WebGL octree design's controls over a sparse voxel octree. Drag to orbit a
// target (or, toggled with C, fly with WASD/QE and mouse look), V cycles surface / volume /
// additive, and the panel holds the opacity transfer, shadow, scattering and sun controls. Input
// maps onto OctreeControls; frames come from RendererOctree on the render thread.
#pragma once

#include <memory>
#include <set>

#include "luxel/octree/octree.h"
#include "luxel/scene/octree_scene.h"
#include "octree_controls.h"
#include "render_worker.h"
#include "renderer_octree.h"
#include "viewer_mode.h"

namespace luxel::viewer {

class ModeOctree : public ViewerMode {
  public:
    // `width` x `height`: internal resolution.
    ModeOctree(scene::OctreeScene scene, int width, int height, float exposure,
               std::unique_ptr<OctreeFrameSource> source);

    void handleEvent(const SDL_Event& event, const ViewRect& view) override;
    void update(double seconds) override;
    void drawStats() override;
    void drawPanel() override;
    std::shared_ptr<const Frame> latestFrame(bool* fresh) override;
    bool frameCurrent() override;
    bool frameConverged() override;
    int internalWidth() const override { return width_; }
    int internalHeight() const override { return height_; }
    void setInternalSize(int width, int height) override {
        width_ = width;
        height_ = height;
        controls_.setSize(width, height);
    }
    std::string name() const override { return "octree"; }

  private:
    void handleKey(SDL_Keycode key, bool shift);

    int width_, height_;
    std::string source_;  // what the tree was made from
    octree::OctreeStats stats_;
    Int3 extent_;
    OctreeControls controls_;
    std::set<SDL_Keycode> held_;
    bool dragging_ = false;
    std::uint64_t generation_ = 0;
    RenderWorker<RendererOctree> worker_;
};

}  // namespace luxel::viewer
