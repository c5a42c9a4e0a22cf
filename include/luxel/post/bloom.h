// Dual-filter bloom on HDR radiance, before tone mapping (M. Bjørge, "Bandwidth-Efficient
// Rendering", SIGGRAPH 2015): a chain of half-resolution levels built with a 5-tap downsample,
// recombined with an 8-tap upsample, every level weighted equally, then lerped with the input:
//   out = (1 - strength) * in + strength * bloom.
// No threshold: every pixel spreads a little, so the mean radiance is kept (exactly for
// power-of-two sizes away from the borders; tests/post/bloom_test.cpp bounds it elsewhere).
#pragma once

#include "luxel/core/image.h"
#include "luxel/post/post_options.h"

namespace luxel::post {

// Levels actually used for a w x h image: at most `requested`, and none whose smaller side would
// drop below 2 pixels (0 for images smaller than 4 pixels on a side).
int bloomLevels(int width, int height, int requested);

// One level down: ceil(w / 2) x ceil(h / 2), the 5-tap filter (karis: Karis-weighted taps).
Image bloomDownsample(const Image& src, bool karis);
// baseWeight * base + lowWeight * (8-tap upsample of `low` to base's size).
Image bloomUpsampleAdd(const Image& low, const Image& base, float baseWeight, float lowWeight);

// The whole effect on an RGB image (extra channels are dropped; 3 channels out).
Image bloom(const Image& hdr, const BloomSettings& settings);

}  // namespace luxel::post
