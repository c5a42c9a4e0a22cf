// Linear float frame -> sRGB bytes -> SDL streaming texture.
#include "frame_texture.h"

#include <algorithm>
#include <cmath>

#include "luxel/core/tonemap.h"

namespace luxel::viewer {

FrameTexture::FrameTexture() {
    // A table instead of a pow per channel: the upload runs every frame on the UI thread.
    for (int i = 0; i < 4096; ++i) {
        srgb_[i] = static_cast<unsigned char>(
            std::lround(255.0f * linearToSrgb(static_cast<float>(i) / 4095.0f)));
    }
}

FrameTexture::~FrameTexture() {
    if (texture_) SDL_DestroyTexture(texture_);
}

bool FrameTexture::update(SDL_Renderer* renderer, const Image& picture) {
    if (picture.empty()) return false;
    if (!texture_ || width_ != picture.width() || height_ != picture.height()) {
        if (texture_) SDL_DestroyTexture(texture_);
        texture_ = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING,
                                     picture.width(), picture.height());
        if (!texture_) return false;
        width_ = picture.width();
        height_ = picture.height();
    }
    void* pixels = nullptr;
    int pitch = 0;
    if (SDL_LockTexture(texture_, nullptr, &pixels, &pitch) != 0) return false;
    for (int y = 0; y < height_; ++y) {
        auto* row = static_cast<unsigned char*>(pixels) + static_cast<std::ptrdiff_t>(y) * pitch;
        for (int x = 0; x < width_; ++x) {
            const Rgb c = picture.rgb(x, y);
            for (int k = 0; k < 3; ++k) {
                const float v = std::isnan(c[k]) ? 0.0f : std::clamp(c[k], 0.0f, 1.0f);
                row[3 * x + k] = srgb_[static_cast<int>(v * 4095.0f + 0.5f)];
            }
        }
    }
    SDL_UnlockTexture(texture_);
    return true;
}

}  // namespace luxel::viewer
