// Anti-aliasing and texture filtering against a supersampled reference: a fine checkerboard lawn
// seen at grazing angles (the garden lawn's moire) with nearest texels at 1 sample per pixel
// aliases; filtering over ray-cone footprints and stratified samples bring the image towards the
// reference by stated factors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

struct Lawn {
    VoxelWorld world;
    TextureSet textures;
    Camera camera;
};

// 96 x 96 voxels of lawn, each face a 16 x 16 checkerboard of dark and light texels (so even
// the nearest pixels cover about a texel: minification everywhere, where aliasing lives), under
// a camera two voxels up looking towards the horizon.
Lawn fineLawn() {
    VoxelWorld world = VoxelWorld::create({96, 8, 96}, 8).value();
    TextureSet textures;
    Texture t{"checker", 16, 16, {}, std::nullopt};
    for (int i = 0; i < 256; ++i) {
        const float x = ((i % 16) + (i / 16)) % 2 ? 0.9f : 0.1f;
        t.texels.push_back({x, x, x, 1});
    }
    const int slot = textures.add(std::move(t)).value();
    addBox(world, {0, 0, 0}, {96, 1, 96}, Voxel{255, 255, 255, alphaForSlot(slot)});
    Camera camera = Camera::lookAt({48.3, 2.6, 1.7}, {47.1, 0.8, 30.0}, 50, 64, 40).value();
    return {std::move(world), std::move(textures), camera};
}

ShadeOptions plain(int samples, TextureFilter filter) {
    ShadeOptions o;
    o.faceShading = false;
    o.shadows = false;
    o.maxReflections = 0;
    o.samplesPerPixel = samples;
    o.textureFilter = filter;
    return o;
}

// RMSE of the lawn pixels' red channel against the reference.
double rmse(const Image& a, const Image& reference) {
    double sq = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const double d = a.rgb(x, y).r - reference.rgb(x, y).r;
            sq += d * d;
        }
    }
    return std::sqrt(sq / (double(a.width()) * a.height()));
}

TEST(Antialias, LawnMoireFallsWithFilteringAndSamples) {
    const Lawn lawn = fineLawn();
    // The reference: 256 stratified nearest-texel samples per pixel, the pixel-box integral.
    const Image reference =
        render(lawn.world, lawn.camera, plain(256, TextureFilter::Nearest), &lawn.textures);
    const auto error = [&](int spp, TextureFilter f) {
        return rmse(render(lawn.world, lawn.camera, plain(spp, f), &lawn.textures), reference);
    };
    const double nearest1 = error(1, TextureFilter::Nearest);
    const double nearest4 = error(4, TextureFilter::Nearest);
    const double nearest16 = error(16, TextureFilter::Nearest);
    const double trilinear1 = error(1, TextureFilter::Trilinear);
    const double aniso1 = error(1, TextureFilter::Anisotropic);
    const double aniso4 = error(4, TextureFilter::Anisotropic);
    std::printf(
        "lawn RMSE vs 256 spp nearest: nearest 1 spp %.4f, 4 spp %.4f, 16 spp %.4f; trilinear "
        "1 spp %.4f; anisotropic 1 spp %.4f, 4 spp %.4f\n",
        nearest1, nearest4, nearest16, trilinear1, aniso1, aniso4);
    // Measured: 0.296, 0.150, 0.070; 0.022; 0.020, 0.022 (the reference's own stratified noise
    // is about 0.02, so filtered images are as close as it can tell).
    EXPECT_LT(nearest4, 0.6 * nearest1);
    EXPECT_LT(nearest16, 0.6 * nearest4);
    EXPECT_LT(trilinear1, 0.15 * nearest1);
    EXPECT_LT(aniso1, 0.15 * nearest1);
    EXPECT_LT(aniso1, trilinear1);
    EXPECT_LT(aniso4, 0.15 * nearest1);
    EXPECT_LT(aniso4, 0.5 * nearest16);
}

}  // namespace
}  // namespace luxel::voxel
