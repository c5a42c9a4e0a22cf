// The one WxH parser of the CLI, the viewer and the benches.
#include "luxel/core/image_size.h"

#include <gtest/gtest.h>

namespace luxel {
namespace {

TEST(ImageSize, ParsesWidthByHeight) {
    EXPECT_EQ(*parseImageSize("640x480", "--size"), (ImageSize{640, 480}));
    EXPECT_EQ(*parseImageSize("1X65536", "--size"), (ImageSize{1, kMaxImageSide}));
}

TEST(ImageSize, RejectsMalformedTextNamingTheOption) {
    for (const char* bad : {"", "640", "640x", "x480", "640x480x2", "640 x480", "-5x5", "+5x5",
                            "5.5x5", "5x5 ", "axb", "99999999999999x1"}) {
        auto size = parseImageSize(bad, "--window");
        ASSERT_FALSE(size.ok()) << bad;
        EXPECT_NE(size.error().message().find("--window '"), std::string::npos)
            << size.error().message();
    }
}

TEST(ImageSize, OneLimitForEverySide) {
    for (const char* bad : {"0x5", "5x0", "65537x1", "1x65537"}) {
        auto size = parseImageSize(bad, "--size");
        ASSERT_FALSE(size.ok()) << bad;
        EXPECT_NE(size.error().message().find("each side must be in 1..65536"), std::string::npos)
            << size.error().message();
    }
}

TEST(ImageSize, ListsTakeSquareShorthandAndRejectEmptyEntries) {
    auto sizes = parseImageSizeList("256,320x180,1024", "--sizes");
    ASSERT_TRUE(sizes.ok()) << sizes.error().message();
    EXPECT_EQ(*sizes, (std::vector<ImageSize>{{256, 256}, {320, 180}, {1024, 1024}}));
    for (const char* bad : {"", "256,", ",256", "256,,512", "256;512", "0", "70000"}) {
        EXPECT_FALSE(parseImageSizeList(bad, "--sizes").ok()) << bad;
    }
}

}  // namespace
}  // namespace luxel
