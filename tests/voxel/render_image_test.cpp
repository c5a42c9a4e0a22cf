// The pixel loop: stratified sample positions, one sample at the pixel centre, primary cones,
// determinism across thread counts.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "gpu/shaders/shared/pixel_samples.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

// Every n: offsets in [0, 1)^2, one per column stratum of width 1/n (N-rooks) and one per row
// stratum; square n: one per cell of the g x g grid.
TEST(PixelSamples, StratifiedAndDeterministic) {
    for (int n = 2; n <= 64; ++n) {
        for (std::uint32_t px : {0u, 7u, 1000u}) {
            std::set<int> columns, rows, cells;
            const int g = int(std::lround(std::sqrt(double(n))));
            for (int k = 0; k < n; ++k) {
                const shared::vec2 o = shared::pixelSampleOffset(px, 3u, k, n);
                ASSERT_GE(o.x, 0.0f);
                ASSERT_LT(o.x, 1.0f);
                ASSERT_GE(o.y, 0.0f);
                ASSERT_LT(o.y, 1.0f);
                const shared::vec2 again = shared::pixelSampleOffset(px, 3u, k, n);
                EXPECT_EQ(o.x, again.x);
                EXPECT_EQ(o.y, again.y);
                if (g * g == n) {
                    cells.insert(int(o.y * g) * g + int(o.x * g));
                } else {
                    columns.insert(int(o.x * n));
                    rows.insert(int(o.y * n));
                }
            }
            if (g * g == n) {
                EXPECT_EQ(int(cells.size()), n) << n;
            } else {
                EXPECT_EQ(int(columns.size()), n) << n;
                EXPECT_EQ(int(rows.size()), n) << n;
            }
        }
    }
    const shared::vec2 centre = shared::pixelSampleOffset(5u, 6u, 0, 1);
    EXPECT_EQ(centre.x, 0.5f);
    EXPECT_EQ(centre.y, 0.5f);
    // Different pixels get different jitter.
    EXPECT_NE(shared::pixelSampleOffset(1u, 0u, 0, 4).x, shared::pixelSampleOffset(2u, 0u, 0, 4).x);
}

TEST(RenderImage, OneSampleIsThePixelCentreRay) {
    VoxelWorld world = VoxelWorld::create({16, 16, 16}, 8).value();
    addBox(world, {0, 0, 0}, {16, 3, 16}, Voxel{90, 160, 70, 255});
    addBox(world, {5, 3, 9}, {9, 9, 12}, Voxel{200, 60, 40, 255});
    const Camera camera = Camera::lookAt({2.5, 8.2, 1.3}, {8, 3, 10}, 60, 20, 14).value();
    ShadeOptions options;
    const Image image = render(world, camera, options);
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Rgb c = shadeRay(world, camera.primaryRay(x, y), options);
            EXPECT_EQ(image.rgb(x, y).r, c.r);
            EXPECT_EQ(image.rgb(x, y).g, c.g);
        }
    }
    // With 9 samples, the same image whatever the thread count, and a pixel's value is the mean
    // of its samples.
    options.samplesPerPixel = 9;
    const Image one = [&] {
        ThreadLimit limit(1);
        return render(world, camera, options);
    }();
    const Image many = render(world, camera, options);
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one.data()[i], many.data()[i]);
    Rgb sum;
    RayCone cone = primaryCone(camera);
    cone.spread /= 3.0;
    for (int k = 0; k < 9; ++k) {
        const shared::vec2 o = shared::pixelSampleOffset(4u, 5u, k, 9);
        sum += shadeRay(world, camera.rayAt(4 + double(o.x), 5 + double(o.y)), cone, options);
    }
    EXPECT_NEAR(one.rgb(4, 5).r, sum.r / 9, 1e-6f);
}

TEST(RenderImage, PrimaryConeSpreadsByOnePixel) {
    const Camera camera = Camera::create({0, 0, 0}, 0, 0, 90, 100, 50).value();
    const RayCone cone = primaryCone(camera);
    EXPECT_EQ(cone.width, 0.0);
    // Adjacent pixel centres at the image centre are 2 tan(45 deg) / 50 apart at distance 1.
    EXPECT_NEAR(cone.spread, 2.0 / 50, 1e-12);
    const Ray a = camera.rayAt(50, 25), b = camera.rayAt(51, 25);
    EXPECT_NEAR(length(a.direction - b.direction), cone.spread, 1e-3);
}

// A scene with `extra` fields and a bricks texture with `textureExtra`, from a file in `tmp`.
Result<VoxelScene> sceneWith(const test::TempDir& tmp, const std::string& name,
                             const std::string& textureExtra, const std::string& extra) {
    const std::string dir = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/textures/";
    return loadVoxelScene(
        tmp.write(name + ".json", R"({"type": "voxel", "textures": [{"name": "bricks", "file": ")" +
                                      dir + R"(bricks.png")" + textureExtra + R"(}],
        "world": {"source": "empty", "size": [8, 8, 8], "shapes": [
                  {"type": "box", "min": [0, 0, 0], "max": [8, 1, 8], "texture": "bricks"}]},
        "camera": {"position": [4, 4, -4], "look_at": [4, 0, 4]})" +
                                      extra + "}"));
}

TEST(RenderImage, SceneFieldsForFilteringAndSamples) {
    const test::TempDir tmp;
    const std::string dir = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/textures/";
    auto scene = sceneWith(tmp, "ok", R"(, "normal_map": ")" + dir + R"(bricks_normal.png")",
                           R"(, "render": {"samples": 9, "texture_filter": "anisotropic",
                                 "anisotropy": 8, "normal_maps": false})");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->shading.samplesPerPixel, 9);
    EXPECT_EQ(scene->shading.textureFilter, TextureFilter::Anisotropic);
    EXPECT_EQ(scene->shading.maxAnisotropy, 8);
    EXPECT_FALSE(scene->shading.normalMaps);
    // The radiance cascades' adaptive samples: on by default, 0 turns them off.
    EXPECT_EQ(scene->shading.adaptiveSamples, ShadeOptions{}.adaptiveSamples);
    EXPECT_GT(ShadeOptions{}.adaptiveSamples, 1);
    auto adaptive = sceneWith(tmp, "adaptive", "",
                              R"(, "render": {"adaptive_samples": 0, "adaptive_contrast": 2.5})");
    ASSERT_TRUE(adaptive.ok()) << adaptive.error().message();
    EXPECT_EQ(adaptive->shading.adaptiveSamples, 0);
    EXPECT_EQ(adaptive->shading.adaptiveContrast, 2.5);
    ASSERT_TRUE(scene->textures.hasNormalMap(0));
    // The shipped brick normal map tilts out of mortar grooves, and is flat on a brick's face.
    int tilted = 0;
    for (const Texel& n : scene->textures[0].normals) tilted += n.b < 0.99f;
    EXPECT_GT(tilted, 40);
    EXPECT_NEAR(scene->textures.normalAt(0, 2.5f / 16, 14.5f / 16, {}, TextureFilter::Nearest).z,
                1.0f, 1e-2f);

    const struct {
        std::string textureExtra, extra, expected;
    } bad[] = {
        {"", R"(, "render": {"samples": 0})", "render.samples"},
        {"", R"(, "render": {"samples": 1000})", "render.samples"},
        {"", R"(, "render": {"adaptive_samples": -1})", "render.adaptive_samples"},
        {"", R"(, "render": {"adaptive_samples": 257})", "render.adaptive_samples"},
        {"", R"(, "render": {"adaptive_samples": 2.5})", "render.adaptive_samples"},
        {"", R"(, "render": {"adaptive_contrast": 0})", "render.adaptive_contrast"},
        {"", R"(, "render": {"adaptive_contrast": "high"})", "render.adaptive_contrast"},
        {"", R"(, "render": {"texture_filter": "bilinear"})", "render.texture_filter"},
        {"", R"(, "render": {"anisotropy": 0})", "render.anisotropy"},
        {"", R"(, "render": {"normal_maps": 1})", "render.normal_maps"},
        {R"(, "normal_map": 3)", "", "textures[0].normal_map"},
        {R"(, "normal_map": "missing.png")", "", "textures[0].normal_map"},
        // A normal map must have its texture's size (16x16 here).
        {R"(, "normal_map": ")" + std::string(LUXEL_SOURCE_DIR) + R"(/docs/images/garden.png")", "",
         "the normal map of texture 'bricks' is 960x540, the texture 16x16"},
    };
    int i = 0;
    for (const auto& c : bad) {
        auto s = sceneWith(tmp, "bad" + std::to_string(i++), c.textureExtra, c.extra);
        ASSERT_FALSE(s.ok()) << c.expected;
        EXPECT_NE(s.error().message().find(c.expected), std::string::npos) << s.error().message();
        // The file is named too.
        if (c.expected.starts_with("render.adaptive")) {
            EXPECT_NE(s.error().message().find("bad" + std::to_string(i - 1) + ".json"),
                      std::string::npos)
                << s.error().message();
        }
    }
}

}  // namespace
}  // namespace luxel::voxel
