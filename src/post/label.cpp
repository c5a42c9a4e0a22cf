// Text rasterised from stb_easy_font's quads.
#include "luxel/post/label.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace luxel::post {
namespace {

// stb_easy_font indexes its tables by character - 32: anything outside ' '..'~' (and '\n')
// would read outside them.
std::string printable(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        if (c != '\n' && (c < ' ' || c > '~')) c = '?';
    }
    return out;
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines(1);
    for (char c : text) {
        if (c == '\n') {
            lines.emplace_back();
        } else {
            lines.back() += c;
        }
    }
    return lines;
}

}  // namespace

int textWidth(std::string_view text, int scale) {
    std::string copy = printable(text);
    return stb_easy_font_width(copy.data()) * std::max(scale, 1);
}

std::size_t drawText(Image& image, int x, int y, std::string_view text, Rgb colour, int scale) {
    scale = std::max(scale, 1);
    std::string copy = printable(text);
    // Each quad is 4 vertices of 16 bytes (x, y, z floats and 4 colour bytes); a glyph has at
    // most a few dozen segments.
    std::vector<char> vertices((copy.size() + 1) * 64 * 32);
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, vertices.data(),
                                          static_cast<int>(vertices.size()));
    std::size_t set = 0;
    for (int q = 0; q < quads; ++q) {
        // Corners 0 and 2 are opposite; the font's coordinates are whole units.
        float c0[2], c2[2];
        std::memcpy(c0, vertices.data() + q * 64, sizeof c0);
        std::memcpy(c2, vertices.data() + q * 64 + 32, sizeof c2);
        const int x0 = x + static_cast<int>(std::min(c0[0], c2[0])) * scale;
        const int x1 = x + static_cast<int>(std::max(c0[0], c2[0])) * scale;
        const int y0 = y + static_cast<int>(std::min(c0[1], c2[1])) * scale;
        const int y1 = y + static_cast<int>(std::max(c0[1], c2[1])) * scale;
        for (int py = std::max(y0, 0); py < std::min(y1, image.height()); ++py) {
            for (int px = std::max(x0, 0); px < std::min(x1, image.width()); ++px) {
                image.setRgb(px, py, colour);
                ++set;
            }
        }
    }
    return set;
}

std::string fitText(std::string_view text, int maxWidth, int scale) {
    std::string out;
    for (const std::string& line : splitLines(text)) {
        std::string fitted = line;
        if (textWidth(fitted, scale) > maxWidth) {
            while (!fitted.empty() && textWidth(fitted + "..", scale) > maxWidth) fitted.pop_back();
            fitted =
                fitted.empty() || textWidth(fitted + "..", scale) > maxWidth ? "" : fitted + "..";
        }
        out += fitted + '\n';
    }
    out.pop_back();  // the '\n' after the last line
    return out;
}

namespace {
constexpr int kMargin = 4;  // between a panel's edge and its caption, in pixels
}  // namespace

int panelLabelScale(const std::vector<std::string>& texts, int width) {
    for (const std::string& text : texts) {
        if (textWidth(text, 2) > width - 2 * kMargin) return 1;
    }
    return 2;
}

void drawPanelLabel(Image& image, int x0, int width, std::string_view text, int scale) {
    const int x1 = std::min(x0 + width, image.width());
    x0 = std::max(x0, 0);
    const int room = x1 - x0 - 2 * kMargin;
    if (room <= 0) return;
    if (scale <= 0) scale = panelLabelScale({std::string(text)}, x1 - x0);
    const std::string fitted = fitText(text, room, scale);
    const int lines = static_cast<int>(splitLines(fitted).size());
    const int boxRight = std::min(x1, x0 + textWidth(fitted, scale) + 2 * kMargin);
    const int boxBottom = std::min(image.height(), lines * kTextLineHeight * scale + kMargin);
    // Darken the box behind the text so it reads on bright and dark panels alike.
    for (int y = 0; y < boxBottom; ++y) {
        for (int x = x0; x < boxRight; ++x) image.setRgb(x, y, image.rgb(x, y) * 0.25f);
    }
    drawText(image, x0 + kMargin, kMargin, fitted, Rgb(1.0f), scale);
}

}  // namespace luxel::post
