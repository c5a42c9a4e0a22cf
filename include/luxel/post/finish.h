// The post pipeline every renderer shares (CLI voxel and octree renders, the viewer): bloom on
// linear radiance, then exposure and the tone curve of luxel/core/tonemap.h, the same toneMap the
// 2D renders use.
#pragma once

#include "luxel/core/image.h"
#include "luxel/post/post_options.h"

namespace luxel::post {

// A render made at the internal size -> the linear image at width x height: upscaled (the
// options' upscaler), sharpened, bloomed. This is what EXR files get; PNGs get the tone on top.
Image processInternal(const Image& internal, int width, int height, const PostOptions& options);
// Linear radiance after bloom (the image written to EXR).
Image applyBloom(const Image& hdr, const PostOptions& options);
// Display-referred [0, 1] RGB for PNG: toneMap(applyBloom(hdr)).
Image finish(const Image& hdr, const PostOptions& options);

}  // namespace luxel::post
