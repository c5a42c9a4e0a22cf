// Dual-filter bloom (Bjørge 2015): the CPU twin of post_bloom_down / post_bloom_up.
#include "luxel/post/bloom.h"

#include <algorithm>

#include "luxel/core/parallel.h"
#include "post/sample.h"

namespace luxel::post {

using detail::vec2;
using detail::vec3;
namespace shared = gpu::shared;

int bloomLevels(int width, int height, int requested) {
    int levels = 0;
    int side = std::min(width, height);
    while (levels < requested && (side + 1) / 2 >= 2) {
        side = (side + 1) / 2;
        ++levels;
    }
    return levels;
}

Image bloomDownsample(const Image& src, bool karis) {
    const int w = std::max(1, (src.width() + 1) / 2), h = std::max(1, (src.height() + 1) / 2);
    Image dst(w, h, 3);
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const vec2 p = shared::postDownPosition(x, y);
                vec3 sum(0.0f);
                float total = 0.0f;
                for (int t = 0; t < 5; ++t) {
                    const vec3 c = detail::bilinear(src, p + shared::postDownTapOffset(t));
                    const float weight =
                        shared::postDownTapWeight(t) * (karis ? shared::postKarisWeight(c) : 1.0f);
                    sum += c * weight;
                    total += weight;
                }
                detail::store(dst, x, y, sum * (1.0f / total));
            }
        }
    });
    return dst;
}

Image bloomUpsampleAdd(const Image& low, const Image& base, float baseWeight, float lowWeight) {
    const int w = base.width(), h = base.height();
    Image dst(w, h, 3);
    const vec2 half(0.5f, 0.5f);
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const vec2 p = shared::postUpPosition(x, y);
                vec3 sum(0.0f);
                for (int t = 0; t < 8; ++t) {
                    sum += detail::bilinear(low, p + shared::postUpTapOffset(t) * half) *
                           shared::postUpTapWeight(t);
                }
                detail::store(dst, x, y, detail::texel(base, x, y) * baseWeight + sum * lowWeight);
            }
        }
    });
    return dst;
}

Image bloom(const Image& hdr, const BloomSettings& settings) {
    Image input = detail::toRgb(hdr);
    const int levels = bloomLevels(input.width(), input.height(), settings.levels);
    const float strength = std::clamp(settings.strength, 0.0f, 1.0f);
    if (levels == 0 || strength == 0.0f) return input;
    // chain[k] is level k + 1 (half, quarter, ...).
    std::vector<Image> chain;
    chain.push_back(bloomDownsample(input, settings.karisAverage));
    for (int k = 1; k < levels; ++k) chain.push_back(bloomDownsample(chain.back(), false));
    // Up the chain, summing levels: acc_k = level_k + up(acc_{k+1}); acc_1 holds all of them.
    Image acc = chain.back();
    for (int k = levels - 2; k >= 0; --k) acc = bloomUpsampleAdd(acc, chain[k], 1.0f, 1.0f);
    return bloomUpsampleAdd(acc, input, 1.0f - strength, strength / float(levels));
}

}  // namespace luxel::post
