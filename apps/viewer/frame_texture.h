// A streaming SDL texture holding the latest frame, converted from linear float to 8-bit sRGB.
#pragma once

#include <SDL.h>

#include "luxel/core/image.h"

namespace luxel::viewer {

class FrameTexture {
  public:
    FrameTexture();
    ~FrameTexture();
    FrameTexture(const FrameTexture&) = delete;
    FrameTexture& operator=(const FrameTexture&) = delete;

    // Uploads `picture` (linear [0, 1] RGB), recreating the texture when the size changes.
    bool update(SDL_Renderer* renderer, const Image& picture);
    SDL_Texture* texture() const { return texture_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    SDL_Texture* texture_ = nullptr;
    int width_ = 0, height_ = 0;
    unsigned char srgb_[4096];  // linear value * 4095 -> sRGB byte
};

}  // namespace luxel::viewer
