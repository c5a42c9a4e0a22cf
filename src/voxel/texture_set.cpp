// Face textures: validation, PNG loading (core image_io), mip chains, nearest-texel lookup and
// filtered sampling over ray-cone footprints (trilinear, anisotropic; the formulas are
// shared/texture_filter.h, which the GPU's texture_sample.glsl runs too).
#include "luxel/voxel/texture_set.h"
#include "gpu/shaders/shared/texture_filter.h"
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

namespace shared = gpu::shared;

Texel operator*(const Texel& t, float s) {
    return {t.r * s, t.g * s, t.b * s, t.a * s};
}
Texel& operator+=(Texel& a, const Texel& b) {
    a.r += b.r, a.g += b.g, a.b += b.b, a.a += b.a;
    return a;
}

// Source texels (and their coverage) of each destination texel when `src` texels shrink to
// `dst`: destination i covers [i, i + 1) * src / dst exactly, so odd sides lose nothing.
std::vector<std::vector<std::pair<int, float>>> areaWeights(int src, int dst) {
    std::vector<std::vector<std::pair<int, float>>> w(dst);
    const double scale = double(src) / dst;
    for (int i = 0; i < dst; ++i) {
        const double lo = i * scale, hi = (i + 1) * scale;
        for (int s = int(std::floor(lo)); s < int(std::ceil(hi)) && s < src; ++s) {
            const double cover = std::min<double>(hi, s + 1) - std::max<double>(lo, s);
            if (cover > 0) w[i].push_back({s, float(cover / scale)});
        }
    }
    return w;
}

// The mip chain of a level-0 image (rows top to bottom), level after level.
std::vector<Texel> buildChain(const std::vector<Texel>& level0, int width, int height) {
    std::vector<Texel> chain(shared::textureChainTexels(width, height));
    std::copy(level0.begin(), level0.end(), chain.begin());
    const int levels = shared::textureLevelCount(width, height);
    for (int l = 1; l < levels; ++l) {
        const int sw = shared::textureLevelSide(width, l - 1);
        const int sh = shared::textureLevelSide(height, l - 1);
        const int dw = shared::textureLevelSide(width, l);
        const int dh = shared::textureLevelSide(height, l);
        const Texel* src = chain.data() + shared::textureLevelOffset(width, height, l - 1);
        Texel* dst = chain.data() + shared::textureLevelOffset(width, height, l);
        const auto wx = areaWeights(sw, dw), wy = areaWeights(sh, dh);
        for (int y = 0; y < dh; ++y) {
            for (int x = 0; x < dw; ++x) {
                Texel sum{0, 0, 0, 0};
                for (const auto& [sy, fy] : wy[y]) {
                    for (const auto& [sx, fx] : wx[x]) {
                        sum += src[static_cast<std::size_t>(sy) * sw + sx] * (fx * fy);
                    }
                }
                dst[static_cast<std::size_t>(y) * dw + x] = sum;
            }
        }
    }
    return chain;
}

// One level of a chain, addressed bottom-up like lookup() with wrapped indices.
struct Level {
    const Texel* texels;
    int width, height;

    Texel at(int column, int rowFromBottom) const {
        const int c = shared::textureWrap(column, width);
        const int r = height - 1 - shared::textureWrap(rowFromBottom, height);
        return texels[static_cast<std::size_t>(r) * width + c];
    }
    // Bilinear between the four texel centres around (u, v); centres sit at (i + 0.5) / side.
    Texel bilinear(float u, float v) const {
        const float x = u * float(width) - 0.5f, y = v * float(height) - 0.5f;
        const float fx0 = std::floor(x), fy0 = std::floor(y);
        const int x0 = int(fx0), y0 = int(fy0);
        const float ax = x - fx0, ay = y - fy0;
        Texel r = at(x0, y0) * ((1 - ax) * (1 - ay));
        r += at(x0 + 1, y0) * (ax * (1 - ay));
        r += at(x0, y0 + 1) * ((1 - ax) * ay);
        r += at(x0 + 1, y0 + 1) * (ax * ay);
        return r;
    }
};

Level levelOf(const std::vector<Texel>& chain, int width, int height, int level) {
    return {chain.data() + shared::textureLevelOffset(width, height, level),
            shared::textureLevelSide(width, level), shared::textureLevelSide(height, level)};
}

// Trilinear: bilinear in the two levels around `lod` (clamped to the chain), blended.
Texel trilinear(const std::vector<Texel>& chain, int width, int height, float u, float v,
                float lod) {
    const int levels = shared::textureLevelCount(width, height);
    const float l = std::clamp(lod, 0.0f, float(levels - 1));
    const int l0 = int(std::floor(l));
    const int l1 = std::min(l0 + 1, levels - 1);
    const float f = l - float(l0);
    Texel a = levelOf(chain, width, height, l0).bilinear(u, v);
    if (f <= 0.0f || l1 == l0) return a;
    a = a * (1 - f);
    a += levelOf(chain, width, height, l1).bilinear(u, v) * f;
    return a;
}

// The filtered chain value over a footprint (the shared formulas; texture_sample.glsl mirrors).
Texel filterChain(const std::vector<Texel>& chain, int width, int height, float u, float v,
                  const TexelFootprint& fp, TextureFilter filter, int maxAnisotropy) {
    float major = shared::textureAxisTexels(fp.majorU, fp.majorV, width, height);
    float minor = shared::textureAxisTexels(fp.minorU, fp.minorV, width, height);
    float mu = fp.majorU, mv = fp.majorV;
    if (minor > major) {  // callers may pass the axes either way round
        std::swap(major, minor);
        mu = fp.minorU, mv = fp.minorV;
    }
    if (filter == TextureFilter::Trilinear) {
        return trilinear(chain, width, height, u, v, shared::textureLod(2.0f * major));
    }
    const int n = shared::textureProbeCount(major, minor, maxAnisotropy);
    const float lod = shared::textureLod(2.0f * std::max(minor, major / float(n)));
    Texel sum{0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const float s = shared::textureProbeOffset(i, n);
        sum += trilinear(chain, width, height, u + s * mu, v + s * mv, lod);
    }
    return sum * (1.0f / float(n));
}

}  // namespace

std::optional<TextureFilter> parseTextureFilter(const std::string& name) {
    if (name == "nearest") return TextureFilter::Nearest;
    if (name == "trilinear") return TextureFilter::Trilinear;
    if (name == "anisotropic") return TextureFilter::Anisotropic;
    return std::nullopt;
}

const char* textureFilterName(TextureFilter filter) {
    switch (filter) {
        case TextureFilter::Trilinear:
            return "trilinear";
        case TextureFilter::Anisotropic:
            return "anisotropic";
        case TextureFilter::Nearest:
            break;
    }
    return "nearest";
}

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
    if (!texture.normals.empty()) {
        if (texture.normals.size() != texture.texels.size()) {
            return Error("texture '" + texture.name + "': its normal map has " +
                         std::to_string(texture.normals.size()) + " texels, the texture " +
                         std::to_string(texture.texels.size()));
        }
        for (const Texel& n : texture.normals) {
            if (!std::isfinite(n.r) || !std::isfinite(n.g) || !std::isfinite(n.b)) {
                return Error("texture '" + texture.name + "' has a non-finite normal");
            }
        }
    }
    for (const Texel& t : texture.texels) anyCutout_ = anyCutout_ || t.cutout();
    // Premultiplied alpha before averaging, so a leaf's transparent texels do not darken it.
    std::vector<Texel> premultiplied(texture.texels.size());
    for (std::size_t i = 0; i < premultiplied.size(); ++i) {
        const Texel& t = texture.texels[i];
        premultiplied[i] = {t.r * t.a, t.g * t.a, t.b * t.a, t.a};
    }
    colourMips_.push_back(buildChain(premultiplied, texture.width, texture.height));
    normalMips_.push_back(texture.normals.empty()
                              ? std::vector<Texel>{}
                              : buildChain(texture.normals, texture.width, texture.height));
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

Status TextureSet::loadNormalMap(Texture& texture, const std::string& path) {
    if (const auto size = pngSize(path)) {
        if (Status s = checkSize(texture.name, size->first, size->second); !s) {
            return Error(path + ": " + s.error().message());
        }
    }
    Result<Image> image = readPng(path, PngEncoding::Linear);
    if (!image) return image.error();
    if (image->width() != texture.width || image->height() != texture.height) {
        return Error(path + ": the normal map of texture '" + texture.name + "' is " +
                     std::to_string(image->width()) + "x" + std::to_string(image->height()) +
                     ", the texture " + std::to_string(texture.width) + "x" +
                     std::to_string(texture.height));
    }
    texture.normals.resize(image->pixelCount());
    for (int y = 0; y < texture.height; ++y) {
        for (int x = 0; x < texture.width; ++x) {
            const Rgb c = image->rgb(x, y);
            Vec3 n{c.r * 2 - 1, c.g * 2 - 1, c.b * 2 - 1};
            const float len = length(n);
            n = len > 1e-6f ? n / len : Vec3{0, 0, 1};
            texture.normals[static_cast<std::size_t>(y) * texture.width + x] = {n.x, n.y, n.z, 1};
        }
    }
    return Ok{};
}

int TextureSet::mipLevels(int slot) const {
    return shared::textureLevelCount(textures_[slot].width, textures_[slot].height);
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

Texel TextureSet::sample(int slot, float u, float v, const TexelFootprint& footprint,
                         TextureFilter filter, int maxAnisotropy) const {
    if (filter == TextureFilter::Nearest) return lookup(slot, u, v);
    const Texture& t = textures_[slot];
    const Texel p =
        filterChain(colourMips_[slot], t.width, t.height, u, v, footprint, filter, maxAnisotropy);
    // Back to straight alpha; an all-transparent footprint keeps the texel under the hit.
    if (!(p.a > 1e-6f)) return lookup(slot, u, v);
    return {p.r / p.a, p.g / p.a, p.b / p.a, std::min(p.a, 1.0f)};
}

Vec3 TextureSet::normalAt(int slot, float u, float v, const TexelFootprint& footprint,
                          TextureFilter filter, int maxAnisotropy) const {
    if (normalMips_[slot].empty()) return {0.0f, 0.0f, 1.0f};
    const Texture& t = textures_[slot];
    Texel n;
    if (filter == TextureFilter::Nearest) {
        n = Level{normalMips_[slot].data(), t.width, t.height}.at(
            shared::voxelTexelIndex(u, t.width), shared::voxelTexelIndex(v, t.height));
    } else {
        n = filterChain(normalMips_[slot], t.width, t.height, u, v, footprint, filter,
                        maxAnisotropy);
    }
    const Vec3 m{n.r, n.g, n.b};
    const float len = length(m);
    return len > 1e-6f ? m / len : Vec3{0.0f, 0.0f, 1.0f};
}

}  // namespace luxel::voxel
