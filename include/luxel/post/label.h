// Text labels drawn into images (panels of a comparison grid), with the small vector font of
// stb_easy_font (Debian libstb-dev): ASCII glyphs built from axis-aligned quads, rasterised here
// onto whole pixels.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/core/vec.h"

namespace luxel::post {

// One line of the font is this many pixels tall at scale 1 (glyphs with descenders included).
inline constexpr int kTextLineHeight = 12;

// The width in pixels of `text` at an integer `scale` >= 1 (the longest line when it has
// several, split by '\n').
int textWidth(std::string_view text, int scale = 1);

// Draws `text` (lines split by '\n') with its top-left corner at (x, y), `scale` pixels per font
// unit, in `colour`; pixels outside the image are skipped. Characters other than printable ASCII
// draw as '?'. Returns the number of pixel writes (a pixel where two strokes meet counts twice).
std::size_t drawText(Image& image, int x, int y, std::string_view text, Rgb colour, int scale = 1);

// `text` shortened to at most `maxWidth` pixels at `scale`: cut at the end, with ".." to show it
// was cut ("" when not even that fits). Per line.
std::string fitText(std::string_view text, int maxWidth, int scale = 1);

// The largest scale (2 or 1) at which every caption fits a panel `width` pixels wide, so the
// panels of one grid share a text size.
int panelLabelScale(const std::vector<std::string>& texts, int width);

// A caption in the top-left corner of the panel of `image` spanning columns [x0, x0 + width):
// white text on a darkened box, at `scale` (0: panelLabelScale of this caption alone), each line
// cut to the panel (fitText), so nothing is drawn outside it.
void drawPanelLabel(Image& image, int x0, int width, std::string_view text, int scale = 0);

}  // namespace luxel::post
