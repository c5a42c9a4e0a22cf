// Image metadata <-> PNG text chunks (tEXt for ASCII values, iTXt for UTF-8 ones), for the PNG
// codec in image_io_png.cpp.
#pragma once

#include <png.h>

#include <vector>

#include "luxel/core/image_metadata.h"

namespace luxel::detail {

// png_text records pointing into `metadata`, which must outlive them (libpng copies them in
// png_set_text).
std::vector<png_text> pngTextChunks(const ImageMetadata& metadata);

// The text chunks libpng has read into `info` so far, in file order.
ImageMetadata pngTextMetadata(png_const_structrp png, png_inforp info);

}  // namespace luxel::detail
