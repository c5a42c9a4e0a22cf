// The shared post pipeline: bloom, then luxel's one toneMap.
#include "luxel/post/finish.h"

#include "luxel/post/bloom.h"
#include "post/sample.h"

namespace luxel::post {

Image applyBloom(const Image& hdr, const PostOptions& options) {
    if (!(options.bloom.strength > 0.0f)) return hdr;
    return bloom(hdr, options.bloom);
}

Image finish(const Image& hdr, const PostOptions& options) {
    return toneMap(applyBloom(hdr, options), options.tone);
}

}  // namespace luxel::post
