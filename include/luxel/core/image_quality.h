// Image quality metrics against a reference of the same size: PSNR and SSIM (Wang, Bovik, Sheikh
// & Simoncelli, "Image Quality Assessment: From Error Visibility to Structural Similarity", IEEE
// TIP 2004). Both read the colour channels (up to 3) of display-referred images; `peak` is the
// largest value a pixel can take (1 for tone-mapped images).
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/image.h"

namespace luxel {

// 10 log10(peak^2 / MSE) over every colour channel; +inf for identical images. Fails when sizes
// or channel counts differ.
Result<double> psnr(const Image& a, const Image& reference, double peak = 1.0);

// Mean SSIM: per channel, local statistics under an 11 x 11 Gaussian window (sigma 1.5, truncated
// and renormalised at the borders), K1 = 0.01, K2 = 0.03, averaged over pixels and channels.
// 1 for identical images.
Result<double> ssim(const Image& a, const Image& reference, double peak = 1.0);

}  // namespace luxel
