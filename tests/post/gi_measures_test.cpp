// The GI measures of compare-solvers (docs/voxel-gi-measures.md): block means, the leak into the
// reference's dark region and the flicker of a solver's low-frequency image as the sun moves.
#include "luxel/post/gi_measures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using luxel::Image;
using luxel::post::blockMeans;
using luxel::post::darkRegionLeak;
using luxel::post::sunFlicker;

Image filled(int w, int h, float value) {
    Image image(w, h, 3);
    image.fill(value);
    return image;
}

// 32 x 16 px (4 x 2 blocks): the left half at 1, the right half at 0.01 (mean 0.505, so the
// right half's four blocks are below 10% of it).
Image halfLit() {
    Image image = filled(32, 16, 1.0f);
    for (int y = 0; y < 16; ++y)
        for (int x = 16; x < 32; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.01f;
    return image;
}

TEST(GiMeasures, BlockMeansAverageEachBlockIncludingPartialOnes) {
    Image image(10, 9, 1);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 10; ++x) image.at(x, y, 0) = static_cast<float>(x);
    const Image blocks = blockMeans(image, 8);
    ASSERT_EQ(blocks.width(), 2);
    ASSERT_EQ(blocks.height(), 2);
    EXPECT_FLOAT_EQ(blocks.at(0, 0, 0), 3.5f);  // columns 0..7
    EXPECT_FLOAT_EQ(blocks.at(1, 0, 0), 8.5f);  // the partial block: columns 8, 9
    EXPECT_FLOAT_EQ(blocks.at(1, 1, 0), 8.5f);  // and its one row
}

TEST(GiMeasures, ASolverEqualToTheReferenceLeaksNothing) {
    const Image reference = halfLit();
    auto leak = darkRegionLeak(reference, reference);
    ASSERT_TRUE(leak.ok()) << leak.error().message();
    EXPECT_EQ(leak->blocks, 8u);
    EXPECT_EQ(leak->darkBlocks, 4u);
    EXPECT_NEAR(leak->referenceMean, 0.505, 1e-6);
    EXPECT_NEAR(leak->referenceDark, 0.01, 1e-6);
    EXPECT_EQ(leak->leak, 0.0);
}

TEST(GiMeasures, LightAddedInTheDarkRegionIsTheLeakOverTheImageMean) {
    const Image reference = halfLit();
    Image solver = reference;
    for (int y = 0; y < 16; ++y)
        for (int x = 16; x < 32; ++x)
            for (int c = 0; c < 3; ++c) solver.at(x, y, c) += 0.2f;
    auto leak = darkRegionLeak(solver, reference);
    ASSERT_TRUE(leak.ok()) << leak.error().message();
    EXPECT_NEAR(leak->solverDark, 0.21, 1e-6);
    EXPECT_NEAR(leak->leak, 0.2 / 0.505, 1e-6);
    // Light in one of the four dark blocks counts a quarter.
    Image oneBlock = reference;
    for (int y = 0; y < 8; ++y)
        for (int x = 16; x < 24; ++x)
            for (int c = 0; c < 3; ++c) oneBlock.at(x, y, c) += 0.2f;
    EXPECT_NEAR(darkRegionLeak(oneBlock, reference)->leak, 0.05 / 0.505, 1e-6);
}

TEST(GiMeasures, LightAddedWhereTheReferenceIsBrightIsNoLeak) {
    const Image reference = halfLit();
    Image solver = reference;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) solver.at(x, y, 1) += 5.0f;
    EXPECT_EQ(darkRegionLeak(solver, reference)->leak, 0.0);
    // A darker solver leaks negatively, at most the dark region's own light.
    Image dark = reference;
    dark.fill(0.0f);
    EXPECT_NEAR(darkRegionLeak(dark, reference)->leak, -0.01 / 0.505, 1e-6);
}

TEST(GiMeasures, LeakOfABlackOrUniformReferenceIsZero) {
    auto black = darkRegionLeak(filled(16, 16, 1.0f), filled(16, 16, 0.0f));
    ASSERT_TRUE(black.ok());
    EXPECT_EQ(black->leak, 0.0);
    auto uniform = darkRegionLeak(filled(16, 16, 3.0f), filled(16, 16, 1.0f));
    ASSERT_TRUE(uniform.ok());
    EXPECT_EQ(uniform->darkBlocks, 0u);
    EXPECT_EQ(uniform->leak, 0.0);
}

TEST(GiMeasures, LeakRefusesMismatchedImagesAndBadFractions) {
    auto sizes = darkRegionLeak(filled(16, 16, 1.0f), filled(16, 8, 1.0f));
    ASSERT_FALSE(sizes.ok());
    EXPECT_NE(sizes.error().message().find("16x16 with 3 channels vs 16x8"), std::string::npos)
        << sizes.error().message();
    EXPECT_FALSE(darkRegionLeak(halfLit(), halfLit(), 0.0).ok());
    EXPECT_FALSE(darkRegionLeak(halfLit(), halfLit(), std::nan("")).ok());
}

// Reference frames brightening by 0.1 a frame: 1, 1.1, 1.2, 1.3 (mean 1.15).
std::vector<Image> brighteningFrames() {
    std::vector<Image> frames;
    for (int k = 0; k < 4; ++k) frames.push_back(filled(24, 16, 1.0f + 0.1f * k));
    return frames;
}

TEST(GiMeasures, ASolverEqualToTheReferenceDoesNotFlicker) {
    const std::vector<Image> reference = brighteningFrames();
    auto flicker = sunFlicker(reference, reference);
    ASSERT_TRUE(flicker.ok()) << flicker.error().message();
    EXPECT_EQ(flicker->flicker, 0.0);
    EXPECT_NEAR(flicker->referenceMean, 1.15, 1e-6);
    EXPECT_NEAR(flicker->referenceChange, 0.1 / 1.15, 1e-6);
    // A constant bias follows the reference's change: wrong, but steady.
    std::vector<Image> biased;
    for (const Image& frame : reference) {
        biased.push_back(frame);
        for (std::size_t i = 0; i < biased.back().size(); ++i) biased.back().data()[i] += 0.5f;
    }
    EXPECT_NEAR(sunFlicker(biased, reference)->flicker, 0.0, 1e-6);
}

TEST(GiMeasures, JitteringFramesFlickerByTheirJumpOverTheMean) {
    const std::vector<Image> reference = brighteningFrames();
    // Every other frame 0.05 brighter: each frame pair changes 0.05 more or less than the
    // reference's.
    std::vector<Image> jitter = reference;
    for (std::size_t k = 1; k < jitter.size(); k += 2)
        for (std::size_t i = 0; i < jitter[k].size(); ++i) jitter[k].data()[i] += 0.05f;
    EXPECT_NEAR(sunFlicker(jitter, reference)->flicker, 0.05 / 1.15, 1e-6);
    // A jump in one block of six (24 x 16 px: 3 x 2 blocks) in one of three pairs.
    std::vector<Image> jump = reference;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) jump[3].at(x, y, c) += 0.6f;
    EXPECT_NEAR(sunFlicker(jump, reference)->flicker, 0.6 / 6 / 3 / 1.15, 1e-6);
}

TEST(GiMeasures, FlickerRefusesMismatchedFrames) {
    const std::vector<Image> reference = brighteningFrames();
    const std::vector<Image> three(reference.begin(), reference.begin() + 3);
    auto count = sunFlicker(three, reference);
    ASSERT_FALSE(count.ok());
    EXPECT_NE(count.error().message().find("3 solver frames but 4 reference frames"),
              std::string::npos)
        << count.error().message();
    EXPECT_FALSE(sunFlicker(std::vector<Image>(reference.begin(), reference.begin() + 1),
                            std::vector<Image>(reference.begin(), reference.begin() + 1))
                     .ok());
    std::vector<Image> resized = reference;
    resized[2] = filled(24, 8, 1.0f);
    EXPECT_FALSE(sunFlicker(resized, reference).ok());
}

}  // namespace
