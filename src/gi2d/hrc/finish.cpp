#include "gi2d/hrc/finish.h"

#include <algorithm>
#include <vector>

#include "gi2d/hrc/finish_rows.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/check.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {
namespace {

namespace shared = gpu::shared;

// Rows per band: the two saved neighbour rows of each band are 1/32 of the image.
constexpr int kBandRows = 64;

shared::vec3 vec3At(const float* p) {
    return {p[0], p[1], p[2]};
}

bool sameSigma(const float* a, const shared::vec3& b) {
    return a[0] == b.x && a[1] == b.y && a[2] == b.z;
}

// The blur's gate per pixel of row y (paper Eq 21). A run of pixels of equal sigma (most of a
// canvas) reuses the run's exp: equal inputs give the same bits (±0 both give exp 1).
void opacityRow(const Medium2D& medium, int y, std::vector<float>& out) {
    const int w = medium.width();
    out.resize(static_cast<std::size_t>(w));
    const float* sigma = medium.absorption.data() + static_cast<std::size_t>(y) * w * 3;
    shared::vec3 last = vec3At(sigma);
    float opacity = shared::hrcOpacity(last);
    for (int x = 0; x < w; ++x) {
        if (!sameSigma(sigma + 3 * x, last)) {
            last = vec3At(sigma + 3 * x);
            opacity = shared::hrcOpacity(last);
        }
        out[x] = opacity;
    }
}

}  // namespace

void finishFluenceInPlace(const Medium2D& medium, Image& fluence, int frustums, bool blur) {
    const int w = fluence.width(), h = fluence.height();
    LUXEL_CHECK(fluence.channels() == 3 && medium.absorption.channels() == 3 &&
                medium.emission.channels() == 3);
    const std::size_t rowFloats = static_cast<std::size_t>(w) * 3;
    float* data = fluence.data();
    auto row = [&](int y) { return data + static_cast<std::size_t>(y) * rowFloats; };
    // Each band overwrites its rows in order and keeps the original of the row above; the rows
    // just outside a band belong to its neighbours, so they are copied before any band starts.
    const int bands = (h + kBandRows - 1) / kBandRows;
    std::vector<float> above, below;
    if (blur) {
        above.resize(static_cast<std::size_t>(bands) * rowFloats);
        below.resize(static_cast<std::size_t>(bands) * rowFloats);
        for (int b = 0; b < bands; ++b) {
            const int y0 = b * kBandRows, y1 = std::min(h, y0 + kBandRows);
            if (y0 > 0) std::copy_n(row(y0 - 1), rowFloats, &above[b * rowFloats]);
            if (y1 < h) std::copy_n(row(y1), rowFloats, &below[b * rowFloats]);
        }
    }
    parallelForRange(bands, 1, [&](int begin, int end) {
        std::vector<float> previous(rowFloats), current(rowFloats), transmittance(rowFloats);
        std::vector<float> opacityAbove, opacityHere, opacityBelow;
        for (int b = begin; b < end; ++b) {
            const int y0 = b * kBandRows, y1 = std::min(h, y0 + kBandRows);
            if (blur) {
                if (y0 > 0) {
                    std::copy_n(&above[b * rowFloats], rowFloats, previous.data());
                    opacityRow(medium, y0 - 1, opacityAbove);
                }
                opacityRow(medium, y0, opacityHere);
            }
            for (int y = y0; y < y1; ++y) {
                std::copy_n(row(y), rowFloats, current.data());
                const float* next = nullptr;
                if (blur && y + 1 < h) {
                    next = y + 1 < y1 ? row(y + 1) : &below[b * rowFloats];
                    opacityRow(medium, y + 1, opacityBelow);
                }
                const float* sigma =
                    medium.absorption.data() + static_cast<std::size_t>(y) * rowFloats;
                // T per pixel, its exp once per run of equal sigma (as in opacityRow).
                shared::vec3 lastSigma = vec3At(sigma);
                shared::vec3 t = shared::hrcFinishTransmittance(lastSigma);
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = static_cast<std::size_t>(x) * 3;
                    if (!sameSigma(sigma + i, lastSigma)) {
                        lastSigma = vec3At(sigma + i);
                        t = shared::hrcFinishTransmittance(lastSigma);
                    }
                    transmittance[i] = t.x, transmittance[i + 1] = t.y, transmittance[i + 2] = t.z;
                }
                FinishRow pass;
                pass.current = current.data();
                if (blur) {
                    pass.above = y > 0 ? previous.data() : nullptr;
                    pass.below = next;
                    pass.opacityAbove = opacityAbove.data();
                    pass.opacityHere = opacityHere.data();
                    pass.opacityBelow = opacityBelow.data();
                }
                pass.transmittance = transmittance.data();
                pass.emission = medium.emission.data() + static_cast<std::size_t>(y) * rowFloats;
                pass.width = w;
                pass.frustums = static_cast<float>(frustums);
                pass.blur = blur;
                finishRow(pass, row(y));
                if (blur) {
                    previous.swap(current);
                    opacityAbove.swap(opacityHere);
                    opacityHere.swap(opacityBelow);
                }
            }
        }
    });
}

Image finishFluence(const Medium2D& medium, const Image& beyond, int frustums, bool blur) {
    Image out = beyond;
    finishFluenceInPlace(medium, out, frustums, blur);
    return out;
}

}  // namespace luxel::gi2d::hrc
