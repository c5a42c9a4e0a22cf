// Light leaks and sun flicker of a GI solver against its reference (docs/voxel-gi-measures.md).
#include "luxel/post/gi_measures.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "luxel/core/check.h"

namespace luxel::post {
namespace {

std::string describe(const Image& image) {
    return std::to_string(image.width()) + "x" + std::to_string(image.height()) + " with " +
           std::to_string(image.channels()) + (image.channels() == 1 ? " channel" : " channels");
}

Status sameShape(const Image& a, const Image& b, const char* what) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) {
        return Error(std::string(what) + ": images of different sizes: " + describe(a) + " vs " +
                     describe(b));
    }
    if (a.empty()) return Error(std::string(what) + ": empty image");
    return Ok{};
}

// The mean of the channels of pixel (x, y).
double brightness(const Image& image, int x, int y) {
    double sum = 0;
    for (int c = 0; c < image.channels(); ++c) sum += image.at(x, y, c);
    return sum / image.channels();
}

double imageMean(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return sum / static_cast<double>(image.size());
}

}  // namespace

Image blockMeans(const Image& image, int block) {
    LUXEL_CHECK_GE(block, 1);
    const int w = (image.width() + block - 1) / block, h = (image.height() + block - 1) / block;
    Image out(w, h, image.channels());
    for (int by = 0; by < h; ++by) {
        for (int bx = 0; bx < w; ++bx) {
            const int x1 = std::min(image.width(), (bx + 1) * block);
            const int y1 = std::min(image.height(), (by + 1) * block);
            for (int c = 0; c < image.channels(); ++c) {
                double sum = 0;
                for (int y = by * block; y < y1; ++y)
                    for (int x = bx * block; x < x1; ++x) sum += image.at(x, y, c);
                out.at(bx, by, c) =
                    static_cast<float>(sum / ((x1 - bx * block) * (y1 - by * block)));
            }
        }
    }
    return out;
}

Result<DarkLeak> darkRegionLeak(const Image& solver, const Image& reference, double darkFraction) {
    if (Status s = sameShape(solver, reference, "leak"); !s) return s.error();
    if (!(darkFraction > 0.0) || !std::isfinite(darkFraction)) {
        return Error("leak: the dark fraction must be a positive number");
    }
    DarkLeak out;
    out.referenceMean = imageMean(reference);
    if (!(out.referenceMean > 0.0)) return out;  // a black reference has no scale to leak against
    // Blocks, not pixels, choose the dark region: a noisy reference's pixels that happen to be
    // low would otherwise be picked for their noise and read as a leak of every other solver.
    const Image s = blockMeans(solver), r = blockMeans(reference);
    const double threshold = darkFraction * out.referenceMean;
    double solverSum = 0, referenceSum = 0;
    for (int y = 0; y < r.height(); ++y) {
        for (int x = 0; x < r.width(); ++x) {
            const double rb = brightness(r, x, y);
            if (rb >= threshold) continue;
            ++out.darkBlocks;
            referenceSum += rb;
            solverSum += brightness(s, x, y);
        }
    }
    out.blocks = r.pixelCount();
    if (out.darkBlocks == 0) return out;
    out.referenceDark = referenceSum / static_cast<double>(out.darkBlocks);
    out.solverDark = solverSum / static_cast<double>(out.darkBlocks);
    out.leak = (out.solverDark - out.referenceDark) / out.referenceMean;
    return out;
}

Result<SunFlicker> sunFlicker(std::span<const Image> solver, std::span<const Image> reference) {
    if (solver.size() != reference.size()) {
        return Error("flicker: " + std::to_string(solver.size()) + " solver frames but " +
                     std::to_string(reference.size()) + " reference frames");
    }
    if (reference.size() < 2) return Error("flicker: needs 2 frames or more");
    SunFlicker out;
    std::vector<Image> s, r;
    for (std::size_t k = 0; k < reference.size(); ++k) {
        if (Status st = sameShape(solver[k], reference[0], "flicker"); !st) return st.error();
        if (Status st = sameShape(reference[k], reference[0], "flicker"); !st) return st.error();
        out.referenceMean += imageMean(reference[k]) / static_cast<double>(reference.size());
        s.push_back(blockMeans(solver[k]));
        r.push_back(blockMeans(reference[k]));
    }
    if (!(out.referenceMean > 0.0)) return out;
    double flicker = 0, change = 0;
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
        double pairFlicker = 0, pairChange = 0;
        for (std::size_t i = 0; i < r[k].size(); ++i) {
            const double dr = double(r[k + 1].data()[i]) - r[k].data()[i];
            const double ds = double(s[k + 1].data()[i]) - s[k].data()[i];
            pairFlicker += std::abs(ds - dr);
            pairChange += std::abs(dr);
        }
        flicker += pairFlicker / static_cast<double>(r[k].size());
        change += pairChange / static_cast<double>(r[k].size());
    }
    const double pairs = static_cast<double>(r.size() - 1);
    out.flicker = flicker / pairs / out.referenceMean;
    out.referenceChange = change / pairs / out.referenceMean;
    return out;
}

}  // namespace luxel::post
