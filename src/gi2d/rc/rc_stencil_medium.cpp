#include "gi2d/rc/rc_stencil_medium.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "gi2d/material_bits.h"

namespace luxel::gi2d::rc {

StencilMedium::StencilMedium(const Medium2D& medium)
    : width_(medium.width()), height_(medium.height()) {
    ids_.resize(static_cast<std::size_t>(width_) * height_);
    std::unordered_map<MaterialBits, std::uint32_t, MaterialBitsHash> index;
    MaterialBits previous{};
    std::uint32_t previousId = std::numeric_limits<std::uint32_t>::max();
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
            const float m[6] = {s.r, s.g, s.b, e.r, e.g, e.b};
            MaterialBits bits;
            std::memcpy(bits.words, m, sizeof bits.words);
            if (previousId == std::numeric_limits<std::uint32_t>::max() || !(bits == previous)) {
                auto [it, inserted] =
                    index.try_emplace(bits, static_cast<std::uint32_t>(sigma_[0].size()));
                if (inserted) {
                    for (int c = 0; c < 3; ++c) {
                        sigma_[c].push_back(m[c]);
                        emission_[c].push_back(m[3 + c]);
                    }
                    grey_ = grey_ && s.r == s.g && s.g == s.b;
                }
                previous = bits;
                previousId = it->second;
            }
            ids_[static_cast<std::size_t>(y) * width_ + x] = previousId;
        }
    }
    // Per material: sigma, its sign bit set in channel 0 where it emits; then per pixel.
    const int channels = grey_ ? 1 : 3;
    std::vector<float> signedSigma[3];
    for (int c = 0; c < channels; ++c) signedSigma[c] = sigma_[c];
    for (std::size_t id = 0; id < paletteSize(); ++id) {
        if (emits(static_cast<std::uint32_t>(id))) {
            signedSigma[0][id] = std::copysign(signedSigma[0][id], -1.0f);
        }
    }
    for (int c = 0; c < channels; ++c) {
        planeSigma_[c].resize(ids_.size());
        for (std::size_t p = 0; p < ids_.size(); ++p) planeSigma_[c][p] = signedSigma[c][ids_[p]];
    }
    buildUniformRadius();
}

void StencilMedium::buildUniformRadius() {
    // The nearest pixel of another material (or off the canvas) lies at Chebyshev distance D
    // exactly when the nearest border pixel (one with such an 8-neighbour) lies at D - 1: so the
    // radius is the chessboard distance to the border pixels, by the two-pass transform.
    const int w = width_, h = height_;
    std::vector<std::int32_t> d(ids_.size());
    auto at = [&](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool border = x == 0 || y == 0 || x == w - 1 || y == h - 1;
            for (int dy = -1; dy <= 1 && !border; ++dy) {
                for (int dx = -1; dx <= 1 && !border; ++dx) {
                    border = ids_[at(x + dx, y + dy)] != ids_[at(x, y)];
                }
            }
            d[at(x, y)] = border ? 0 : kMaxUniformRadius;
        }
    }
    for (int y = 1; y < h; ++y) {
        for (int x = 1; x < w - 1; ++x) {
            std::int32_t& v = d[at(x, y)];
            v = std::min({v, d[at(x - 1, y)] + 1, d[at(x - 1, y - 1)] + 1, d[at(x, y - 1)] + 1,
                          d[at(x + 1, y - 1)] + 1});
        }
    }
    for (int y = h - 2; y >= 0; --y) {
        for (int x = w - 2; x >= 1; --x) {
            std::int32_t& v = d[at(x, y)];
            v = std::min({v, d[at(x + 1, y)] + 1, d[at(x + 1, y + 1)] + 1, d[at(x, y + 1)] + 1,
                          d[at(x - 1, y + 1)] + 1});
        }
    }
    uniformRadius_.resize(ids_.size());
    for (std::size_t p = 0; p < d.size(); ++p) {
        uniformRadius_[p] = static_cast<std::uint8_t>(d[p]);
    }
}

std::uint64_t StencilMedium::bytesFor(std::uint64_t width, std::uint64_t height) {
    return width * height * (sizeof(std::uint32_t) + 9 * sizeof(float) + 16 + 5);
}

std::vector<Rgb> toSlotMajor(const std::vector<Rgb>& probeMajor, int stored) {
    const std::size_t probes = probeMajor.size() / stored;
    std::vector<Rgb> out(probeMajor.size());
    for (std::size_t p = 0; p < probes; ++p) {
        for (int s = 0; s < stored; ++s) out[s * probes + p] = probeMajor[p * stored + s];
    }
    return out;
}

std::vector<Rgb> toProbeMajor(const std::vector<Rgb>& slotMajor, int stored) {
    const std::size_t probes = slotMajor.size() / stored;
    std::vector<Rgb> out(slotMajor.size());
    for (std::size_t p = 0; p < probes; ++p) {
        for (int s = 0; s < stored; ++s) out[p * stored + s] = slotMajor[s * probes + p];
    }
    return out;
}

}  // namespace luxel::gi2d::rc
