// The seam between the window (app.cpp) and what it shows: a 2D scene or a voxel world. A mode
// turns input into state changes, posts them to its render thread and hands back finished frames.
#pragma once

#include <SDL.h>

#include <cstdint>
#include <memory>
#include <string>

#include "frame.h"
#include "luxel/core/vec.h"

struct ImDrawList;

namespace luxel::viewer {

// Where the frame is drawn in the window (aspect-fit, centred), for mapping the mouse.
struct ViewRect {
    double x = 0, y = 0, width = 1, height = 1;  // window pixels
    // Window position -> [0, 1]^2 over the frame (may lie outside for points off the picture).
    Vec2d toUnit(double wx, double wy) const { return {(wx - x) / width, (wy - y) / height}; }
};

class ViewerMode {
  public:
    virtual ~ViewerMode() = default;

    // Input not taken by the panels (keys, mouse), and window events.
    virtual void handleEvent(const SDL_Event& event, const ViewRect& view) = 0;
    // Once per frame: continuous input (held keys), then post the state if it changed.
    virtual void update(double seconds) = 0;
    // The mode's ImGui panel contents (inside the "luxel-view" window).
    virtual void drawPanel() = 0;
    // Lines always shown above the panel, under the frame statistics.
    virtual void drawStats() {}
    // Drawn over the frame every UI frame, panels shown or not (e.g. the paint brush outline).
    virtual void drawOverFrame() {}
    // True once after the mode wants its controls seen (the overlay then opens "controls").
    virtual bool takePanelRequest() { return false; }

    virtual std::shared_ptr<const Frame> latestFrame(bool* fresh) = 0;
    // The latest frame shows the current state (see ScriptClock).
    virtual bool frameCurrent() = 0;
    virtual bool frameConverged() = 0;
    // Internal resolution; the frame is scaled to the window.
    virtual int internalWidth() const = 0;
    virtual int internalHeight() const = 0;
    // Renders at a new internal resolution from the next frame on (adaptive_resolution.h).
    virtual void setInternalSize(int width, int height) = 0;
    // "2D", "voxel" or "octree", for the overlay and the exit summary.
    virtual std::string name() const = 0;
};

}  // namespace luxel::viewer
