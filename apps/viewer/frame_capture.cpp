// PNG output for screenshots and recordings.
#include "frame_capture.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "luxel/core/image_io.h"

namespace luxel::viewer {

Status writeFramePng(const std::string& path, const Frame& frame) {
    if (frame.picture.empty()) return Error(path + ": no frame has been rendered yet");
    // The metadata says what made the picture (the solver, the path tracer's samples so far).
    return writePng(path, frame.picture, PngEncoding::Srgb, frame.metadata);
}

Status writeWindowPng(const std::string& path, SDL_Renderer* renderer) {
    int w = 0, h = 0;
    if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0 || w <= 0 || h <= 0) {
        return Error(path + ": cannot read the window size: " + SDL_GetError());
    }
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
    if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGB24, rgb.data(), w * 3) != 0) {
        return Error(path + ": cannot read the window: " + SDL_GetError());
    }
    Image image(w, h, 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) image.data()[i] = rgb[i] / 255.0f;
    // The window already holds display (sRGB) values: write them unchanged.
    return writePng(path, image, PngEncoding::Linear);
}

Status FrameRecorder::offer(const Frame& frame) {
    if (remaining_ <= 0 || frame.picture.empty()) return Ok{};
    if (written_ == 0) {
        std::error_code ec;
        std::filesystem::create_directories(dir_, ec);
        if (ec) return Error(dir_ + ": cannot create the --record folder: " + ec.message());
    }
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", written_);
    if (Status s = writeFramePng((std::filesystem::path(dir_) / name).string(), frame); !s) {
        return s;
    }
    ++written_;
    --remaining_;
    return Ok{};
}

std::string nextScreenshotName() {
    for (int i = 1; i < 10000; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "luxel-view-%04d.png", i);
        if (!std::filesystem::exists(name)) return name;
    }
    return "luxel-view.png";
}

}  // namespace luxel::viewer
