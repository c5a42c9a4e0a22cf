// Adaptive supersampling of the radiance cascades' picture (src/voxel/cascades/adaptive_samples.h,
// docs/algorithms/voxel-radiance-cascades.md §4.2): the rule that picks the pixels on images made
// here, then the picture of a one-voxel lamp in a dark room, where one ray per pixel centre
// aliases the lamp's silhouette: with the adaptive pass the 8 x 8 block means come close to a
// 64-sample picture's, for a few pixels' extra rays, and a picture without strong contrast
// refines nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "luxel/post/gi_measures.h"
#include "luxel/voxel/path_trace_sums.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/cascades/adaptive_samples.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;
using cascades::adaptivePixels;

Image grey(int width, int height, float value) {
    Image image(width, height, 3);
    for (std::size_t i = 0; i < image.size(); ++i) image.data()[i] = value;
    return image;
}

void setPixel(Image& image, int x, int y, float value) {
    for (int c = 0; c < 3; ++c) image.at(x, y, c) = value;
}

TEST(AdaptiveSamples, UniformAndSmoothImagesRefineNothing) {
    EXPECT_TRUE(adaptivePixels(grey(32, 24, 0.3f), 1.0).empty());
    EXPECT_TRUE(adaptivePixels(grey(32, 24, 0.0f), 1.0).empty());  // black: no mean to scale by
    // A ramp from 0 to 1 across the image: neighbours differ by 1/31 of it, the mean is 0.5.
    Image ramp(32, 24, 3);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) setPixel(ramp, x, y, float(x) / 31.0f);
    EXPECT_TRUE(adaptivePixels(ramp, 1.0).empty());
    EXPECT_TRUE(adaptivePixels(ramp, 0.1).empty());
    // At a contrast below 1/31 / 0.5 every pixel differs enough from a neighbour.
    EXPECT_EQ(adaptivePixels(ramp, 0.05, 1.0).size(), std::size_t(32 * 24));
}

TEST(AdaptiveSamples, ABrightPixelRefinesItselfAndItsEightNeighbours) {
    Image image = grey(32, 24, 0.1f);
    setPixel(image, 10, 7, 50.0f);
    const std::vector<std::uint32_t> pixels = adaptivePixels(image, 1.0);
    std::vector<std::uint32_t> expected;
    for (int y = 6; y <= 8; ++y)
        for (int x = 9; x <= 11; ++x) expected.push_back(std::uint32_t(y * 32 + x));
    EXPECT_EQ(pixels, expected);  // ascending, the 3 x 3 block
    // At a corner only the neighbours inside the image.
    Image corner = grey(32, 24, 0.1f);
    setPixel(corner, 0, 0, 50.0f);
    EXPECT_EQ(adaptivePixels(corner, 1.0), (std::vector<std::uint32_t>{0, 1, 32, 33}));
    // A NaN counts as black: one dark pixel (a difference of about the mean), not an infinite
    // difference that outranks every other.
    Image nan = grey(32, 24, 0.1f);
    setPixel(nan, 5, 5, std::nanf(""));
    EXPECT_EQ(adaptivePixels(nan, 0.9).size(), std::size_t(9));
    EXPECT_TRUE(adaptivePixels(nan, 1.5).empty());
}

TEST(AdaptiveSamples, TheCapKeepsTheLargestDifferences) {
    // A checkerboard of 0 and 1 (every pixel differs by 1 from a neighbour, the mean 0.5) with
    // one pixel of 3: above the cap, that pixel and its neighbours (difference 2 or 3) first,
    // then the lowest indices.
    Image board(16, 16, 3);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) setPixel(board, x, y, float((x + y) % 2));
    setPixel(board, 8, 8, 3.0f);
    const std::vector<std::uint32_t> all = adaptivePixels(board, 1.0, 1.0);
    EXPECT_EQ(all.size(), std::size_t(256));
    const std::vector<std::uint32_t> capped = adaptivePixels(board, 1.0, 16.0 / 256.0);
    ASSERT_EQ(capped.size(), std::size_t(16));
    EXPECT_TRUE(std::is_sorted(capped.begin(), capped.end()));
    for (int y = 7; y <= 9; ++y)
        for (int x = 7; x <= 9; ++x) {
            EXPECT_TRUE(std::binary_search(capped.begin(), capped.end(), std::uint32_t(y * 16 + x)))
                << x << "," << y;
        }
    // The 7 others: the lowest indices among the rest.
    EXPECT_EQ(std::vector<std::uint32_t>(capped.begin(), capped.begin() + 7),
              (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
    // The default cap: a share of the pixels.
    EXPECT_EQ(adaptivePixels(board, 1.0).size(), std::size_t(256 * cascades::kAdaptiveMaxShare));
}

// The rule as written in adaptive_samples.h, pixel by pixel: every neighbour looked up with a
// bounds test, the cap by a sort of all the candidates.
std::vector<std::uint32_t> adaptivePixelsByTheRule(const Image& picture, double contrast,
                                                   double maxShare) {
    const int width = picture.width(), height = picture.height();
    const auto luminance = [&](int x, int y) {
        const double l =
            pathLuminance(Rgb(picture.at(x, y, 0), picture.at(x, y, 1), picture.at(x, y, 2)));
        return std::isfinite(l) ? float(l) : 0.0f;
    };
    double sum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) sum += luminance(x, y);
    const double mean = sum / (double(width) * height);
    if (!(mean > 0.0)) return {};
    std::vector<std::pair<float, std::uint32_t>> over;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float largest = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    largest = std::max(largest, std::abs(luminance(x, y) - luminance(nx, ny)));
                }
            if (largest > float(contrast * mean)) {
                over.push_back({largest, std::uint32_t(std::size_t(y) * width + x)});
            }
        }
    const std::size_t cap = std::size_t(maxShare * double(width) * height);
    if (over.size() > cap) {
        std::sort(over.begin(), over.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first > b.first : a.second < b.second;
        });
        over.resize(cap);
    }
    std::vector<std::uint32_t> out;
    for (const auto& [difference, pixel] : over) out.push_back(pixel);
    std::sort(out.begin(), out.end());
    return out;
}

TEST(AdaptiveSamples, MatchesTheRulePixelByPixelOnRandomImages) {
    // Sizes down to one pixel and one row or column (every pixel on an edge), random levels with
    // repeated values (ties at the cap), a few non-finite pixels (black to the rule), contrasts
    // that refine few or many and caps that bind or not.
    std::uint32_t state = 12345u;
    const auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    };
    const int sizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {3, 5}, {37, 23}, {64, 48}};
    for (const auto& size : sizes) {
        for (const double contrast : {0.0, 0.5, 2.0}) {
            for (const double maxShare : {1.0, 1.0 / 32.0, 0.2}) {
                Image image(size[0], size[1], 3);
                for (int y = 0; y < size[1]; ++y)
                    for (int x = 0; x < size[0]; ++x) {
                        for (int c = 0; c < 3; ++c) {
                            image.at(x, y, c) = float(next() % 5) * 0.25f;
                        }
                        if (next() % 97 == 0) image.at(x, y, next() % 3) = std::nanf("");
                        if (next() % 89 == 0) image.at(x, y, 0) = INFINITY;
                    }
                EXPECT_EQ(adaptivePixels(image, contrast, maxShare),
                          adaptivePixelsByTheRule(image, contrast, maxShare))
                    << size[0] << "x" << size[1] << " contrast " << contrast << " cap " << maxShare;
            }
        }
    }
}

TEST(AdaptiveSamples, OnlyWhenMoreThanTheFirstPass) {
    ShadeOptions o;
    o.samplesPerPixel = 1;
    o.adaptiveSamples = 16;
    EXPECT_EQ(cascades::adaptiveSamples(o), 16);
    o.adaptiveSamples = 0;
    EXPECT_EQ(cascades::adaptiveSamples(o), 0);
    o.adaptiveSamples = 4;
    o.samplesPerPixel = 4;
    EXPECT_EQ(cascades::adaptiveSamples(o), 0);
    o.adaptiveSamples = 1000;
    EXPECT_EQ(cascades::adaptiveSamples(o), kMaxSamplesPerPixel);
}

// A closed 14-voxel grey room (walls one voxel thick) lit by one bright voxel in the air.
constexpr Int3 kLamp{7, 5, 8};
constexpr int kWidth = 96, kHeight = 72;

struct LampRoom : ClosedLampRoom {
    LampRoom() : ClosedLampRoom(kLamp, 0.5f, Rgb(40.0f, 30.0f, 20.0f)) {}
};

// Off the lamp's axes, so its silhouette crosses pixels at many fractions; the lamp about 7
// pixels wide.
Camera lampCamera() {
    return *Camera::lookAt({3.31, 7.83, 2.17}, {7.46, 5.41, 8.52}, 60.0, kWidth, kHeight);
}

struct Drawn {
    Image picture;
    int refined = 0;
};

Drawn draw(const LampRoom& room, int samples, int adaptive) {
    ShadeOptions o = room.o;
    o.samplesPerPixel = samples;
    o.adaptiveSamples = adaptive;
    auto cascades = RadianceCascades::create(room.world, nullptr, o);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    if (!cascades.ok()) return {};
    cascades->solve();
    Drawn d;
    auto image = cascades->render(lampCamera(), &d.refined);
    EXPECT_TRUE(image.ok()) << image.error().message();
    if (image.ok()) d.picture = std::move(*image);
    return d;
}

double meanOf(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return sum / double(image.size());
}

// The RMSE of the 8 x 8 block means over the reference's mean (compare-solvers' low-frequency
// error).
double lowFrequencyError(const Image& image, const Image& reference) {
    const Image a = post::blockMeans(image), b = post::blockMeans(reference);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = double(a.data()[i]) - b.data()[i];
        sum += d * d;
    }
    return std::sqrt(sum / double(a.size())) / meanOf(reference);
}

TEST(CascadesAdaptiveSamples, LampSilhouetteComesCloseToManySamples) {
    const LampRoom room;
    const Drawn one = draw(room, 1, 0), adaptive = draw(room, 1, 16), many = draw(room, 64, 0);
    ASSERT_FALSE(many.picture.empty());
    const double oneError = lowFrequencyError(one.picture, many.picture);
    const double adaptiveError = lowFrequencyError(adaptive.picture, many.picture);
    const double share = double(adaptive.refined) / (kWidth * kHeight);
    std::printf("against 64 samples: 1 sample %.2f%%, 1 + 16 adaptive %.2f%% (%d pixels, %.2f%%)\n",
                100 * oneError, 100 * adaptiveError, adaptive.refined, 100 * share);
    EXPECT_EQ(one.refined, 0);
    EXPECT_EQ(many.refined, 0);
    // The centres alias the lamp's edge: a sizeable error at the blocks' scale...
    EXPECT_GT(oneError, 0.05);
    // ...that the refined pixels mostly remove, for a small share of the pixels (measured: 8.1%
    // and 2.6%, 1.3% of the pixels).
    EXPECT_LT(adaptiveError, 0.4 * oneError);
    EXPECT_GT(adaptive.refined, 0);
    EXPECT_LT(share, 0.03);
}

// Every refined pixel is on the lamp's silhouette: its centre ray or a neighbour's meets the
// lamp, the rest of the room (smoothly lit walls, their corners) is not drawn again. And the
// count render() reports is the rule's on its first pass.
TEST(CascadesAdaptiveSamples, OnlyTheLampsSilhouetteIsRefined) {
    const LampRoom room;
    const Drawn one = draw(room, 1, 0), adaptive = draw(room, 1, 16);
    ASSERT_FALSE(adaptive.picture.empty());
    const std::vector<std::uint32_t> pixels = adaptivePixels(one.picture, room.o.adaptiveContrast);
    EXPECT_EQ(int(pixels.size()), adaptive.refined);
    const Camera camera = lampCamera();
    const auto seesLamp = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return false;
        const Hit h =
            castToSurface(room.world, nullptr, camera.rayAt(x + 0.5, y + 0.5), room.o.stepCap).hit;
        return h.hit && h.voxel == kLamp;
    };
    int lampPixels = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) lampPixels += seesLamp(x, y);
    EXPECT_GT(lampPixels, 10);
    for (std::uint32_t p : pixels) {
        const int x = int(p % kWidth), y = int(p / kWidth);
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) near = near || seesLamp(x + dx, y + dy);
        EXPECT_TRUE(near) << "pixel " << x << "," << y << " refined away from the lamp";
    }
    // Pixels not refined keep the first pass's value exactly.
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (std::binary_search(pixels.begin(), pixels.end(), std::uint32_t(y * kWidth + x)))
                continue;
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(adaptive.picture.at(x, y, c), one.picture.at(x, y, c)) << x << "," << y;
            }
        }
}

// A sky-lit floor seen from above has no strong contrast: the adaptive pass draws nothing again
// and costs nothing.
TEST(CascadesAdaptiveSamples, SmoothPictureRefinesNothing) {
    const VoxelWorld world = floorWorld();
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(1.0f, 0.9f, 0.8f));
    o.adaptiveSamples = 16;
    auto cascades = RadianceCascades::create(world, nullptr, o);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    cascades->solve();
    const Int3 size = world.size();
    const Camera camera = *Camera::lookAt({size.x * 0.5 + 0.3, 1.9, size.z * 0.5 - 0.2},
                                          {size.x * 0.5, 1.0, size.z * 0.5}, 40.0, 48, 36);
    int refined = -1;
    auto image = cascades->render(camera, &refined);
    ASSERT_TRUE(image.ok()) << image.error().message();
    EXPECT_GT(meanOf(*image), 0.0);
    EXPECT_EQ(refined, 0);
}

}  // namespace
