// PSNR and SSIM (Wang et al. 2004) with a separable Gaussian window.
#include "luxel/core/image_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "luxel/core/parallel.h"

namespace luxel {
namespace {

Status checkSizes(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) {
        return Error("images differ in size: " + std::to_string(a.width()) + "x" +
                     std::to_string(a.height()) + "x" + std::to_string(a.channels()) + " vs " +
                     std::to_string(b.width()) + "x" + std::to_string(b.height()) + "x" +
                     std::to_string(b.channels()));
    }
    if (a.empty()) return Error("images are empty");
    return Ok{};
}

int colourChannels(const Image& image) {
    return image.channels() == 2 ? 1 : std::min(image.channels(), 3);
}

constexpr int kRadius = 5;  // 11 x 11 window
constexpr double kSigma = 1.5;

// Separable Gaussian blur, truncated at the borders with the weights renormalised.
std::vector<double> blur(const std::vector<double>& in, int w, int h) {
    double kernel[2 * kRadius + 1];
    for (int i = -kRadius; i <= kRadius; ++i) {
        kernel[i + kRadius] = std::exp(-0.5 * i * i / (kSigma * kSigma));
    }
    std::vector<double> tmp(in.size()), out(in.size());
    parallelForRange(h, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                double sum = 0, total = 0;
                for (int i = std::max(-kRadius, -x); i <= std::min(kRadius, w - 1 - x); ++i) {
                    sum += kernel[i + kRadius] * in[static_cast<std::size_t>(y) * w + x + i];
                    total += kernel[i + kRadius];
                }
                tmp[static_cast<std::size_t>(y) * w + x] = sum / total;
            }
        }
    });
    parallelForRange(h, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                double sum = 0, total = 0;
                for (int i = std::max(-kRadius, -y); i <= std::min(kRadius, h - 1 - y); ++i) {
                    sum += kernel[i + kRadius] * tmp[static_cast<std::size_t>(y + i) * w + x];
                    total += kernel[i + kRadius];
                }
                out[static_cast<std::size_t>(y) * w + x] = sum / total;
            }
        }
    });
    return out;
}

}  // namespace

Result<double> psnr(const Image& a, const Image& reference, double peak) {
    if (Status s = checkSizes(a, reference); !s) return s.error();
    const int channels = colourChannels(a);
    double sum = 0;
    for (std::size_t p = 0; p < a.pixelCount(); ++p) {
        for (int c = 0; c < channels; ++c) {
            const double d = double(a.data()[p * a.channels() + c]) -
                             double(reference.data()[p * a.channels() + c]);
            sum += d * d;
        }
    }
    const double mse = sum / (static_cast<double>(a.pixelCount()) * channels);
    if (mse == 0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / mse);
}

Result<double> ssim(const Image& a, const Image& reference, double peak) {
    if (Status s = checkSizes(a, reference); !s) return s.error();
    const int w = a.width(), h = a.height(), channels = colourChannels(a);
    const double c1 = (0.01 * peak) * (0.01 * peak), c2 = (0.03 * peak) * (0.03 * peak);
    const std::size_t n = a.pixelCount();
    double total = 0;
    for (int c = 0; c < channels; ++c) {
        std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
        for (std::size_t p = 0; p < n; ++p) {
            x[p] = a.data()[p * a.channels() + c];
            y[p] = reference.data()[p * a.channels() + c];
            xx[p] = x[p] * x[p];
            yy[p] = y[p] * y[p];
            xy[p] = x[p] * y[p];
        }
        const auto mx = blur(x, w, h), my = blur(y, w, h);
        const auto sxx = blur(xx, w, h), syy = blur(yy, w, h), sxy = blur(xy, w, h);
        double sum = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const double vx = sxx[p] - mx[p] * mx[p], vy = syy[p] - my[p] * my[p];
            const double cov = sxy[p] - mx[p] * my[p];
            sum += ((2 * mx[p] * my[p] + c1) * (2 * cov + c2)) /
                   ((mx[p] * mx[p] + my[p] * my[p] + c1) * (vx + vy + c2));
        }
        total += sum / static_cast<double>(n);
    }
    return total / channels;
}

}  // namespace luxel
