// The codecs' writers into an open AtomicFile, which the caller publishes; used by writeImages to
// replace several files together.
#pragma once

#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"

namespace luxel::detail {

Status writePngInto(AtomicFile& file, const Image& image, PngEncoding encoding,
                    const ImageMetadata& metadata);
Status writeExrInto(AtomicFile& file, const Image& image, const ImageMetadata& metadata);

}  // namespace luxel::detail
