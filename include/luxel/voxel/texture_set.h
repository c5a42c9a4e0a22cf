// Face textures for voxels: up to 254 RGBA textures, addressed by the voxel's alpha byte.
//
// Voxel alpha is a material byte: 0 = empty, 255 = plain block (procedural texture), 1..254 =
// texture slot a - 1. A textured face's colour multiplies the voxel colour (a tint): the nearest
// texel, or a filtered colour over the ray cone's footprint (sample()). A texel with alpha < 0.5
// is a cutout that the ray passes through (the Unity tracer's "transparent pixel: loop to the
// next block"); that decision always reads the nearest texel (lookup()), so geometry does not
// change with distance or filter. Filtering: docs/algorithms/voxel-textures.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

inline constexpr int kMaxTextures = 254;
// Largest accepted texture side: faces are one voxel, so more texels only cost memory.
inline constexpr int kMaxTextureSide = 1024;
inline constexpr std::uint8_t kPlainBlockAlpha = 255;

// The texture slot a voxel's alpha selects, or -1 for empty and plain blocks.
constexpr int textureSlotOf(Voxel v) {
    return v.a >= 1 && v.a <= kMaxTextures ? v.a - 1 : -1;
}
// The alpha byte that selects texture `slot` (0..253).
constexpr std::uint8_t alphaForSlot(int slot) {
    return static_cast<std::uint8_t>(slot + 1);
}

// A linear RGB colour and a linear alpha, as stored per texel (and uploaded to the GPU as is).
struct Texel {
    float r = 1, g = 1, b = 1, a = 1;
    constexpr bool cutout() const { return a < 0.5f; }
    constexpr bool operator==(const Texel&) const = default;
};

// The footprint of a ray cone on a face, in face coordinates (a face spans [0, 1)^2): the two
// half-axes of the ellipse it covers (texel_footprint.h). Zero axes: a point sample (level 0,
// bilinear for the filtered modes).
struct TexelFootprint {
    float majorU = 0, majorV = 0;
    float minorU = 0, minorV = 0;
};

enum class TextureFilter {
    Nearest,      // the texel under (u, v)
    Trilinear,    // mip-mapped, level from the footprint's major axis (isotropic)
    Anisotropic,  // several trilinear probes along the footprint's major axis
};

struct Texture {
    std::string name;
    int width = 0, height = 0;
    std::vector<Texel> texels;  // rows top to bottom, as in the image file
    // Energy-conserving reflections: this material's reflectivity in [0, 1] (empty: the
    // renderer's default).
    std::optional<float> reflectivity;
    // Tangent-space normal map (r, g, b = x along u, y along v, z out of the face, each in
    // [-1, 1]; a unused), the same size and row order as `texels`. Empty: flat.
    std::vector<Texel> normals = {};
};

class TextureSet {
  public:
    // Adds a texture and returns its slot. Fails for more than kMaxTextures, a duplicate or empty
    // name, a side outside 1..kMaxTextureSide, a texel count that does not match, non-finite
    // texels, or a reflectivity outside [0, 1].
    Result<int> add(Texture texture);
    // Reads a PNG: colour is sRGB-decoded to linear, alpha is linear (no alpha channel: opaque;
    // grey images are grey in every channel). Size limits as in add().
    static Result<Texture> load(const std::string& name, const std::string& path);
    // Reads a tangent-space normal map PNG into texture.normals: 8-bit RGB as data (no sRGB
    // curve), mapped c / 255 * 2 - 1 and renormalised. It must have the texture's size.
    static Status loadNormalMap(Texture& texture, const std::string& path);

    int size() const { return static_cast<int>(textures_.size()); }
    bool empty() const { return textures_.empty(); }
    const Texture& operator[](int slot) const { return textures_[slot]; }
    std::optional<int> find(const std::string& name) const;

    // Nearest texel at face coordinates (u, v) in [0, 1): column floor(u * width), row
    // floor(v * height) counted from the bottom (v grows upwards on side faces, so images stand
    // upright on walls). Coordinates are clamped into the texture. `slot` must be valid.
    Texel lookup(int slot, float u, float v) const;
    // Filtered colour over a footprint (Nearest: lookup). `maxAnisotropy` caps the probes.
    Texel sample(int slot, float u, float v, const TexelFootprint& footprint, TextureFilter filter,
                 int maxAnisotropy = 16) const;
    // Tangent-space normal (x along u, y along v, z out of the face), unit length; (0, 0, 1)
    // for textures without a normal map. Filtered like sample(), then renormalised.
    Vec3 normalAt(int slot, float u, float v, const TexelFootprint& footprint, TextureFilter filter,
                  int maxAnisotropy = 16) const;
    bool hasNormalMap(int slot) const { return !normalMips_[slot].empty(); }
    // Whether any texel of any texture is a cutout (a ray may pass a textured voxel).
    bool anyCutout() const { return anyCutout_; }

    // Mip chains, built by add(): levels of max(1, side >> l) texels (exact area averages),
    // level after level, rows top to bottom (sizes and offsets: shared/texture_filter.h). Colour
    // chains hold premultiplied alpha (r * a, g * a, b * a, a) so transparent texels add no
    // colour; normal chains hold averaged, unnormalised vectors. What the GPU uploads.
    const std::vector<Texel>& colourMips(int slot) const { return colourMips_[slot]; }
    const std::vector<Texel>& normalMips(int slot) const { return normalMips_[slot]; }
    int mipLevels(int slot) const;

  private:
    std::vector<Texture> textures_;
    std::vector<std::vector<Texel>> colourMips_, normalMips_;
    bool anyCutout_ = false;
};

// Filter names as the CLI and scene files spell them: "nearest", "trilinear", "anisotropic".
std::optional<TextureFilter> parseTextureFilter(const std::string& name);
const char* textureFilterName(TextureFilter filter);

}  // namespace luxel::voxel
