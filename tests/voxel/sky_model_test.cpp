// Voxel scenes' sky models: the gradient and the CIE standard overcast sky in the scene file
// (top = zenith, horizon = zenith / 3), the Preetham clear sky against the paper's formulas
// evaluated independently (Python, double precision) and its shape, each bad "sky" refused with a
// located error naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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

// The linear sRGB colour's CIE xyY (the inverse of sky_preetham.h's matrix, IEC 61966-2-1).
struct XyY {
    double x, y, luminance;
};
XyY xyYOf(Rgb c) {
    const double bigX = 0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b;
    const double bigY = 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b;
    const double bigZ = 0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b;
    const double sum = bigX + bigY + bigZ;
    return {bigX / sum, bigY / sum, bigY};
}

ShadeOptions preetham(float turbidity, Vec3 sun, float zenith) {
    ShadeOptions o;
    o.skyModel = ShadeOptions::SkyModel::Preetham;
    o.skyTurbidity = turbidity;
    o.sunDirection = sun;
    o.skyZenithLuminance = zenith;
    return o;
}

Vec3d direction(double elevationDegrees, double azimuthDegrees) {
    const double e = elevationDegrees * std::numbers::pi / 180.0,
                 a = azimuthDegrees * std::numbers::pi / 180.0;
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

TEST(SkyModel, PreethamMatchesThePapersFormulas) {
    // Sun straight up, T = 2: Appendix A.2's zenith chromaticity at θs = 0 is
    // (0.00394 T + 0.25886, 0.00516 T + 0.26688); the zenith's luminance is the one asked for.
    const XyY up = xyYOf(skyColor({0.0, 1.0, 0.0}, preetham(2.0f, {0.0f, 1.0f, 0.0f}, 1.5f)));
    EXPECT_NEAR(up.luminance, 1.5, 1e-5);
    EXPECT_NEAR(up.x, 0.26674, 2e-5);
    EXPECT_NEAR(up.y, 0.27720, 2e-5);
    // T = 5, sun 30° above the horizon (θs = 60°), given unnormalised.
    const XyY zenith =
        xyYOf(skyColor({0.0, 1.0, 0.0}, preetham(5.0f, {1.7320508f, 1.0f, 0.0f}, 1.0f)));
    EXPECT_NEAR(zenith.luminance, 1.0, 1e-5);
    EXPECT_NEAR(zenith.x, 0.258656, 2e-5);
    EXPECT_NEAR(zenith.y, 0.272474, 2e-5);
    // T = 3, sun 30° up towards +x, the direction 45° up and 60° round from it: Perez's
    // F(θ, γ) / F(0, θs) times the zenith's values.
    const XyY sample =
        xyYOf(skyColor(direction(45.0, 60.0), preetham(3.0f, {0.8660254f, 0.5f, 0.0f}, 0.5f)));
    EXPECT_NEAR(sample.luminance, 0.734476, 2e-5);
    EXPECT_NEAR(sample.x, 0.257034, 2e-5);
    EXPECT_NEAR(sample.y, 0.264996, 2e-5);
}

TEST(SkyModel, PreethamIsBrightAroundTheSunAndBlueAboveAndSymmetric) {
    const ShadeOptions clear = preetham(2.5f, {0.0f, 0.5f, 1.0f}, 0.4f);  // sun towards +z
    const auto luminance = [](Rgb c) { return xyYOf(c).luminance; };
    // At the sun's elevation: 10° from the sun against the opposite side of the sky.
    const double sunElevation = std::atan2(0.5, 1.0) * 180.0 / std::numbers::pi;
    const double nearSun = luminance(skyColor(direction(sunElevation, 80.0), clear));
    const double opposite = luminance(skyColor(direction(sunElevation, -90.0), clear));
    EXPECT_GT(nearSun, 3.0 * opposite);
    // Mirror images across the sun's vertical plane (x -> -x) see the same sky.
    for (double azimuth : {10.0, 45.0, 120.0}) {
        const Rgb a = skyColor(direction(20.0, 90.0 - azimuth), clear);
        const Rgb b = skyColor(direction(20.0, 90.0 + azimuth), clear);
        EXPECT_NEAR(a.r, b.r, 1e-6 * (1.0 + a.r));
        EXPECT_NEAR(a.b, b.b, 1e-6 * (1.0 + a.b));
    }
    // A clear sky is blue above; a hazy one is whiter.
    const Rgb zenithClear = skyColor({0.0, 1.0, 0.0}, clear);
    const Rgb zenithHazy = skyColor({0.0, 1.0, 0.0}, preetham(9.0f, {0.0f, 0.5f, 1.0f}, 0.4f));
    EXPECT_GT(zenithClear.b, 1.5 * zenithClear.r);
    EXPECT_LT(zenithHazy.b / zenithHazy.r, zenithClear.b / zenithClear.r);
}

TEST(SkyModel, PreethamBelowTheHorizonIsTheHorizonsAndFinite) {
    const ShadeOptions clear = preetham(3.0f, {0.2f, 0.3f, 1.0f}, 0.4f);
    for (double azimuth = -180.0; azimuth < 180.0; azimuth += 15.0) {
        const Rgb above = skyColor(direction(0.005, azimuth), clear);
        const Rgb below = skyColor(direction(-0.005, azimuth), clear);
        EXPECT_NEAR(above.g, below.g, 1e-3 * above.g) << azimuth;
        const Rgb down = skyColor(direction(-60.0, azimuth), clear);
        EXPECT_TRUE(std::isfinite(down.r) && down.r >= 0.0f && down.g > 0.0f) << azimuth;
    }
    // A sun below the horizon is taken at it: finite, and the same sky as a sun at the horizon.
    const Rgb night = skyColor(direction(40.0, 10.0), preetham(3.0f, {1.0f, -0.4f, 0.0f}, 0.4f));
    const Rgb dusk = skyColor(direction(40.0, 10.0), preetham(3.0f, {1.0f, 0.0f, 0.0f}, 0.4f));
    EXPECT_TRUE(std::isfinite(night.r) && std::isfinite(night.g) && std::isfinite(night.b));
    EXPECT_GT(night.g, 0.0f);
    // Not equal: γ still sees the sun below; finite and of the horizon sun's order.
    EXPECT_LT(std::abs(night.g - dusk.g), dusk.g);
}

TEST(SkyModel, SceneReadsThePreethamSky) {
    auto defaults = sceneWithSky(R"({"model": "preetham"})");
    ASSERT_TRUE(defaults.ok()) << defaults.error().message();
    EXPECT_EQ(defaults->shading.skyModel, ShadeOptions::SkyModel::Preetham);
    EXPECT_FLOAT_EQ(defaults->shading.skyTurbidity, 3.0f);
    EXPECT_FLOAT_EQ(defaults->shading.skyZenithLuminance, 0.4f);
    auto hazy = sceneWithSky(R"({"model": "preetham", "turbidity": 6.5, "zenith": 1.25})");
    ASSERT_TRUE(hazy.ok()) << hazy.error().message();
    EXPECT_FLOAT_EQ(hazy->shading.skyTurbidity, 6.5f);
    EXPECT_FLOAT_EQ(hazy->shading.skyZenithLuminance, 1.25f);
    auto gradient = sceneWithSky(R"({"top": [1, 1, 1]})");
    ASSERT_TRUE(gradient.ok()) << gradient.error().message();
    EXPECT_EQ(gradient->shading.skyModel, ShadeOptions::SkyModel::Gradient);
}

TEST(SkyModel, BadSkiesAreRefusedNamingTheField) {
    struct Case {
        const char* sky;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"model": "clear"})",
         "sky.model: unknown sky model 'clear' (known: gradient, "
         "cie-overcast, preetham)"},
        {R"({"model": 3})", "sky.model: must be a string"},
        {R"({"model": "cie-overcast"})", "sky.zenith: required field is missing"},
        {R"({"model": "cie-overcast", "zenith": [1, -0.5, 1]})", "sky.zenith[1]: must be in"},
        {R"({"model": "cie-overcast", "zenith": [1, 1]})", "sky.zenith: must be an array of 3"},
        {R"({"model": "cie-overcast", "zenith": [1, NaN, 1]})", "invalid JSON"},
        {R"({"model": "cie-overcast", "zenith": [1, 1, 1], "top": [1, 1, 1]})",
         "sky.top: the \"cie-overcast\" model takes \"zenith\" alone"},
        {R"({"model": "cie-overcast", "horizon": [1, 1, 1], "zenith": [1, 1, 1]})",
         "sky.horizon: the \"cie-overcast\" model takes \"zenith\" alone"},
        {R"({"zenith": [1, 1, 1]})",
         "sky.zenith: only the \"cie-overcast\" and \"preetham\" models take"},
        {R"({"model": "gradient", "top": [1, 1, 1], "zenith": [1, 1, 1]})",
         "sky.zenith: only the \"cie-overcast\" and \"preetham\" models take"},
        {R"({"modell": "cie-overcast"})", "unknown field 'modell'"},
        {R"({"model": "preetham", "turbidity": 1.5})", "sky.turbidity: must be in 2..10"},
        {R"({"model": "preetham", "turbidity": "hazy"})", "sky.turbidity: must be a number"},
        {R"({"model": "preetham", "zenith": [1, 1, 1]})",
         "sky.zenith: the \"preetham\" model takes the zenith's luminance as one number"},
        {R"({"model": "preetham", "zenith": -1})", "sky.zenith: must be in"},
        {R"({"model": "preetham", "top": [1, 1, 1]})", "sky.top: the \"preetham\" model takes"},
        {R"({"turbidity": 3})", "sky.turbidity: only the \"preetham\" model takes a turbidity"},
        {R"({"model": "cie-overcast", "zenith": [1, 1, 1], "turbidity": 3})",
         "sky.turbidity: only the \"preetham\" model takes a turbidity"},
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
