// Screenshots and --record: rendered frames (internal resolution) and whole-window captures
// (with the panels) written as PNG through luxel's image_io.
#pragma once

#include <SDL.h>

#include <string>

#include "frame.h"
#include "luxel/core/error.h"

namespace luxel::viewer {

// Writes the frame's picture (8-bit sRGB).
Status writeFramePng(const std::string& path, const Frame& frame);

// Reads back what the renderer drew this frame (call before SDL_RenderPresent) and writes it.
Status writeWindowPng(const std::string& path, SDL_Renderer* renderer);

// Writes the next `count` new frames as DIR/frame_00000.png, frame_00001.png, ...
class FrameRecorder {
  public:
    FrameRecorder(int count, std::string dir) : remaining_(count), dir_(std::move(dir)) {}
    // Records `frame` if recording is still on. Fails when the file cannot be written.
    Status offer(const Frame& frame);
    bool active() const { return remaining_ > 0; }
    int written() const { return written_; }

  private:
    int remaining_;
    std::string dir_;
    int written_ = 0;
};

// Next free "luxel-view-NNNN.png" in the current folder (for the screenshot key).
std::string nextScreenshotName();

}  // namespace luxel::viewer
