// Face textures: validation, PNG loading (core image_io) and nearest-texel lookup.
#include "luxel/voxel/texture_set.h"
#include "gpu/shaders/shared/voxel_shading.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <utility>

#include "luxel/core/image_io.h"

namespace luxel::voxel {
namespace {

Status checkSize(const std::string& name, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxTextureSide || height > kMaxTextureSide) {
        return Error("texture '" + name + "' is " + std::to_string(width) + "x" +
                     std::to_string(height) + ": each side must be in 1.." +
                     std::to_string(kMaxTextureSide));
    }
    return Ok{};
}

// The size in a PNG's IHDR chunk, read before decoding so an absurd texture is refused before
// its pixels are allocated. Anything unreadable is left to readPng to report.
std::optional<std::pair<int, int>> pngSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<unsigned char, 24> b{};
    if (!in.read(reinterpret_cast<char*>(b.data()), b.size())) return std::nullopt;
    if (b[0] != 0x89 || b[1] != 'P' || b[2] != 'N' || b[3] != 'G' || b[12] != 'I' || b[13] != 'H' ||
        b[14] != 'D' || b[15] != 'R') {
        return std::nullopt;
    }
    const auto be32 = [&](int at) {
        return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
               (std::uint32_t{b[at + 2]} << 8) | std::uint32_t{b[at + 3]};
    };
    const std::uint32_t w = be32(16), h = be32(20);
    const auto clampSide = [](std::uint32_t s) {
        return static_cast<int>(std::min<std::uint32_t>(s, 1u << 30));
    };
    return std::pair{clampSide(w), clampSide(h)};
}

}  // namespace

Result<int> TextureSet::add(Texture texture) {
    if (texture.name.empty()) return Error("a texture needs a name");
    if (size() >= kMaxTextures) {
        return Error("too many textures: at most " + std::to_string(kMaxTextures) +
                     " (voxel alpha 1..254 selects one)");
    }
    if (find(texture.name)) return Error("texture '" + texture.name + "' is defined twice");
    if (Status s = checkSize(texture.name, texture.width, texture.height); !s) return s.error();
    if (texture.texels.size() != static_cast<std::size_t>(texture.width) * texture.height) {
        return Error("texture '" + texture.name + "' has " + std::to_string(texture.texels.size()) +
                     " texels, its size needs " +
                     std::to_string(static_cast<std::size_t>(texture.width) * texture.height));
    }
    for (const Texel& t : texture.texels) {
        if (!std::isfinite(t.r) || !std::isfinite(t.g) || !std::isfinite(t.b) ||
            !std::isfinite(t.a)) {
            return Error("texture '" + texture.name + "' has a non-finite texel");
        }
    }
    if (texture.reflectivity && !(*texture.reflectivity >= 0.0f && *texture.reflectivity <= 1.0f)) {
        return Error("texture '" + texture.name + "': reflectivity must be in [0, 1]");
    }
    textures_.push_back(std::move(texture));
    return size() - 1;
}

Result<Texture> TextureSet::load(const std::string& name, const std::string& path) {
    if (const auto size = pngSize(path)) {
        if (Status s = checkSize(name, size->first, size->second); !s) {
            return Error(path + ": " + s.error().message());
        }
    }
    Result<Image> image = readPng(path, PngEncoding::Srgb);
    if (!image) return image.error();
    if (Status s = checkSize(name, image->width(), image->height()); !s) {
        return Error(path + ": " + s.error().message());
    }
    Texture texture;
    texture.name = name;
    texture.width = image->width();
    texture.height = image->height();
    texture.texels.resize(image->pixelCount());
    const int channels = image->channels();
    for (int y = 0; y < texture.height; ++y) {
        for (int x = 0; x < texture.width; ++x) {
            Texel& t = texture.texels[static_cast<std::size_t>(y) * texture.width + x];
            const Rgb c = image->rgb(x, y);  // grey reads as grey in every channel
            t = {c.r, c.g, c.b, 1.0f};
            // Grey+alpha and RGBA carry alpha last; readPng leaves it linear.
            if (channels == 2 || channels == 4) t.a = image->at(x, y, channels - 1);
        }
    }
    return texture;
}

std::optional<int> TextureSet::find(const std::string& name) const {
    for (int i = 0; i < size(); ++i) {
        if (textures_[i].name == name) return i;
    }
    return std::nullopt;
}

Texel TextureSet::lookup(int slot, float u, float v) const {
    const Texture& t = textures_[slot];
    // The texel addressing the GPU shader runs (shared/voxel_shading.h).
    const int column = gpu::shared::voxelTexelIndex(u, t.width);
    const int row = t.height - 1 - gpu::shared::voxelTexelIndex(v, t.height);
    return t.texels[static_cast<std::size_t>(row) * t.width + column];
}

Texel TextureSet::sample(int slot, float u, float v, const TexelFootprint&, TextureFilter,
                         int) const {
    return lookup(slot, u, v);
}

Vec3 TextureSet::normalAt(int, float, float, const TexelFootprint&, TextureFilter) const {
    return {0.0f, 0.0f, 1.0f};
}

}  // namespace luxel::voxel
