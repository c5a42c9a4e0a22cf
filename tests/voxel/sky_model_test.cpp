// Voxel scenes' sky models: the gradient and the CIE standard overcast sky in the scene file
// (top = zenith, horizon = zenith / 3), each bad "sky" refused with a located error naming the
// field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/voxel/sky_model.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {
namespace {

const char* kPath = "t/sky.json";

Result<VoxelScene> sceneWithSky(const std::string& sky) {
    return parseVoxelScene(R"({"type": "voxel", "world": {"source": "empty", "size": [4, 4, 4]},
        "camera": {"position": [2, 2, -4]},
        "sky": )" + sky + "}",
                           kPath);
}

TEST(SkyModel, CieOvercastIsTheGradientFromZenithToAThirdOfIt) {
    const SkyGradient g = cieOvercastSky({0.9f, 1.2f, 3.0f});
    EXPECT_EQ(g.top, (Rgb{0.9f, 1.2f, 3.0f}));
    EXPECT_FLOAT_EQ(g.horizon.r, 0.3f);
    EXPECT_FLOAT_EQ(g.horizon.g, 0.4f);
    EXPECT_FLOAT_EQ(g.horizon.b, 1.0f);
    // L(θ) = Lz (1 + 2 cos θ) / 3 at 60° from the zenith is 2 Lz / 3.
    ShadeOptions o;
    o.skyTop = g.top;
    o.skyHorizon = g.horizon;
    const Rgb at60 = skyColor({std::sqrt(3.0) / 2.0, 0.5, 0.0}, o);
    EXPECT_NEAR(at60.b, 2.0, 1e-6);
}

TEST(SkyModel, SceneReadsTheGradientAndTheOvercastPreset) {
    auto overcast = sceneWithSky(R"({"model": "cie-overcast", "zenith": [1.5, 3, 6]})");
    ASSERT_TRUE(overcast.ok()) << overcast.error().message();
    EXPECT_EQ(overcast->shading.skyTop, (Rgb{1.5f, 3.0f, 6.0f}));
    EXPECT_FLOAT_EQ(overcast->shading.skyHorizon.r, 0.5f);
    EXPECT_FLOAT_EQ(overcast->shading.skyHorizon.g, 1.0f);
    EXPECT_FLOAT_EQ(overcast->shading.skyHorizon.b, 2.0f);

    for (const char* sky :
         {R"({"top": [0.1, 0.2, 0.3], "horizon": [1, 1, 1]})",
          R"({"model": "gradient", "top": [0.1, 0.2, 0.3], "horizon": [1, 1, 1]})"}) {
        auto gradient = sceneWithSky(sky);
        ASSERT_TRUE(gradient.ok()) << gradient.error().message();
        EXPECT_EQ(gradient->shading.skyTop, (Rgb{0.1f, 0.2f, 0.3f}));
        EXPECT_EQ(gradient->shading.skyHorizon, Rgb(1.0f));
    }
    // A gradient field left out keeps its default.
    auto topOnly = sceneWithSky(R"({"top": [2, 2, 2]})");
    ASSERT_TRUE(topOnly.ok()) << topOnly.error().message();
    EXPECT_EQ(topOnly->shading.skyTop, Rgb(2.0f));
    EXPECT_EQ(topOnly->shading.skyHorizon, ShadeOptions{}.skyHorizon);
}

TEST(SkyModel, BadSkiesAreRefusedNamingTheField) {
    struct Case {
        const char* sky;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"model": "clear"})",
         "sky.model: unknown sky model 'clear' (known: gradient, "
         "cie-overcast)"},
        {R"({"model": 3})", "sky.model: must be a string"},
        {R"({"model": "cie-overcast"})", "sky.zenith: required field is missing"},
        {R"({"model": "cie-overcast", "zenith": [1, -0.5, 1]})", "sky.zenith[1]: must be in"},
        {R"({"model": "cie-overcast", "zenith": [1, 1]})", "sky.zenith: must be an array of 3"},
        {R"({"model": "cie-overcast", "zenith": [1, NaN, 1]})", "invalid JSON"},
        {R"({"model": "cie-overcast", "zenith": [1, 1, 1], "top": [1, 1, 1]})",
         "sky.top: the \"cie-overcast\" model takes \"zenith\" alone"},
        {R"({"model": "cie-overcast", "horizon": [1, 1, 1], "zenith": [1, 1, 1]})",
         "sky.horizon: the \"cie-overcast\" model takes \"zenith\" alone"},
        {R"({"zenith": [1, 1, 1]})", "sky.zenith: only the \"cie-overcast\" model takes"},
        {R"({"model": "gradient", "top": [1, 1, 1], "zenith": [1, 1, 1]})",
         "sky.zenith: only the \"cie-overcast\" model takes"},
        {R"({"modell": "cie-overcast"})", "unknown field 'modell'"},
    };
    for (const Case& c : cases) {
        auto scene = sceneWithSky(c.sky);
        ASSERT_FALSE(scene.ok()) << c.sky;
        const std::string message = scene.error().message();
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
        // Located in the file: "t/sky.json:LINE:COLUMN: ...", the sky on line 3.
        EXPECT_EQ(message.rfind(std::string(kPath) + ":3:", 0), 0u) << message;
    }
}

}  // namespace
}  // namespace luxel::voxel
