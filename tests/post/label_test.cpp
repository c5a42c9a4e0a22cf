// Text labels (post/label.h): glyph pixels land inside the text's box, scale as asked, and a label
// never spills out of its panel.
#include "luxel/post/label.h"

#include <gtest/gtest.h>

#include <string>

namespace luxel::post {
namespace {

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inclusive bounds of the set pixels
    int count = 0;
};

Box litPixels(const Image& image, int fromX = 0, int toX = -1) {
    Box box;
    if (toX < 0) toX = image.width();
    for (int y = 0; y < image.height(); ++y) {
        for (int x = fromX; x < toX; ++x) {
            if (image.at(x, y, 0) <= 0.5f) continue;
            box.x0 = std::min(box.x0, x);
            box.y0 = std::min(box.y0, y);
            box.x1 = std::max(box.x1, x);
            box.y1 = std::max(box.y1, y);
            ++box.count;
        }
    }
    return box;
}

TEST(Label, GlyphPixelsLandInsideTheTextBox) {
    Image image(80, 40, 3);
    const std::size_t set = drawText(image, 10, 5, "Hi 42", Rgb(1.0f));
    const Box box = litPixels(image);
    ASSERT_GT(box.count, 20);
    EXPECT_GE(set, static_cast<std::size_t>(box.count));  // strokes may cross
    EXPECT_GE(box.x0, 10);
    EXPECT_GE(box.y0, 5);
    EXPECT_LT(box.x1, 10 + textWidth("Hi 42"));
    EXPECT_LT(box.y1, 5 + kTextLineHeight);
    // 'H' starts at the left of its cell, and its uprights span several rows.
    EXPECT_LE(box.x0, 11);
    EXPECT_GE(box.y1 - box.y0, 5);
}

TEST(Label, ScaleTwoDoublesEverySide) {
    Image one(100, 40, 3), two(100, 40, 3);
    drawText(one, 0, 0, "A", Rgb(1.0f), 1);
    drawText(two, 0, 0, "A", Rgb(1.0f), 2);
    const Box a = litPixels(one), b = litPixels(two);
    EXPECT_EQ(b.count, 4 * a.count);
    EXPECT_EQ(b.x1 + 1, 2 * (a.x1 + 1));
    EXPECT_EQ(b.y1 + 1, 2 * (a.y1 + 1));
    EXPECT_EQ(textWidth("A", 2), 2 * textWidth("A", 1));
}

TEST(Label, TextOutsideTheImageIsClippedAndOddCharactersAreSafe) {
    Image image(8, 8, 3);
    drawText(image, -3, -4, "W\x01\xff\n\t", Rgb(1.0f));  // must not read or write out of bounds
    Image empty(8, 8, 3);
    EXPECT_EQ(drawText(empty, 100, 100, "far away", Rgb(1.0f)), 0u);
}

TEST(Label, FitTextCutsLongLinesWithDots) {
    EXPECT_EQ(fitText("short", 1000), "short");
    const std::string cut = fitText("a rather long caption", 40);
    EXPECT_LE(textWidth(cut), 40);
    EXPECT_EQ(cut.substr(cut.size() - 2), "..");
    EXPECT_EQ(fitText("line one\nline two", 1000), "line one\nline two");
    EXPECT_EQ(fitText("wide", 1), "");
}

TEST(Label, PanelLabelsStayInsideNarrowPanels) {
    // Three panels of 30 px with 4 px gaps, each with a caption far wider than the panel.
    Image image(98, 40, 3);
    image.fill(0.0f);
    for (int i = 0; i < 3; ++i) {
        drawPanelLabel(image, i * 34, 30, "reference\n1024 rays, 59.2 s, rel. L1 0.0312");
    }
    for (int gap : {30, 64}) {
        for (int x = gap; x < gap + 4; ++x) {
            for (int y = 0; y < image.height(); ++y) {
                ASSERT_EQ(image.rgb(x, y), Rgb(0.0f)) << "x " << x << " y " << y;
            }
        }
    }
    for (int i = 0; i < 3; ++i) {
        const Box box = litPixels(image, i * 34, i * 34 + 30);
        EXPECT_GT(box.count, 0) << "panel " << i;
    }
    // A wide panel gets the large text; the caption fits without being cut.
    Image wide(600, 60, 3);
    drawPanelLabel(wide, 0, 600, "reference\n1024 rays");
    const Box big = litPixels(wide);
    EXPECT_GE(big.y1 - big.y0, 2 * kTextLineHeight);  // two lines at scale 2
    EXPECT_LT(big.x1, 4 + textWidth("reference\n1024 rays", 2));
}

TEST(Label, PanelsOfOneGridShareTheLargestScaleThatFitsThemAll) {
    const std::string shortText = "hrc", longText = "1753 ms, rel. L1 0.0535";
    const int width = textWidth(longText, 2);  // the long caption fits at scale 1 only
    EXPECT_EQ(panelLabelScale({shortText}, width), 2);
    EXPECT_EQ(panelLabelScale({shortText, longText}, width), 1);
    EXPECT_EQ(panelLabelScale({shortText, longText}, width + 8), 2);
}

TEST(Label, PanelLabelDarkensItsBoxOnly) {
    Image image(200, 100, 3);
    image.fill(0.8f);
    drawPanelLabel(image, 0, 200, "hrc");
    EXPECT_NEAR(image.at(1, 1, 0), 0.2f, 1e-6);  // the box, darkened
    EXPECT_EQ(image.at(199, 99, 0), 0.8f);       // far from it, untouched
}

}  // namespace
}  // namespace luxel::post
