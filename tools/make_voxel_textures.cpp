// Writes the face textures under scenes/voxel/textures/ (16x16 RGBA PNG, deterministic):
//   bricks.png  running-bond bricks with mortar joints
//   bricks_normal.png  its tangent-space normal map: mortar grooves recessed below the bricks
//   leaves.png  leaf clusters with transparent holes (alpha 0: cutouts the rays pass through)
//   grass.png   grass with blade streaks
// Usage: luxel_make_voxel_textures OUTPUT_DIR
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "luxel/core/image.h"
#include "luxel/core/image_io.h"
#include "luxel/core/tonemap.h"

namespace {

constexpr int kSide = 16;

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t salt) {
    std::uint32_t h = x * 0x9e3779b9u ^ (y + 0x7f4a7c15u) * 0x85ebca6bu ^ salt * 0xc2b2ae35u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    return h ^ (h >> 16);
}

// A value in [-1, 1] from a hash.
float jitter(std::uint32_t h) {
    return static_cast<float>(h & 0xffffu) / 32767.5f - 1.0f;
}

// Sets a texel from 8-bit sRGB values (so the PNG holds exactly these bytes) and a linear alpha.
void put(luxel::Image& image, int x, int y, float r, float g, float b, float a = 1.0f) {
    const auto channel = [](float c) {
        return luxel::srgbToLinear(std::clamp(c, 0.0f, 255.0f) / 255.0f);
    };
    image.at(x, y, 0) = channel(r);
    image.at(x, y, 1) = channel(g);
    image.at(x, y, 2) = channel(b);
    image.at(x, y, 3) = a;
}

luxel::Image bricks() {
    luxel::Image image(kSide, kSide, 4);
    for (int y = 0; y < kSide; ++y) {
        const int course = y / 4;
        const int shift = (course % 2) * 4;  // running bond: every other course by half a brick
        for (int x = 0; x < kSide; ++x) {
            const int bx = (x + shift) % kSide;
            const bool mortar = y % 4 == 3 || bx % 8 == 7;
            if (mortar) {
                const float m = 200.0f + 12.0f * jitter(hash(x, y, 1));
                put(image, x, y, m, m - 6.0f, m - 16.0f);
                continue;
            }
            const int brick = (x + shift) / 8 + course * 3;
            const float shade = 18.0f * jitter(hash(brick, course, 2));
            const float speck = 10.0f * jitter(hash(x, y, 3));
            put(image, x, y, 170.0f + shade + speck, 74.0f + 0.5f * shade + speck,
                56.0f + 0.4f * shade + speck);
        }
    }
    return image;
}

// Whether texel (x, y) of bricks() is mortar.
bool brickMortar(int x, int y) {
    const int shift = ((y / 4) % 2) * 4;
    return y % 4 == 3 || ((x + shift) % kSide) % 8 == 7;
}

// Tangent-space normals of a height field (bricks 1, mortar 0) by wrapped central differences:
// x along u (columns, left to right), y along v (up the face: rows run downwards), z out of the
// face; stored (n + 1) / 2 as data (no sRGB curve).
luxel::Image bricksNormal() {
    luxel::Image image(kSide, kSide, 3);
    const auto height = [](int x, int y) {
        return brickMortar((x + kSide) % kSide, (y + kSide) % kSide) ? 0.0f : 1.0f;
    };
    constexpr float kDepth = 0.8f;  // groove depth in texel widths: how steep the bevels are
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            const float du = 0.5f * (height(x + 1, y) - height(x - 1, y)) * kDepth;
            const float dv = 0.5f * (height(x, y - 1) - height(x, y + 1)) * kDepth;
            const float len = std::sqrt(du * du + dv * dv + 1.0f);
            image.at(x, y, 0) = (-du / len + 1.0f) * 0.5f;
            image.at(x, y, 1) = (-dv / len + 1.0f) * 0.5f;
            image.at(x, y, 2) = (1.0f / len + 1.0f) * 0.5f;
        }
    }
    return image;
}

luxel::Image leaves() {
    luxel::Image image(kSide, kSide, 4);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            // Holes: about a third of the texels, in 2x2 clumps so the gaps read as gaps.
            const bool hole = (hash(x / 2, y / 2, 4) & 0xff) < 80 && (hash(x, y, 5) & 3) != 0;
            const float v = 24.0f * jitter(hash(x, y, 6));
            const float clump = 14.0f * jitter(hash(x / 3, y / 3, 7));
            put(image, x, y, 62.0f + v + clump, 128.0f + v + clump, 44.0f + 0.5f * v,
                hole ? 0.0f : 1.0f);
        }
    }
    return image;
}

luxel::Image grass() {
    luxel::Image image(kSide, kSide, 4);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            // Blade streaks: columns share a tone, with per-texel flecks.
            const float blade = 16.0f * jitter(hash(x, 0, 8));
            const float fleck = 12.0f * jitter(hash(x, y, 9));
            put(image, x, y, 96.0f + blade + fleck, 160.0f + blade + fleck, 70.0f + 0.5f * fleck);
        }
    }
    return image;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: luxel_make_voxel_textures OUTPUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    const struct {
        const char* name;
        luxel::Image image;
        luxel::PngEncoding encoding = luxel::PngEncoding::Srgb;
    } textures[] = {{"bricks.png", bricks()},
                    {"bricks_normal.png", bricksNormal(), luxel::PngEncoding::Linear},
                    {"leaves.png", leaves()},
                    {"grass.png", grass()}};
    for (const auto& t : textures) {
        const std::string path = dir + "/" + t.name;
        if (luxel::Status s = luxel::writePng(path, t.image, t.encoding); !s) {
            std::fprintf(stderr, "luxel_make_voxel_textures: %s\n", s.error().message().c_str());
            return 1;
        }
        std::printf("wrote %s\n", path.c_str());
    }
    return 0;
}
