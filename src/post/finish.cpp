// The shared post pipeline: bloom, then luxel's one toneMap.
#include "luxel/post/finish.h"

#include "luxel/post/bloom.h"
#include "luxel/post/upscale.h"
#include "post/sample.h"

namespace luxel::post {

Image applyBloom(const Image& hdr, const PostOptions& options) {
    if (!(options.bloom.strength > 0.0f)) return hdr;
    return bloom(hdr, options.bloom);
}

Image processInternal(const Image& internal, int width, int height, const PostOptions& options) {
    Image full = internal.width() == width && internal.height() == height
                     ? internal
                     : upscale(internal, width, height, options.upscaler);
    if (options.sharpness > 0.0f) full = sharpen(full, options.sharpness);
    return applyBloom(full, options);
}

Image finish(const Image& hdr, const PostOptions& options) {
    return toneMap(applyBloom(hdr, options), options.tone);
}

}  // namespace luxel::post
