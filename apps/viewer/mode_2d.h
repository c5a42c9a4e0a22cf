// 2D mode: the raylib radiance-cascades demo's controls (drag the light, SPACE probes, R GI, C
// cascade, Up/Down intensity, 1-5 colour), solver/backend/exposure switches, and paint mode with
// save to JSON.
#pragma once

#include <memory>
#include <string>

#include "luxel/gi2d/scene2d.h"
#include "paint_tool.h"
#include "render_worker.h"
#include "renderer_2d.h"
#include "viewer_mode.h"

namespace luxel::viewer {

struct Mode2DSettings {
    View2D view;
    std::string savePath;  // Ctrl+S writes the scene here
};

class Mode2D : public ViewerMode {
  public:
    Mode2D(gi2d::Scene2D scene, Mode2DSettings settings);

    void handleEvent(const SDL_Event& event, const ViewRect& view) override;
    void update(double seconds) override;
    void drawPanel() override;
    void drawStats() override;
    void drawOverFrame() override;
    bool takePanelRequest() override {
        const bool wanted = panelRequest_;
        panelRequest_ = false;
        return wanted;
    }
    std::shared_ptr<const Frame> latestFrame(bool* fresh) override;
    bool frameCurrent() override;
    bool frameConverged() override;
    int internalWidth() const override { return view_.width; }
    int internalHeight() const override { return view_.height; }
    void setInternalSize(int width, int height) override {
        view_.width = width;
        view_.height = height;
        viewChanged();
    }
    std::string name() const override { return "2D"; }

    // Writes the scene as JSON to the save path; the result is shown in the panel.
    Status save();

  private:
    void handleKey(const SDL_KeyboardEvent& key);
    Vec2d toScene(double wx, double wy, const ViewRect& view) const;
    void sceneChanged() {
        ++sceneVersion_;
        dirty_ = true;
    }
    void viewChanged() { dirty_ = true; }
    gi2d::Shape* light();

    gi2d::Scene2D scene_;
    View2D view_;
    std::string savePath_, saveMessage_;
    int lightIndex_ = -1;  // the shape Up/Down/1-5 and empty-space drags act on
    int dragIndex_ = -1;   // shape being dragged, -1 when none
    Vec2d dragLast_;
    bool paintMode_ = false;
    bool panelRequest_ = false;  // paint mode was switched on: show its controls
    Vec2d pointer_{-1, -1};      // last pointer position, window pixels
    ViewRect lastView_;          // where the frame was drawn at the last input
    Brush brush_;
    PaintTool paint_;
    std::uint64_t sceneVersion_ = 1, generation_ = 0;
    bool dirty_ = true;  // state changed since the last post
    RenderWorker<Renderer2D> worker_;
};

}  // namespace luxel::viewer
