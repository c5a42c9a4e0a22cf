// Face textures: texel lookup at face corners, PNG decoding (sRGB colour, linear alpha), limits.
#include "luxel/voxel/texture_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "luxel/core/image_io.h"
#include "luxel/core/tonemap.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

// A w x h texture whose texel at (column, row) is (column, row, 0, 1).
Texture indexTexture(const std::string& name, int w, int h) {
    Texture t{name, w, h, {}, std::nullopt};
    for (int row = 0; row < h; ++row) {
        for (int column = 0; column < w; ++column) {
            t.texels.push_back({float(column), float(row), 0.0f, 1.0f});
        }
    }
    return t;
}

TEST(TextureSet, LookupAtFaceUvCorners) {
    TextureSet set;
    ASSERT_EQ(set.add(indexTexture("t", 4, 2)).value(), 0);
    const float justBelowOne = std::nextafter(1.0f, 0.0f);
    // v = 0 is the bottom row of the image (the last one), v -> 1 the top row (row 0).
    EXPECT_EQ(set.lookup(0, 0.0f, 0.0f), (Texel{0, 1, 0, 1}));
    EXPECT_EQ(set.lookup(0, justBelowOne, 0.0f), (Texel{3, 1, 0, 1}));
    EXPECT_EQ(set.lookup(0, 0.0f, justBelowOne), (Texel{0, 0, 0, 1}));
    EXPECT_EQ(set.lookup(0, justBelowOne, justBelowOne), (Texel{3, 0, 0, 1}));
    // Texel boundaries: u = 0.25 starts column 1, v = 0.5 starts the upper row.
    EXPECT_EQ(set.lookup(0, 0.25f, 0.5f), (Texel{1, 0, 0, 1}));
    EXPECT_EQ(set.lookup(0, std::nextafter(0.25f, 0.0f), std::nextafter(0.5f, 0.0f)),
              (Texel{0, 1, 0, 1}));
    // Out-of-range coordinates clamp instead of reading outside.
    EXPECT_EQ(set.lookup(0, 1.0f, 1.0f), (Texel{3, 0, 0, 1}));
    EXPECT_EQ(set.lookup(0, -0.5f, -0.5f), (Texel{0, 1, 0, 1}));
}

TEST(TextureSet, KnowsWhetherAnyTexelIsACutout) {
    TextureSet set;
    EXPECT_FALSE(set.anyCutout());
    ASSERT_TRUE(set.add(indexTexture("opaque", 4, 2)).ok());
    EXPECT_FALSE(set.anyCutout());
    Texture leaf = indexTexture("leaf", 4, 2);
    leaf.texels[5].a = 0.49f;  // below 0.5: a cutout
    Texture bad = indexTexture("bad", 2, 2);
    bad.texels[0].a = 0.0f;
    bad.texels[1].r = std::nanf("");
    EXPECT_FALSE(set.add(bad).ok());  // refused textures do not count
    EXPECT_FALSE(set.anyCutout());
    ASSERT_TRUE(set.add(leaf).ok());
    EXPECT_TRUE(set.anyCutout());
}

TEST(TextureSet, MaterialByteSelectsTheSlot) {
    EXPECT_EQ(textureSlotOf(Voxel{1, 2, 3, 0}), -1);
    EXPECT_EQ(textureSlotOf(Voxel{1, 2, 3, 255}), -1);
    EXPECT_EQ(textureSlotOf(Voxel{1, 2, 3, 1}), 0);
    EXPECT_EQ(textureSlotOf(Voxel{1, 2, 3, 254}), 253);
    EXPECT_EQ(alphaForSlot(253), 254);
}

TEST(TextureSet, LimitsAndBadTextures) {
    TextureSet set;
    for (int i = 0; i < kMaxTextures; ++i) {
        ASSERT_TRUE(set.add(indexTexture(std::to_string(i), 1, 1)).ok());
    }
    auto extra = set.add(indexTexture("one too many", 1, 1));
    ASSERT_FALSE(extra.ok());
    EXPECT_NE(extra.error().message().find("at most 254"), std::string::npos);

    TextureSet other;
    ASSERT_TRUE(other.add(indexTexture("a", 2, 2)).ok());
    EXPECT_FALSE(other.add(indexTexture("a", 2, 2)).ok());  // duplicate name
    EXPECT_FALSE(other.add(indexTexture("", 2, 2)).ok());
    Texture wrongCount = indexTexture("b", 2, 2);
    wrongCount.texels.pop_back();
    EXPECT_FALSE(other.add(wrongCount).ok());
    Texture tooBig{"c", kMaxTextureSide + 1, 1, {}, std::nullopt};
    tooBig.texels.resize(kMaxTextureSide + 1);
    auto big = other.add(tooBig);
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().message().find("1..1024"), std::string::npos);
    Texture shiny = indexTexture("d", 1, 1);
    shiny.reflectivity = 1.5f;
    EXPECT_FALSE(other.add(shiny).ok());
    Texture nan = indexTexture("e", 1, 1);
    nan.texels[0].g = std::nanf("");
    EXPECT_FALSE(other.add(nan).ok());
    EXPECT_EQ(other.size(), 1);
}

TEST(TextureSet, PngColourIsDecodedAndAlphaIsLinear) {
    const test::TempDir tmp;
    Image rgba(2, 1, 4);
    rgba.at(0, 0, 0) = srgbToLinear(128 / 255.0f);
    rgba.at(0, 0, 3) = 1.0f;
    rgba.at(1, 0, 1) = 1.0f;
    rgba.at(1, 0, 3) = 102 / 255.0f;  // 0.4: a cutout
    const std::string path = tmp.path("rgba.png");
    ASSERT_TRUE(writePng(path, rgba).ok());
    auto t = TextureSet::load("rgba", path);
    ASSERT_TRUE(t.ok()) << t.error().message();
    ASSERT_EQ(t->width, 2);
    EXPECT_NEAR(t->texels[0].r, srgbToLinear(128 / 255.0f), 1e-6);
    EXPECT_EQ(t->texels[0].a, 1.0f);
    EXPECT_NEAR(t->texels[1].a, 0.4f, 1e-6);
    EXPECT_TRUE(t->texels[1].cutout());
    EXPECT_FALSE(t->texels[0].cutout());

    Image grey(1, 1, 1);
    grey.at(0, 0, 0) = 0.25f;
    const std::string greyPath = tmp.path("grey.png");
    ASSERT_TRUE(writePng(greyPath, grey).ok());
    auto g = TextureSet::load("grey", greyPath);
    ASSERT_TRUE(g.ok()) << g.error().message();
    EXPECT_NEAR(g->texels[0].r, 0.25f, 2e-3);
    EXPECT_EQ(g->texels[0].g, g->texels[0].r);
    EXPECT_EQ(g->texels[0].a, 1.0f);
}

TEST(TextureSet, BadPngFilesAreErrors) {
    const test::TempDir tmp;
    EXPECT_FALSE(TextureSet::load("m", tmp.path("does-not-exist.png")).ok());
    const std::string corrupt = tmp.path("corrupt.png");
    std::ofstream(corrupt) << "\x89PNG\r\n\x1a\n this is not a png";
    EXPECT_FALSE(TextureSet::load("c", corrupt).ok());
    // A header claiming 100000 x 100000 is refused before any pixel is decoded.
    const unsigned char header[] = {0x89, 'P',  'N', 'G', '\r', '\n', 0x1a, '\n', 0,    0, 0,
                                    13,   'I',  'H', 'D', 'R',  0,    1,    0x86, 0xa0, 0, 1,
                                    0x86, 0xa0, 8,   6,   0,    0,    0,    0,    0,    0, 0};
    const std::string huge = tmp.path("huge.png");
    std::ofstream(huge, std::ios::binary)
        .write(reinterpret_cast<const char*>(header), sizeof(header));
    auto h = TextureSet::load("huge", huge);
    ASSERT_FALSE(h.ok());
    EXPECT_NE(h.error().message().find("100000x100000"), std::string::npos) << h.error().message();
}

}  // namespace
}  // namespace luxel::voxel
