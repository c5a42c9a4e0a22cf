// The codecs' writers into an open AtomicFile, which the caller publishes; used by writeImages to
// replace several files together.
#pragma once

#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"

namespace luxel::detail {

Status writePngInto(AtomicFile& file, const ImageRows& image, PngEncoding encoding,
                    const ImageMetadata& metadata);
Status writeExrInto(AtomicFile& file, const ImageRows& image, const ImageMetadata& metadata);

// Rows an EXR strip holds when its rows are made on demand: line blocks of 16 rows, two per
// OpenEXR thread, so the threads still compress side by side.
int exrStripRows();

}  // namespace luxel::detail
